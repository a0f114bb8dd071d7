#include "lexel/cases/run/thesis_tables.h"

#include <stdexcept>

#include "lexel/cases/load/flatland_case.h"

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
        const std::filesystem::path path = casesDir / thesis.file;
        const flatland::FlatScene scene = LoadFlatScene(path);
        try {
            results.push_back(
                {thesis, scene, flatland::RunFlatlandCase(scene, methods, Metric::kL1)});
        } catch (const DomainError& e) {
            throw FlatlandInputError(path.string(), e);
        }
    }
    return results;
}

}  // namespace lexel::cases
