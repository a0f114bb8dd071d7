#include "lexel/cases/app/output_guard.h"

#include "lexel/solvers/errors.h"

namespace lexel::cases {

void RefuseDuplicateNames(const std::vector<std::string>& names,
                          const std::vector<std::string>& sources) {
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (names[i] == names[j])
                throw InputError("--out: " + sources[j] + " and " + sources[i] +
                                 " are both named '" + names[i] +
                                 "' (their outputs would overwrite each other)");
}

}  // namespace lexel::cases
