#include "lexel/cases/report/sweep_lights_csv.h"

#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>

#include "lexel/cases/report/columns.h"

namespace lexel::cases {

using spatial::Light;

namespace {

// A row of lights.csv: light `light` of the sweep.
struct LightRow {
    const SweepResult* sweep = nullptr;
    std::size_t light = 0;
    const SweepCell& Cell(std::size_t method) const { return sweep->cells[light][method]; }
};

// The getter of method `m`'s SweepCell field.
template <class T>
std::function<CellValue(const LightRow&)> CellField(std::size_t m, T SweepCell::*field) {
    return [m, field](const LightRow& row) -> CellValue {
        if constexpr (std::is_floating_point_v<T>)
            return double(row.Cell(m).*field);
        else if constexpr (std::is_integral_v<T>)
            return std::int64_t(row.Cell(m).*field);
        else
            return row.Cell(m).*field;
    };
}

// The columns of lights.csv: the light, then per method its misclassified pixels (phase 0's), h,
// e, time and storage factors (worst and 99th-percentile pixel); over several phases the mean and
// standard error, and with adaptive phases (--max-phases) how many; with shimmer poses the shimmer;
// the multi-start methods' winning start; the virtual shadow maps' pages.
ColumnTable<LightRow> LightColumns(const SweepResult& r) {
    const auto position = [](int axis) {
        return [axis](const LightRow& row) {
            const Light& light = row.sweep->lights[row.light];
            return CellValue(
                (light.type == Light::Type::kPoint ? light.position : light.direction)[axis]);
        };
    };
    ColumnTable<LightRow> table = {
        {"light", "",
         [](const LightRow& row) {
             const std::vector<std::size_t>& indices = row.sweep->indices;
             return CellValue(
                 std::int64_t(row.light < indices.size() ? indices[row.light] : row.light));
         },
         kCsvColumn},
        {"kind", "",
         [](const LightRow& row) {
             return CellValue(std::string(row.sweep->lights[row.light].type == Light::Type::kPoint
                                              ? "point"
                                              : "directional"));
         },
         kCsvColumn},
        {"x", "scene units", position(0), kCsvColumn},
        {"y", "scene units", position(1), kCsvColumn},
        {"z", "scene units", position(2), kCsvColumn},
        {"receiver_pixels", "pixels",
         [](const LightRow& row) {
             return CellValue(std::int64_t(row.sweep->receiverPixels[row.light]));
         },
         kCsvColumn}};
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
        const std::string& name = r.methods[m];
        const auto add = [&](const std::string& suffix, const std::string& unit, auto getter) {
            table.push_back({name + suffix, unit, getter, kCsvColumn});
        };
        add("_misclassified", "pixels", CellField(m, &SweepCell::misclassified));
        add("_h", "pixels²/texel²", CellField(m, &SweepCell::h));
        add("_e", "edge energy", CellField(m, &SweepCell::e));
        add("_ms", "ms", CellField(m, &SweepCell::ms));
        add("_storage_factor", "texels/pixel", CellField(m, &SweepCell::storageFactor));
        add("_storage_factor_p99", "texels/pixel", CellField(m, &SweepCell::storageFactorP99));
        if (r.phases > 1) {
            add("_misclassified_mean", "pixels", CellField(m, &SweepCell::misclassifiedMean));
            add("_misclassified_se", "pixels", CellField(m, &SweepCell::misclassifiedError));
        }
        if (r.maxPhases > r.phases) add("_phases", "phases", CellField(m, &SweepCell::phases));
        if (r.shimmerPoses > 1)
            add("_shimmer", "% of stable pixels per step", CellField(m, &SweepCell::shimmer));
        if (!r.cells.empty() && !r.cells[0][m].winner.empty())
            add("_winner", "", CellField(m, &SweepCell::winner));
        if (!r.cells.empty() && r.cells[0][m].pagesRequested >= 0) {
            add("_pages_requested", "pages", CellField(m, &SweepCell::pagesRequested));
            add("_pages_resident", "pages", CellField(m, &SweepCell::pagesResident));
            add("_pages_dropped", "pages", CellField(m, &SweepCell::pagesDropped));
        }
    }
    return table;
}

}  // namespace

std::string SweepLightsCsv(const SweepResult& r) {
    const ColumnTable<LightRow> columns = LightColumns(r);
    std::string csv = CsvHeader(columns) + '\n';
    for (std::size_t l = 0; l < r.lights.size(); ++l)
        csv += CsvRow(columns, LightRow{&r, l}) + '\n';
    return csv;
}

}  // namespace lexel::cases
