#include "lexel/cases/studies/storage/storage_report.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>

#include "lexel/cases/plot/curve_plot.h"
#include "lexel/cases/plot/image_figure.h"
#include "lexel/cases/report/columns.h"
#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/image_io.h"

namespace lexel::cases {

namespace {

std::string FrustumLine(const spatial::ViewFrustum& f) {
    return "fov_y " + Significant(f.fovYDeg, 6) + "°, aspect " + Significant(f.aspect, 6) + ", n " +
           Significant(f.nearPlane, 6) + ", f " + Significant(f.farPlane, 6) +
           " (f/n = " + Significant(f.DepthRatio(), 6) + ")";
}

std::string Opt(const std::optional<double>& v) { return v ? Significant(*v, 6) : "–"; }

// Every `every`-th η of the sweeps, both ends included.
std::vector<std::size_t> TableEtas(std::size_t count) {
    std::vector<std::size_t> rows;
    const std::size_t every = std::max<std::size_t>(1, (count - 1) / 8);
    for (std::size_t i = 0; i < count; i += every) rows.push_back(i);
    if (rows.back() != count - 1) rows.push_back(count - 1);
    return rows;
}

std::string WarpText(const StorageStudy& s) {
    std::vector<std::string> header = {"eta"};
    for (double r : s.warpRatios) header.push_back("S̄ f/n = " + Significant(r, 6));
    TextTable table(header);
    for (std::size_t i : TableEtas(s.warp.front().size())) {
        std::vector<std::string> row = {Fixed(s.warp.front()[i].eta, 2)};
        for (const auto& sweep : s.warp) row.push_back(Significant(sweep[i].storage, 6));
        table.AddRow(row);
    }
    return "\nFigs. 5–6, light overhead: S̄ against η (-1 no warp, 0 LiSPSM, 1 PSM; eqs. 11–12)\n" +
           table.Render();
}

std::string HemisphereText(const StorageStudy& s) {
    TextTable table({"scheme", "min S̄", "max S̄", "max / min"});
    for (const HemisphereStudy& h : s.hemisphere)
        table.AddRow({h.scheme, Significant(h.minStorage, 6), Significant(h.maxStorage, 6),
                      Significant(h.maxStorage / h.minStorage, 4)});
    const int size = s.hemisphere.empty() ? 0 : s.hemisphere.front().grid.size;
    return "\nFig. 7: S̄ over the hemisphere of light directions (" + std::to_string(size) + "×" +
           std::to_string(size) + " grid, §4.4 vertex rule)\n" + table.Render();
}

std::string PartitionText(const StorageStudy& s) {
    TextTable table({"k", "ZP (eq. 17)", "ZP + W (eq. 18)", "S̄_opt"});
    for (const spatial::PartitionSweepPoint& p : s.partitions)
        table.AddRow({std::to_string(p.k), Significant(p.zp, 6), Significant(p.zpWarp, 6),
                      Significant(p.optimal, 6)});
    return "\nFig. 10, light overhead: S̄ against the partitions k\n" + table.Render();
}

std::string MapCountText(const StorageStudy& s) {
    TextTable table({"maps j", "ZP overhead", "ZP + W overhead", "ZP behind",
                     "FP + ZP + W overhead", "FP + ZP + W behind"});
    for (const spatial::MapCountPoint& p : s.maps)
        table.AddRow({std::to_string(p.maps), Significant(p.zpOverhead, 6),
                      Significant(p.zpWarpOverhead, 6), Significant(p.zpBehind, 6),
                      Opt(p.fpOverhead), Opt(p.fpBehind)});
    return "\nFig. 12: S̄ against the shadow maps j (eqs. 17–21; FP + ZP + W for j = 4m, its "
           "near-face map not counted in j)\n" +
           table.Render();
}

std::string CrossoverText(const StorageStudy& s) {
    TextTable table({"maps j", "partitions per face", "f/n (closed form)", "f/n (vertex rule)"});
    for (const spatial::CrossoverPoint& p : s.crossover)
        table.AddRow({std::to_string(p.maps), std::to_string(p.facePartitions),
                      Significant(p.depthRatio, 6), Significant(p.depthRatioEvaluated, 6)});
    return "\nFig. 13, light behind: the depth ratio above which FP + ZP + W needs less than ZP\n" +
           table.Render();
}

}  // namespace

std::string StorageText(const StorageStudy& s) {
    std::ostringstream out;
    out << "Lloyd et al. 2006's storage factor S̄ (texels over image pixels for w_l/w_i ≤ 1):\n  "
        << FrustumLine(s.frustum) << "\n"
        << "S̄_opt = ln(f/n) / (2 tanθ) = " << Significant(s.optimal, 6) << " (Appendix C)\n"
        << WarpText(s) << HemisphereText(s) << PartitionText(s) << MapCountText(s)
        << CrossoverText(s);
    return out.str();
}

nlohmann::json StorageJson(const StorageStudy& s) {
    nlohmann::json doc;
    doc["frustum"] = {{"fov_y_deg", s.frustum.fovYDeg},
                      {"aspect", s.frustum.aspect},
                      {"near", s.frustum.nearPlane},
                      {"far", s.frustum.farPlane}};
    doc["optimal"] = s.optimal;
    for (std::size_t r = 0; r < s.warpRatios.size(); ++r) {
        nlohmann::json points = nlohmann::json::array();
        for (const spatial::WarpSweepPoint& p : s.warp[r])
            points.push_back({{"eta", p.eta},
                              {"n_prime", FiniteOrNull(p.nPrime)},
                              {"max_x", p.maxErrors.x},
                              {"max_z", p.maxErrors.z},
                              {"storage", p.storage}});
        doc["warp"].push_back({{"depth_ratio", s.warpRatios[r]}, {"points", points}});
    }
    for (const HemisphereStudy& h : s.hemisphere) {
        nlohmann::json storage = nlohmann::json::array();
        for (const spatial::HemisphereCell& c : h.grid.cells)
            storage.push_back(c.inside ? nlohmann::json(c.storage) : nlohmann::json(nullptr));
        doc["hemisphere"].push_back({{"scheme", h.scheme},
                                     {"size", h.grid.size},
                                     {"min", h.minStorage},
                                     {"max", h.maxStorage},
                                     {"storage", storage}});
    }
    for (const spatial::PartitionSweepPoint& p : s.partitions)
        doc["partitions"].push_back(
            {{"k", p.k}, {"zp", p.zp}, {"zp_warp", p.zpWarp}, {"optimal", p.optimal}});
    for (const spatial::MapCountPoint& p : s.maps)
        doc["maps"].push_back(
            {{"maps", p.maps},
             {"zp_overhead", p.zpOverhead},
             {"zp_warp_overhead", p.zpWarpOverhead},
             {"zp_behind", p.zpBehind},
             {"zp_warp_behind", p.zpWarpBehind},
             {"fp_overhead",
              p.fpOverhead ? nlohmann::json(*p.fpOverhead) : nlohmann::json(nullptr)},
             {"fp_behind", p.fpBehind ? nlohmann::json(*p.fpBehind) : nlohmann::json(nullptr)}});
    for (const spatial::CrossoverPoint& p : s.crossover)
        doc["crossover"].push_back({{"maps", p.maps},
                                    {"face_partitions", p.facePartitions},
                                    {"depth_ratio", p.depthRatio},
                                    {"depth_ratio_evaluated", p.depthRatioEvaluated}});
    return doc;
}

std::string StorageCsv(const StorageStudy& s) {
    std::ostringstream csv;
    csv << "figure,series,x1,x2,value\n";
    const auto row = [&](const char* figure, const std::string& series, const std::string& x1,
                         const std::string& x2, double value) {
        csv << figure << ',' << series << ',' << x1 << ',' << x2 << ',' << CsvNumber(value) << '\n';
    };
    for (std::size_t r = 0; r < s.warpRatios.size(); ++r)
        for (const spatial::WarpSweepPoint& p : s.warp[r])
            row("fig5_6", "warp", CsvNumber(p.eta), CsvNumber(s.warpRatios[r]), p.storage);
    for (const HemisphereStudy& h : s.hemisphere)
        for (const spatial::HemisphereCell& c : h.grid.cells)
            if (c.inside) row("fig7", h.scheme, CsvNumber(c.gx), CsvNumber(c.gy), c.storage);
    for (const spatial::PartitionSweepPoint& p : s.partitions) {
        row("fig10", "ZP", std::to_string(p.k), "", p.zp);
        row("fig10", "ZP + W", std::to_string(p.k), "", p.zpWarp);
        row("fig10", "optimal", std::to_string(p.k), "", p.optimal);
    }
    for (const spatial::MapCountPoint& p : s.maps) {
        const std::string j = std::to_string(p.maps);
        row("fig12", "ZP overhead", j, "", p.zpOverhead);
        row("fig12", "ZP + W overhead", j, "", p.zpWarpOverhead);
        row("fig12", "ZP behind", j, "", p.zpBehind);
        if (p.fpOverhead) row("fig12", "FP + ZP + W overhead", j, "", *p.fpOverhead);
        if (p.fpBehind) row("fig12", "FP + ZP + W behind", j, "", *p.fpBehind);
    }
    for (const spatial::CrossoverPoint& p : s.crossover) {
        row("fig13", "closed form", std::to_string(p.maps), std::to_string(p.facePartitions),
            p.depthRatio);
        row("fig13", "vertex rule", std::to_string(p.maps), std::to_string(p.facePartitions),
            p.depthRatioEvaluated);
    }
    return csv.str();
}

namespace {

// Fig. 7's colours for log10 S̄ from the smallest to the largest decade.
constexpr spatial::ImageColour kHemisphereRamp[4] = {
    {0.1f, 0.1f, 0.5f}, {0.0f, 0.8f, 0.9f}, {1.0f, 0.9f, 0.1f}, {0.8f, 0.05f, 0.05f}};

// log10 S̄ in [lo, hi] → a dark-blue, cyan, yellow, red ramp; white outside the hemisphere. One
// pixel per grid cell (the figure scales it up).
spatial::Image HemisphereImage(const HemisphereStudy& h, double lo, double hi) {
    const int size = h.grid.size;
    spatial::Image image = spatial::MakeImage(size, size, 3, 1.0f);
    for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
            const spatial::HemisphereCell& cell = h.grid.cells[row * size + col];
            if (!cell.inside) continue;
            const double t =
                std::clamp((std::log10(cell.storage) - lo) / std::max(1e-12, hi - lo), 0.0, 1.0);
            const double segment = std::min(2.999999, 3.0 * t);
            const int i = static_cast<int>(segment);
            const float w = static_cast<float>(segment - i);
            const spatial::ImageColour a = kHemisphereRamp[i], b = kHemisphereRamp[i + 1];
            image.at(col, row, 0) = (1.0f - w) * a.r + w * b.r;
            image.at(col, row, 1) = (1.0f - w) * a.g + w * b.g;
            image.at(col, row, 2) = (1.0f - w) * a.b + w * b.b;
        }
    return image;
}

// Fig. 7's figure for one scheme: what the disc shows, its extremes, and the shared log scale.
ImageFigure HemisphereFigure(const HemisphereStudy& h, const spatial::ViewFrustum& frustum,
                             double lo, double hi) {
    ImageFigure figure;
    figure.title = "Fig. 7: storage factor S̄ over the hemisphere of light directions, " + h.scheme;
    figure.lines = {
        "The hemisphere seen from above (" + std::to_string(h.grid.size) + " × " +
            std::to_string(h.grid.size) +
            " cells): the light behind the viewer on the left, in front on the right, overhead "
            "in the middle; frustum " +
            FrustumLine(frustum) + ".",
        "S̄ from " + Significant(h.minStorage, 4) + " to " + Significant(h.maxStorage, 4) + " for " +
            h.scheme + "; the three schemes share one scale."};
    figure.key = {{"outside the hemisphere", {1.0f, 1.0f, 1.0f}}};
    figure.bar = ColourBar{
        "storage factor S̄ (log scale)",
        std::vector<spatial::ImageColour>(std::begin(kHemisphereRamp), std::end(kHemisphereRamp)),
        lo, hi, true};
    return figure;
}

std::string FileStem(const std::string& scheme) {
    if (scheme == "no warp") return "no_warp";
    if (scheme == "LiSPSM") return "lispsm";
    return "fp_w";
}

}  // namespace

