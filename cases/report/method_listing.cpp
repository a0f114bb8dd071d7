#include "lexel/cases/report/method_listing.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <vector>

#include "lexel/flatland/methods.h"
#include "lexel/spatial/methods/method_info.h"

namespace lexel::cases {

namespace {

// Left-aligned columns (names, families and models are ASCII), two spaces apart, the last one
// unpadded: a listing to read, not numbers to compare.
std::string LeftAligned(const std::vector<std::vector<std::string>>& rows) {
    std::vector<std::size_t> widths;
    for (const std::vector<std::string>& row : rows)
        for (std::size_t c = 0; c + 1 < row.size(); ++c) {
            widths.resize(std::max(widths.size(), c + 1));
            widths[c] = std::max(widths[c], row[c].size());
        }
    std::string out;
    for (const std::vector<std::string>& row : rows) {
        for (std::size_t c = 0; c < row.size(); ++c)
            out += c + 1 < row.size() ? row[c] + std::string(widths[c] - row[c].size() + 2, ' ')
                                      : row[c];
        out += '\n';
    }
    return out;
}

}  // namespace

std::string MethodListingText() {
    std::vector<std::vector<std::string>> spatialRows = {
        {"3D method", "family", "runs", "storage model", "description"}};
    for (const spatial::MethodInfo& m : spatial::MethodInfos())
        spatialRows.push_back({m.name, std::string(spatial::MethodFamilyName(m.family)),
                               m.traits.optIn ? "when named" : "by default",
                               std::string(spatial::StorageModelName(m.storage)), m.description});
    std::vector<std::vector<std::string>> flatlandRows = {{"flatland method", "description"}};
    for (const std::string& name : flatland::FlatlandMethodNames())
        flatlandRows.push_back({name, std::string(flatland::FlatlandMethodDescription(name))});
    return LeftAligned(spatialRows) + "\n" + LeftAligned(flatlandRows);
}

std::string MethodListingJson() {
    nlohmann::ordered_json out;
    out["spatial"] = nlohmann::ordered_json::array();
    for (const spatial::MethodInfo& m : spatial::MethodInfos()) {
        const spatial::MethodTraits& t = m.traits;
        out["spatial"].push_back({
            {"name", m.name},
            {"description", m.description},
            {"citation", m.citation},
            {"family", spatial::MethodFamilyName(m.family)},
            {"default", !t.optIn},
            {"storage_model", spatial::StorageModelName(m.storage)},
            {"traits",
             {{"fair_table", t.fairTable},
              {"report_table", t.reportTable},
              {"frustum_fitted", t.frustumFitted},
              {"optimizer", t.optimizer},
              {"partitioned", t.partitioned},
              {"virtual_map", t.virtualMap},
              {"warped", t.warped},
              {"gpu_map", t.gpuMap}}},
        });
    }
    out["flatland"] = nlohmann::ordered_json::array();
    for (const std::string& name : flatland::FlatlandMethodNames())
        out["flatland"].push_back(
            {{"name", name}, {"description", flatland::FlatlandMethodDescription(name)}});
    return out.dump(2) + "\n";
}

}  // namespace lexel::cases
