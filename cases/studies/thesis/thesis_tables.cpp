#include "lexel/cases/studies/thesis/thesis_tables.h"

#include <stdexcept>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/studies/thesis/thesis_scene.h"

namespace lexel::cases {

const std::vector<std::pair<std::string, std::string>>& TableRows() {
    static const std::vector<std::pair<std::string, std::string>> rows = {
        {"Our Method (L1)", "optimal-l1"},   {"Our Method (L2)", "optimal-l2"},
        {"Our Method (L∞)", "optimal-linf"}, {"Perspective SM", "psm-thesis"},
        {"PSM (true sampling)", "psm"},      {"Normal SM", "normal"},
        {"plane-optimal", "plane-optimal"},  {"split-dp", "split-dp"}};
    return rows;
}

const flatland::MethodReport& TableResult::Method(const std::string& name) const {
    for (const auto& m : report.methods)
        if (m.method == name) return m;
    throw std::logic_error("method not in table: " + name);
}

std::vector<TableResult> RunThesisTables(const std::vector<ThesisTable>& tables,
                                         const std::filesystem::path& casesDir) {
    std::vector<std::string> methods;
    for (const auto& [label, method] : TableRows()) methods.push_back(method);
    std::vector<TableResult> results;
    for (const ThesisTable& thesis : tables) {
        const ThesisSceneChoice choice = ChooseThesisScene(thesis, casesDir);
        const flatland::FlatScene& scene = choice.scene;
        try {
            results.push_back(
                {thesis, scene,
                 flatland::RunFlatlandCase(scene, methods, Metric::kL1, nullptr, nullptr,
                                           /*keepFootprints=*/true),
                 std::filesystem::relative(choice.path, casesDir).generic_string(), choice.fitted,
                 choice.agreement.worstAngleDeg, choice.agreement.worstFootprint});
        } catch (const DomainError& e) {
            throw FlatlandInputError(choice.path.string(), e);
        }
    }
    return results;
}

}  // namespace lexel::cases
