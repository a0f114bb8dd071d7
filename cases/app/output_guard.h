// Checks a command makes before it writes its --out files, so that a refused run writes nothing:
// two cases of one run never share an output name, and no output replaces a case file the
// command line gave (issue 16, "names are file stems").
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lexel::cases {

// Throws InputError "--out: <a> and <b> are both named '<name>' (their outputs would overwrite
// each other)" when two of `names` are equal; sources[i] is the case file of names[i].
void RefuseDuplicateNames(const std::vector<std::string>& names,
                          const std::vector<std::string>& sources);

// Throws InputError "--out: writing <file> would overwrite the case file <input>" when a file
// that `isOutput` accepts (a file name inside outDir) is, once directories and links are
// resolved, one of `inputs`.
void RefuseOverwritingInputs(const std::filesystem::path& outDir,
                             const std::vector<std::string>& inputs,
                             const std::function<bool(const std::string& fileName)>& isOutput);

}  // namespace lexel::cases
