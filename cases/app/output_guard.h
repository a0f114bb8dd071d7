// Checks a command makes before it writes its --out files, so that a refused run writes nothing:
// two cases of one run never share an output name. That no
// output replaces a case file the command reads is OutputSet's (its OutputPlan), for every
// command alike.
#pragma once

#include <string>
#include <vector>

namespace lexel::cases {

// Throws InputError "--out: <a> and <b> are both named '<name>' (their outputs would overwrite
// each other)" when two of `names` are equal; sources[i] is the case file of names[i].
void RefuseDuplicateNames(const std::vector<std::string>& names,
                          const std::vector<std::string>& sources);

}  // namespace lexel::cases