std::vector<std::string> WriteStorageFigures(const std::filesystem::path& dir,
                                             const StorageStudy& s) {
    std::vector<std::string> files;
    const auto path = [&](const std::string& name) {
        files.push_back(name);
        return (dir / name).string();
    };
    CurvePlot warp;
    warp.title =
        "Figs. 5–6: S̄ against η, light overhead (fov_y " + Significant(s.frustum.fovYDeg, 4) + "°)";
    warp.xLabel = "η (-1 no warp, 0 LiSPSM, 1 PSM)";
    warp.yLabel = "storage factor S̄";
    warp.logX = false;
    warp.logY = true;
    for (std::size_t r = 0; r < s.warpRatios.size(); ++r) {
        PlotCurve curve{"f/n = " + Significant(s.warpRatios[r], 6), {}, {}};
        for (const spatial::WarpSweepPoint& p : s.warp[r]) {
            curve.x.push_back(p.eta);
            curve.y.push_back(p.storage);
        }
        warp.curves.push_back(curve);
    }
    WriteCurvePlot(path("fig5_6_warp.png"), warp);

    // Fig. 7: one colour scale for the three schemes, whole decades.
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const HemisphereStudy& h : s.hemisphere)
        lo = std::min(lo, std::log10(h.minStorage)), hi = std::max(hi, std::log10(h.maxStorage));
    lo = std::floor(lo), hi = std::ceil(hi);
    for (const HemisphereStudy& h : s.hemisphere)
        WriteImageFigure(path("fig7_hemisphere_" + FileStem(h.scheme) + ".png"),
                         HemisphereImage(h, lo, hi), HemisphereFigure(h, s.frustum, lo, hi));

    const std::vector<double> powersOfTwo = {1, 2, 4, 8, 16};
    CurvePlot partitions;
    partitions.title = "Fig. 10: S̄ against the partitions k, light overhead";
    partitions.xLabel = "partitions k";
    partitions.yLabel = "storage factor S̄";
    partitions.logY = true;
    partitions.xTicks = powersOfTwo;
    partitions.guideY = s.optimal;
    partitions.guideLabel = "S̄_opt = " + Significant(s.optimal, 4);
    PlotCurve zp{"ZP", {}, {}}, zpWarp{"ZP + W", {}, {}};
    for (const spatial::PartitionSweepPoint& p : s.partitions) {
        zp.x.push_back(p.k), zp.y.push_back(p.zp);
        zpWarp.x.push_back(p.k), zpWarp.y.push_back(p.zpWarp);
    }
    partitions.curves = {zp, zpWarp};
    WriteCurvePlot(path("fig10_partitions.png"), partitions);

    CurvePlot maps = partitions;
    maps.title =
        "Fig. 12: S̄ against the shadow maps j (f/n = " + Significant(s.frustum.DepthRatio(), 6) +
        ")";
    maps.xLabel = "shadow maps j";
    PlotCurve zpOver{"ZP, light overhead", {}, {}}, zpwOver{"ZP + W, overhead", {}, {}},
        zpBehind{"ZP (+ W), behind", {}, {}}, fpOver{"FP + ZP + W, overhead", {}, {}},
        fpBehind{"FP + ZP + W, behind", {}, {}};
    for (const spatial::MapCountPoint& p : s.maps) {
        const double j = p.maps;
        zpOver.x.push_back(j), zpOver.y.push_back(p.zpOverhead);
        zpwOver.x.push_back(j), zpwOver.y.push_back(p.zpWarpOverhead);
        zpBehind.x.push_back(j), zpBehind.y.push_back(p.zpBehind);
        if (p.fpOverhead) fpOver.x.push_back(j), fpOver.y.push_back(*p.fpOverhead);
        if (p.fpBehind) fpBehind.x.push_back(j), fpBehind.y.push_back(*p.fpBehind);
    }
    maps.curves = {zpOver, zpwOver, zpBehind, fpOver, fpBehind};
    WriteCurvePlot(path("fig12_maps.png"), maps);

    CurvePlot crossover;
    crossover.title = "Fig. 13: ZP/FP crossover, light behind";
    crossover.xLabel = "shadow maps j";
    crossover.yLabel = "depth ratio f/n";
    crossover.logX = false;
    crossover.logY = true;
    PlotCurve closed{"closed form", {}, {}}, evaluated{"vertex rule", {}, {}};
    for (const spatial::CrossoverPoint& p : s.crossover) {
        closed.x.push_back(p.maps), closed.y.push_back(p.depthRatio);
        evaluated.x.push_back(p.maps), evaluated.y.push_back(p.depthRatioEvaluated);
    }
    crossover.curves = {closed, evaluated};
    WriteCurvePlot(path("fig13_crossover.png"), crossover);
    return files;
}

