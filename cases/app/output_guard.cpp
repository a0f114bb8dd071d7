#include "lexel/cases/app/output_guard.h"

#include <system_error>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace fs = std::filesystem;

void RefuseDuplicateNames(const std::vector<std::string>& names,
                          const std::vector<std::string>& sources) {
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (names[i] == names[j])
                throw InputError("--out: " + sources[j] + " and " + sources[i] +
                                 " are both named '" + names[i] +
                                 "' (their outputs would overwrite each other)");
}

void RefuseOverwritingInputs(const fs::path& outDir, const std::vector<std::string>& inputs,
                             const std::function<bool(const std::string& fileName)>& isOutput) {
    std::error_code error;
    const fs::path outAt = fs::weakly_canonical(fs::absolute(outDir), error);
    if (error) return;  // an --out that cannot be resolved fails when it is written
    for (const std::string& input : inputs) {
        const fs::path path = fs::absolute(input);
        // Where the input's name lies (a link there is replaced by the output) and the file it
        // resolves to (the link's target would be replaced through a directory link).
        const fs::path named = fs::weakly_canonical(path.parent_path(), error) / path.filename();
        const fs::path resolved = fs::weakly_canonical(path, error);
        for (const fs::path& at : {named, resolved})
            if (at.parent_path() == outAt && isOutput(at.filename().string()))
                throw InputError("--out: writing " + (outDir / at.filename()).string() +
                                 " would overwrite the case file " + input);
    }
}

}  // namespace lexel::cases
