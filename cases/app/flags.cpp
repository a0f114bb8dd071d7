#include "lexel/cases/app/flags.h"

#include "lexel/spatial/harness/sub_texel_phase.h"

namespace lexel::cases {

CLI::Validator NonEmpty(const std::string& what) {
    return CLI::Validator(
        [what](std::string& value) {
            return value.empty() ? "must name " + what + ", got an empty string" : std::string();
        },
        "", "NonEmpty");
}

CLI::Option* AddBackend(CLI::App* sub, std::string& backend, const std::string& what) {
    return sub->add_option("--backend", backend, what)->check(CLI::IsMember({"cpu", "gl"}));
}

void AddPhases(CLI::App* sub, int& phases, int& maxPhases) {
    sub->add_option("--phases", phases,
                    "3D: average each method's misclassified pixels over K sub-texel shifts of "
                    "its map(s) (default: the case's phases, or 1)")
        ->check(CLI::Range(1, lexel::spatial::kMaxPhases));
    sub->add_option("--max-phases", maxPhases,
                    "3D: where a method's mean over K phases has a standard error above 2% of it "
                    "(and above 1 pixel), average it over 2K, 4K, ... up to N phases (default: "
                    "the case's max_phases, or K)")
        ->check(CLI::Range(1, lexel::spatial::kMaxPhases));
}

}  // namespace lexel::cases