// ---- measured beside analytic ------------------------------------------------------------------

namespace {

// A row of `lexel storage --case`: one method on light `light`.
struct StorageRow {
    std::size_t light = 0;
    const CaseStorageLight* outcome = nullptr;
    const CaseStorageRow* method = nullptr;
};

// The columns of a storage row in `lexel storage --case --format json|csv`, in CSV order.
ColumnTable<StorageRow> StorageColumns() {
    const auto number = [](auto get) {
        return [get](const StorageRow& r) { return CellValue(double(get(r))); };
    };
    using R = StorageRow;
    return {
        {"light", "", [](const R& r) { return CellValue(std::int64_t(r.light)); }, kCsvColumn},
        {"method", "", [](const R& r) { return CellValue(r.method->method); }},
        {"maps", "maps", [](const R& r) { return CellValue(std::int64_t{r.method->maps}); }},
        {"texels", "texels", [](const R& r) { return CellValue(r.method->texels); }},
        {"max_perspective_aliasing", "texels/pixel",
         number([](const R& r) { return r.method->perspectiveMax; })},
        {"storage_factor", "texels/pixel", number([](const R& r) { return r.method->measured; })},
        {"storage_factor_p99", "texels/pixel",
         number([](const R& r) { return r.method->measuredP99; })},
        {"scheme", "", [](const R& r) { return CellValue(r.method->camera.scheme); }},
        {"scheme_storage_camera", "texels/pixel",
         number([](const R& r) { return r.method->camera.storage; })},
        {"scheme_storage_visible", "texels/pixel",
         number([](const R& r) { return r.method->visible.storage; })},
        {"optimal_camera", "texels/pixel",
         number([](const R& r) { return r.outcome->optimalCamera; }), kCsvColumn},
        {"optimal_visible", "texels/pixel",
         number([](const R& r) { return r.outcome->optimalVisible; }), kCsvColumn}};
}

std::vector<StorageRow> StorageRows(std::size_t l, const CaseStorageLight& light) {
    std::vector<StorageRow> rows;
    for (const CaseStorageRow& row : light.rows) rows.push_back({l, &light, &row});
    return rows;
}

// The terminal's storage table of one light.
TextTable StorageTable(std::size_t l, const CaseStorageLight& light) {
    const ColumnTable<StorageRow> columns = StorageColumns();
    const std::vector<TextColumn<StorageRow>> text = {
        TextColumnOf(columns, "method", "method"),
        TextColumnOf(columns, "maps", "maps"),
        TextColumnOf(columns, "max_perspective_aliasing", "max\nw_l/w_i"),
        TextColumnOf(columns, "storage_factor", "S\nmeasured"),
        TextColumnOf(columns, "storage_factor_p99", "S measured\n(p99)"),
        TextColumnOf(columns, "scheme", "scheme"),
        TextColumnOf(columns, "scheme_storage_camera", "S scheme\n(camera)"),
        TextColumnOf(columns, "scheme_storage_visible", "S scheme\n(visible)"),
        {"measured /\nS_opt\n(visible)", [](const StorageRow& r) {
             return Significant(r.method->measured / r.outcome->optimalVisible, 3);
         }}};
    return TextTableOf(text, StorageRows(l, light));
}

}  // namespace

std::string CaseStorageText(const CaseStorage& r) {
    std::ostringstream out;
    out << "Measured storage factor beside Lloyd et al. 2006's S̄, " << r.caseName << ":\n  camera "
        << FrustumLine(r.camera) << "\n  visible planar depths "
        << Significant(r.visible.nearPlane, 4) << "–" << Significant(r.visible.farPlane, 4)
        << " (f/n = " << Significant(r.visible.DepthRatio(), 4)
        << ")\n  partitioned methods k = " << r.partitions << "\n";
    for (std::size_t l = 0; l < r.lights.size(); ++l) {
        const CaseStorageLight& light = r.lights[l];
        out << (l ? "\n" : "") << "light " << l << ": " << LightLabel(light.light)
            << ", γ = " << Fixed(light.gammaDeg, 1) << "°"
            << (light.light.type == spatial::Light::Type::kPoint
                    ? " (direction from the visible points' centroid)"
                    : "")
            << "\nS̄_opt " << Significant(light.optimalCamera, 4) << " (camera) / "
            << Significant(light.optimalVisible, 4) << " (visible depths); best single map "
            << Significant(light.bestSingleCamera, 4) << " / "
            << Significant(light.bestSingleVisible, 4) << "\n";
        out << StorageTable(l, light).Render();
    }
    return out.str();
}

nlohmann::json CaseStorageJson(const CaseStorage& r) {
    const auto frustum = [](const spatial::ViewFrustum& f) {
        return nlohmann::json{{"fov_y_deg", f.fovYDeg},
                              {"aspect", f.aspect},
                              {"near", f.nearPlane},
                              {"far", f.farPlane}};
    };
    nlohmann::json doc = {{"case", r.caseName},
                          {"camera", frustum(r.camera)},
                          {"visible", frustum(r.visible)},
                          {"partitions", r.partitions}};
    const ColumnTable<StorageRow> columns = StorageColumns();
    for (const CaseStorageLight& light : r.lights) {
        nlohmann::json methods = nlohmann::json::array();
        for (const StorageRow& row : StorageRows(0, light)) {
            nlohmann::json method;
            AddJsonColumns(columns, row, method);
            methods.push_back(method);
        }
        doc["lights"].push_back({{"description", LightLabel(light.light)},
                                 {"gamma_deg", light.gammaDeg},
                                 {"optimal_camera", light.optimalCamera},
                                 {"optimal_visible", light.optimalVisible},
                                 {"best_single_camera", light.bestSingleCamera},
                                 {"best_single_visible", light.bestSingleVisible},
                                 {"methods", methods}});
    }
    return doc;
}

std::string CaseStorageColumnReference() { return ColumnReference(StorageColumns()); }

std::string CaseStorageCsv(const CaseStorage& r) {
    const ColumnTable<StorageRow> columns = StorageColumns();
    std::string csv = CsvHeader(columns) + '\n';
    for (std::size_t l = 0; l < r.lights.size(); ++l)
        for (const StorageRow& row : StorageRows(l, r.lights[l]))
            csv += CsvRow(columns, row) + '\n';
    return csv;
}

}  // namespace lexel::cases
