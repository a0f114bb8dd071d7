#include "lexel/cases/report/spatial_report.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "lexel/cases/plot/image_figure.h"
#include "lexel/cases/report/columns.h"
#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/solvers/statistics.h"
#include "lexel/spatial/harness/images.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::cases {

std::string SampleCountText(const spatial::LightSamples& samples) {
    const std::size_t contacts = std::min(samples.contactSamples, samples.lsX.size());
    std::string text = std::to_string(samples.lsX.size() - contacts) + " boundary samples";
    if (contacts > 0) text += " and " + std::to_string(contacts) + " at thin-shadow contacts";
    return text;
}

std::vector<std::string> LightHeaderLines(std::size_t l, const spatial::LightOutcome& o) {
    std::vector<std::string> lines = {"light " + std::to_string(l) + ": " + LightLabel(o.light) +
                                      " — " + std::to_string(o.receiverPixels) +
                                      " pixels face it, " + std::to_string(o.truthShadowed) +
                                      " shadowed (Embree rays), " + SampleCountText(o.samples)};
    if (o.mapTruthDisagree >= 0)
        lines.push_back(
            "the report's focused 4000² truth map disagrees with the rays on " +
            std::to_string(o.mapTruthDisagree) +
            (o.mapTruthDisagree == 1 ? " pixel (" : " pixels (") +
            Fixed(100.0 * o.mapTruthDisagree / std::max<std::int64_t>(1, o.receiverPixels), 3) +
            "%)");
    return lines;
}

// "mean ± 95% half-width" of a phase mean (sub_texel_phase.h): kNormal95 standard errors.
std::string PhaseMeanText(double mean, double standardError) {
    return Fixed(mean, 1) + " ± " + Fixed(kNormal95 * standardError, 1);
}

namespace {

// A row of `lexel run`'s method table: one method's outcome on light `light`.
struct MethodRow {
    std::size_t light = 0;
    const spatial::LightOutcome* outcome = nullptr;
    const spatial::MethodOutcome* method = nullptr;
};

CellValue ToCell(std::int64_t n) { return n; }
CellValue ToCell(int n) { return std::int64_t{n}; }
CellValue ToCell(double x) { return x; }
CellValue ToCell(const std::string& s) { return s; }

// The getter of a MethodMetrics field.
template <class T>
std::function<CellValue(const MethodRow&)> Metric(T spatial::MethodMetrics::*field) {
    return [field](const MethodRow& row) { return ToCell(row.method->metrics.*field); };
}

// A virtual shadow map's page count (`field` of PageOutcome); nothing for the other methods.
std::function<CellValue(const MethodRow&)> Pages(std::int64_t spatial::PageOutcome::*field) {
    return [field](const MethodRow& row) {
        return row.method->pages ? CellValue(*row.method->pages.*field) : CellValue{};
    };
}

// A virtual shadow map's maps are its resident pages; a partitioned method's its cascades.
CellValue Maps(const MethodRow& row) {
    const spatial::MethodOutcome& m = *row.method;
    return m.pages ? m.pages->resident
                   : static_cast<std::int64_t>(std::max<std::size_t>(1, m.cascades.size()));
}

// The columns of a method's row in `lexel run --format json|csv` (and its terminal table), in
// CSV order; `phased` (--phases K > 1) adds the phase means.
ColumnTable<MethodRow> MethodColumns(bool phased) {
    using spatial::MethodMetrics;
    ColumnTable<MethodRow> table = {
        {"light", "", [](const MethodRow& r) { return CellValue(std::int64_t(r.light)); },
         kCsvColumn},
        {"method", "", [](const MethodRow& r) { return ToCell(r.method->method); }},
        {"misclassified", "pixels", Metric(&MethodMetrics::misclassified)},
        {"false_shadow", "pixels", Metric(&MethodMetrics::falseShadow)},
        {"false_light", "pixels",
         [](const MethodRow& r) {
             return CellValue(r.method->metrics.misclassified - r.method->metrics.falseShadow);
         }},
        {"h", "pixels²/texel²", Metric(&MethodMetrics::h)},
        {"ms", "ms", Metric(&MethodMetrics::ms)},
        {"uncovered", "pixels", Metric(&MethodMetrics::uncovered)},
        {"mean_footprint", "frame pixels/texel", Metric(&MethodMetrics::footprintMean)},
        {"max_footprint", "frame pixels/texel", Metric(&MethodMetrics::footprintMax)},
        {"maps", "maps", Maps, kCsvColumn},
        {"max_perspective_aliasing", "texels/pixel", Metric(&MethodMetrics::perspectiveMax)},
        {"storage_factor", "texels/pixel", Metric(&MethodMetrics::storageFactor)},
        {"pages_requested", "pages", Pages(&spatial::PageOutcome::requested), kCsvColumn},
        {"pages_resident", "pages", Pages(&spatial::PageOutcome::resident), kCsvColumn},
        {"pages_dropped", "pages", Pages(&spatial::PageOutcome::dropped), kCsvColumn}};
    if (phased) {
        const ColumnTable<MethodRow> phaseColumns = {
            {"phases", "phases", Metric(&MethodMetrics::phases)},
            {"misclassified_mean", "pixels", Metric(&MethodMetrics::misclassifiedMean)},
            {"misclassified_standard_error", "pixels", Metric(&MethodMetrics::misclassifiedError)},
            {"false_shadow_mean", "pixels", Metric(&MethodMetrics::falseShadowMean)}};
        table.insert(table.end(), phaseColumns.begin(), phaseColumns.end());
    }
    const ColumnTable<MethodRow> jsonOnly = {
        {"p99_perspective_aliasing", "texels/pixel", Metric(&MethodMetrics::perspectiveP99),
         kJsonColumn},
        {"texels", "texels", Metric(&MethodMetrics::texels), kJsonColumn},
        {"storage_factor_p99", "texels/pixel", Metric(&MethodMetrics::storageFactorP99),
         kJsonColumn}};
    table.insert(table.end(), jsonOnly.begin(), jsonOnly.end());
    return table;
}

std::vector<MethodRow> MethodRows(std::size_t light, const spatial::LightOutcome& o) {
    std::vector<MethodRow> rows;
    for (const spatial::MethodOutcome& m : o.methods) rows.push_back({light, &o, &m});
    return rows;
}

}  // namespace

TextTable SpatialMethodTable(const spatial::LightOutcome& o) {
    // Over several phases: the mean and its 95% interval beside phase 0's count.
    const bool phased = o.phases > 1;
    const ColumnTable<MethodRow> columns = MethodColumns(phased);
    std::vector<TextColumn<MethodRow>> text = {
        TextColumnOf(columns, "method", "method"),
        TextColumnOf(columns, "misclassified", "misclassified")};
    if (phased)
        text.push_back({"mean over\n" + std::to_string(o.phases) +
                            (o.maxPhases > o.phases ? "+" : "") + " phases\n(95% CI)",
                        [&o](const MethodRow& r) {
                            const spatial::MethodMetrics& metrics = r.method->metrics;
                            std::string mean = PhaseMeanText(metrics.misclassifiedMean,
                                                             metrics.misclassifiedError);
                            if (metrics.phases != o.phases)
                                mean += " at " + std::to_string(metrics.phases);
                            return mean;
                        }});
    const std::vector<TextColumn<MethodRow>> rest = {
        TextColumnOf(columns, "false_shadow", "false\nshadow"),
        TextColumnOf(columns, "false_light", "false\nlight"),
        TextColumnOf(columns, "uncovered", "uncovered"),
        TextColumnOf(columns, "mean_footprint", "mean\nσ1(J⁻¹)"),
        TextColumnOf(columns, "max_footprint", "max\nσ1(J⁻¹)"),
        TextColumnOf(columns, "storage_factor", "storage\nfactor"),
        TextColumnOf(columns, "h", "h\n(eq. 6)", SignificantText(6)),
        TextColumnOf(columns, "ms", "ms", FixedText(3))};
    text.insert(text.end(), rest.begin(), rest.end());
    return TextTableOf(text, MethodRows(0, o));
}

std::vector<std::string> IterationLines(const spatial::LightOutcome& o) {
    std::vector<std::string> lines;
    for (const auto& m : o.methods) {
        if (m.trace.hAfterIteration.empty()) continue;
        std::string line = m.method + ": h by Algorithm 1 iteration";
        for (std::size_t i = 0; i < m.trace.hAfterIteration.size(); ++i)
            line += (i ? " → " : " ") + Significant(m.trace.hAfterIteration[i], 6);
        if (m.metrics.h < m.trace.hBeforeRefine) line += "; refined " + Significant(m.metrics.h, 6);
        lines.push_back(line);
    }
    return lines;
}

namespace {

// A row of the cascade table: cascade `index` of a partitioned method.
struct CascadeRow {
    const spatial::MethodOutcome* method = nullptr;
    std::size_t index = 0;
    const spatial::CascadeOutcome& Cascade() const { return method->cascades[index]; }
};

// The columns of a cascade in `lexel run --format json` (beside its clip_from_world) and the
// terminal's cascade table.
ColumnTable<CascadeRow> CascadeColumns() {
    const auto field = [](auto get) {
        return [get](const CascadeRow& r) { return CellValue(get(r.Cascade())); };
    };
    using spatial::CascadeOutcome;
    return {
        {"z_near", "eye depth", field([](const CascadeOutcome& c) { return c.cascade.zNear; }),
         kJsonColumn},
        {"z_far", "eye depth", field([](const CascadeOutcome& c) { return c.cascade.zFar; }),
         kJsonColumn},
        {"width", "texels",
         field([](const CascadeOutcome& c) { return std::int64_t{c.cascade.map.width}; }),
         kJsonColumn},
        {"height", "texels",
         field([](const CascadeOutcome& c) { return std::int64_t{c.cascade.map.height}; }),
         kJsonColumn},
        {"visible_points", "points",
         field([](const CascadeOutcome& c) { return std::int64_t(c.cascade.visiblePoints); }),
         kJsonColumn},
        {"pixels", "pixels", field([](const CascadeOutcome& c) { return c.pixels; }), kJsonColumn},
        {"h", "pixels²/texel²", field([](const CascadeOutcome& c) { return c.h; }), kJsonColumn}};
}

// A row of the page table: a virtual shadow map's pages (MethodOutcome::pages set).
struct PageRow {
    const spatial::MethodOutcome* method = nullptr;
    const spatial::PageOutcome& Pages() const { return *method->pages; }
};

// The columns of a virtual shadow map's pages in JSON and the terminal's table.
ColumnTable<PageRow> PageColumns() {
    using spatial::PageOutcome;
    const auto count = [](auto field) {
        return [field](const PageRow& r) { return CellValue(std::int64_t(r.Pages().*field)); };
    };
    return {{"page_texels", "texels", count(&PageOutcome::pageTexels), kJsonColumn},
            {"pool_pages", "pages", count(&PageOutcome::poolPages), kJsonColumn},
            {"requested", "pages", count(&PageOutcome::requested), kJsonColumn},
            {"resident", "pages", count(&PageOutcome::resident), kJsonColumn},
            {"dropped", "pages", count(&PageOutcome::dropped), kJsonColumn},
            {"lod_bias", "levels", [](const PageRow& r) { return CellValue(r.Pages().lodBias); },
             kJsonColumn}};
}

}  // namespace

std::optional<TextTable> CascadeTable(const spatial::LightOutcome& o) {
    std::vector<CascadeRow> rows;
    for (const spatial::MethodOutcome& m : o.methods)
        for (std::size_t c = 0; c < m.cascades.size(); ++c) rows.push_back({&m, c});
    if (rows.empty()) return std::nullopt;
    const ColumnTable<CascadeRow> columns = CascadeColumns();
    const std::vector<TextColumn<CascadeRow>> text = {
        {"method", [](const CascadeRow& r) { return r.index == 0 ? r.method->method : ""; }},
        {"cascade", [](const CascadeRow& r) { return std::to_string(r.index); }},
        TextColumnOf(columns, "z_near", "depth\nfrom"),
        TextColumnOf(columns, "z_far", "depth\nto"),
        {"map",
         [](const CascadeRow& r) {
             const spatial::Resolution map = r.Cascade().cascade.map;
             return std::to_string(map.width) + "×" + std::to_string(map.height);
         }},
        TextColumnOf(columns, "visible_points", "readback\npoints"),
        TextColumnOf(columns, "pixels", "pixels"),
        TextColumnOf(columns, "h", "h")};
    return TextTableOf(text, rows);
}

std::optional<TextTable> PageTable(const spatial::LightOutcome& o) {
    std::vector<PageRow> rows;
    for (const spatial::MethodOutcome& m : o.methods)
        if (m.pages) rows.push_back({&m});
    if (rows.empty()) return std::nullopt;
    const ColumnTable<PageRow> columns = PageColumns();
    const std::vector<TextColumn<PageRow>> text = {
        {"method", [](const PageRow& r) { return r.method->method; }},
        {"page", [](const PageRow& r) { return std::to_string(r.Pages().pageTexels) + "²"; }},
        TextColumnOf(columns, "pool_pages", "pool\npages"),
        TextColumnOf(columns, "requested", "pages\nrequested"),
        TextColumnOf(columns, "resident", "pages\nresident"),
        TextColumnOf(columns, "dropped", "pages\ndropped"),
        TextColumnOf(columns, "lod_bias", "LOD\nbias", FixedText(3))};
    return TextTableOf(text, rows);
}

std::string CameraPathCaption(const CameraPathStudy& study, std::size_t light) {
    return "camera path, light " + std::to_string(light) + ": P changed in " +
           std::to_string(study.Changes()) + " of " + std::to_string(study.poses.size()) +
           " poses (hysteresis: keep P unless the new median badness is below 80% of the kept "
           "one)";
}

TextTable CameraPathTable(const CameraPathStudy& study) {
    TextTable table({"pose", "P\nchanged", "median\nbadness\nkept", "median\nbadness\nnew",
                     "misclassified\n(hysteresis)", "misclassified\n(fresh)"});
    for (std::size_t k = 0; k < study.poses.size(); ++k) {
        const PoseOutcome& p = study.poses[k];
        table.AddRow({std::to_string(k), p.changed ? "yes" : "no", Significant(p.medianKept, 5),
                      Significant(p.medianNew, 5), std::to_string(p.misclassifiedHysteresis),
                      std::to_string(p.misclassifiedFresh)});
    }
    return table;
}

std::string ShimmerCaption(std::size_t light) {
    return "camera path, light " + std::to_string(light) +
           ": pixels whose shadow decision changes between consecutive poses where the rays' "
           "does not";
}

TextTable ShimmerTable(const CameraPathStudy& study) {
    TextTable table({"method", "shimmer (% of stable\npixels per step)"});
    for (std::size_t m = 0; m < study.methods.size(); ++m)
        table.AddRow({study.methods[m], Fixed(study.shimmerPercent[m], 3)});
    return table;
}

std::string SpatialRunText(const spatial::Scene&, const SpatialRun& run) {
    std::ostringstream text;
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) {
        const auto& o = run.outcomes[l];
        const std::vector<std::string> header = LightHeaderLines(l, o);
        text << (l ? "\n" : "");
        for (std::size_t k = 0; k < header.size(); ++k)
            text << WrapText((k ? "  " : "") + header[k], kTerminalColumns, "  ");
        text << SpatialMethodTable(o).Render();
        for (const std::string& line : IterationLines(o))
            text << WrapText(line, kTerminalColumns, "  ");
        if (const std::optional<TextTable> cascades = CascadeTable(o))
            text << "\ncascades of the partitioned methods, light " << l
                 << " (depth: planar eye depth)\n"
                 << cascades->Render();
        if (const std::optional<TextTable> pages = PageTable(o))
            text << "\nvirtual shadow maps' pages, light " << l << '\n' << pages->Render();
    }
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l)
        text << '\n'
             << WrapText(CameraPathCaption(run.cameraPath[l], l), kTerminalColumns, "  ")
             << CameraPathTable(run.cameraPath[l]).Render() << '\n'
             << WrapText(ShimmerCaption(l), kTerminalColumns, "  ")
             << ShimmerTable(run.cameraPath[l]).Render();
    return text.str();
}

namespace {

// A 4×4 as 4 rows of 4 numbers (row-major), each printed so that it reads back to the same double.
nlohmann::json RowMajor(const glm::dmat4& m) {
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}

// What a method's clip_from_world is: its one map's ("single"), its first cascade's ("cascades":
// each cascade has its own), the base of its warp ("warped") or its coarsest page's ("virtual").
const char* MapKind(const spatial::MethodOutcome& m) {
    if (m.pages) return "virtual";
    if (!m.cascades.empty()) return "cascades";
    return spatial::IsWarpedMethod(m.method) ? "warped" : "single";
}

}  // namespace

namespace {

// One method of light l: its columns, its h trace, its map kind and clip-from-world matrix, its
// cascades (each with its matrix) and pages.
nlohmann::json MethodJson(const spatial::Scene& scene, const SpatialRun& run, std::size_t l,
                          const ColumnTable<MethodRow>& columns, const spatial::MethodOutcome& m) {
    const auto& o = run.outcomes[l];
    nlohmann::json method;
    AddJsonColumns(columns, MethodRow{l, &o, &m}, method);
    if (!m.trace.hAfterIteration.empty()) method["h_after_iteration"] = m.trace.hAfterIteration;
    const spatial::Resolution map =
        m.pages ? spatial::Resolution{m.pages->pageTexels, m.pages->pageTexels} : scene.shadowMap;
    method["map_kind"] = MapKind(m);
    method["clip_from_world"] = RowMajor(run.evaluator->ClipFromWorldOf(o.light, m.matrix, map));
    const ColumnTable<CascadeRow> cascadeColumns = CascadeColumns();
    for (std::size_t c = 0; c < m.cascades.size(); ++c) {
        const spatial::Cascade& cascade = m.cascades[c].cascade;
        nlohmann::json entry = {{"clip_from_world", RowMajor(run.evaluator->ClipFromWorldOf(
                                                        o.light, cascade.matrix, cascade.map))}};
        AddJsonColumns(cascadeColumns, CascadeRow{&m, c}, entry);
        method["cascades"].push_back(entry);
    }
    if (m.pages) AddJsonColumns(PageColumns(), PageRow{&m}, method["pages"]);
    return method;
}

// One light's camera-path study: per pose whether the map changed and its counts, and each
// method's shimmer.
nlohmann::json CameraPathJson(std::size_t l, const CameraPathStudy& study) {
    nlohmann::json poses = nlohmann::json::array();
    for (std::size_t k = 0; k < study.poses.size(); ++k) {
        const PoseOutcome& p = study.poses[k];
        poses.push_back({{"pose", k},
                         {"changed", p.changed},
                         {"median_badness_kept", FiniteOrNull(p.medianKept)},
                         {"median_badness_new", p.medianNew},
                         {"misclassified_hysteresis", p.misclassifiedHysteresis},
                         {"misclassified_fresh", p.misclassifiedFresh}});
    }
    nlohmann::json shimmer;
    for (std::size_t m = 0; m < study.methods.size(); ++m)
        shimmer[study.methods[m]] = study.shimmerPercent[m];
    return {{"light", l},
            {"poses", poses.size()},
            {"changes", study.Changes()},
            {"frames", poses},
            {"shimmer_percent", shimmer}};
}

}  // namespace

nlohmann::json SpatialRunJson(const spatial::Scene& scene, const SpatialRun& run) {
    nlohmann::json doc;
    doc["case"] = scene.name;
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) {
        const auto& o = run.outcomes[l];
        nlohmann::json light = {{"light", l},
                                {"description", LightLabel(o.light)},
                                {"receiver_pixels", o.receiverPixels},
                                {"truth_shadowed", o.truthShadowed},
                                {"boundary_samples", o.samples.lsX.size()}};
        if (o.mapTruthDisagree >= 0) light["map4000_disagrees_with_rays"] = o.mapTruthDisagree;
        const ColumnTable<MethodRow> columns = MethodColumns(o.phases > 1);
        for (const auto& m : o.methods)
            light["methods"].push_back(MethodJson(scene, run, l, columns, m));
        doc["lights"].push_back(light);
    }
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l)
        doc["camera_path"].push_back(CameraPathJson(l, run.cameraPath[l]));
    return doc;
}

std::string SpatialRunColumnReference() { return ColumnReference(MethodColumns(true)); }

std::string SpatialRunCsv(const SpatialRun& run) {
    // Over several phases (every light has the case's): the means and the standard error.
    const bool phased = !run.outcomes.empty() && run.outcomes.front().phases > 1;
    const ColumnTable<MethodRow> columns = MethodColumns(phased);
    std::string csv = CsvHeader(columns) + '\n';
    for (std::size_t l = 0; l < run.outcomes.size(); ++l)
        for (const MethodRow& row : MethodRows(l, run.outcomes[l]))
            csv += CsvRow(columns, row) + '\n';
    return csv;
}

namespace {

std::string Count(std::int64_t n, const std::string& what) {
    return std::to_string(n) + " " + what;
}

// The figure of a frame or error image: title, counts and key.
ImageFigure FrameFigure(const std::string& title, const spatial::LightOutcome& o,
                        const spatial::MethodOutcome& m, bool errors) {
    ImageFigure figure;
    figure.title = title;
    const std::int64_t falseLight = m.metrics.misclassified - m.metrics.falseShadow;
    if (errors) {
        figure.lines = {"Where " + m.method +
                            "'s shadow decision differs from exact shadow rays: " +
                            std::to_string(m.metrics.misclassified) + " of " +
                            Count(o.receiverPixels, "counted pixels") + " misclassified (" +
                            std::to_string(m.metrics.falseShadow) + " false shadow, " +
                            std::to_string(falseLight) + " false light); " +
                            Count(m.metrics.uncovered, "uncovered") + ".",
                        "Counted pixels: visible and facing the light; those facing away are in "
                        "shadow for every method and the truth alike."};
        figure.key = {
            {"false shadow: a lit pixel shadowed (" + std::to_string(m.metrics.falseShadow) + ")",
             spatial::kFalseShadowColour},
            {"false light: a shadowed pixel lit (" + std::to_string(falseLight) + ")",
             spatial::kFalseLightColour},
            {"agrees with the rays (darker where truly shadowed)", {0.6f, 0.6f, 0.6f}},
            {"uncovered: no map covers it, shaded lit (" + std::to_string(m.metrics.uncovered) +
                 ")",
             spatial::kUncoveredColour},
            {"no geometry", spatial::kBackgroundColour}};
        return figure;
    }
    figure.lines = {"The frame shaded with " + m.method +
                    "'s shadows: " + Count(o.receiverPixels, "counted pixels") + ", " +
                    Count(m.metrics.misclassified, "misclassified") + ", " +
                    Count(m.metrics.uncovered, "uncovered") + "; " +
                    Count(o.truthShadowed, "truly shadowed (Embree rays)") + "."};
    figure.key = {{"lit (grey: n·l)", {0.75f, 0.75f, 0.75f}},
                  {"shadowed or facing away (ambient)",
                   {spatial::kAmbient, spatial::kAmbient, spatial::kAmbient}},
                  {"uncovered: no map covers it (" + std::to_string(m.metrics.uncovered) + ")",
                   spatial::kUncoveredColour},
                  {"no geometry", spatial::kSkyColour}};
    return figure;
}

// The figure of a shadow-map image: what the map is, its samples, key and depth scale.
ImageFigure MapFigure(const std::string& title, const std::string& what,
                      const spatial::ShadowMap& map, const spatial::LightSamples& samples) {
    ImageFigure figure;
    figure.title = title;
    figure.lines = {
        what + ", " + std::to_string(map.resolution.width) + "×" +
        std::to_string(map.resolution.height) + " texels: " +
        Count(static_cast<std::int64_t>(samples.lsX.size()), "boundary samples (Algorithm 1's)") +
        ", " +
        Count(static_cast<std::int64_t>(samples.lsRelevant.size()),
              "visible points of the readback") +
        ", as the report's Fig. 2."};
    figure.key = {{"visible point (readback)", spatial::kVisiblePointColour},
                  {"boundary sample", spatial::kBoundarySampleColour},
                  {"empty texel", spatial::kEmptyTexelColour}};
    const spatial::MapDepthRange range = spatial::DepthRangeOf(map);
    if (range.any)
        figure.bar = ColourBar{"depth from the light (scene units): near light, far dark",
                               {{spatial::kNearGrey, spatial::kNearGrey, spatial::kNearGrey},
                                {spatial::kFarGrey, spatial::kFarGrey, spatial::kFarGrey}},
                               range.nearest,
                               range.farthest,
                               false};
    return figure;
}

// A virtual shadow map's pool: its resident pages tiled in the order of their requests.
ImageFigure PoolFigure(const std::string& title, const spatial::MethodOutcome& m) {
    ImageFigure figure = MapFigure(title + " · page pool", m.method, m.buffers.map, {});
    const spatial::PageOutcome& p = *m.pages;
    figure.lines = {
        m.method + "'s physical page pool, " + std::to_string(m.buffers.map.resolution.width) +
        "×" + std::to_string(m.buffers.map.resolution.height) +
        " texels: " + Count(p.resident, "resident pages") + " of " + std::to_string(p.pageTexels) +
        "² texels (pool " + std::to_string(p.poolPages) + ", " + std::to_string(p.requested) +
        " requested, " + std::to_string(p.dropped) +
        " dropped), the most requested first, row by row; each page is its own "
        "light matrix."};
    figure.key = {{"empty texel", spatial::kEmptyTexelColour}};
    return figure;
}

}  // namespace

std::size_t SpatialImageCount(const SpatialRun& run) {
    std::size_t images = 0;
    for (const spatial::LightOutcome& o : run.outcomes)
        for (const spatial::MethodOutcome& m : o.methods)
            images += 2 + (m.cascades.empty() ? 1 : m.buffers.cascadeMaps.size());
    return images;
}

std::vector<SpatialImageFile> WriteSpatialImages(const std::filesystem::path& dir,
                                                 const spatial::Scene& scene, const SpatialRun& run,
                                                 const std::function<void()>& onImage) {
    std::vector<SpatialImageFile> files;
    const spatial::Evaluator& evaluator = *run.evaluator;
    const auto write = [&](std::size_t l, const std::string& method, const std::string& kind,
                           const spatial::Image& image, const ImageFigure& figure) {
        const std::string file =
            scene.name + "_light" + std::to_string(l) + "_" + method + "_" + kind + ".png";
        WriteImageFigure((dir / file).string(), image, figure);
        files.push_back({file, l, method, kind, figure.lines.front()});
        if (onImage) onImage();
    };
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) {
        const spatial::LightOutcome& o = run.outcomes[l];
        const spatial::LightSpace lightSpace(o.light, evaluator.bounds());
        for (const auto& m : o.methods) {
            const std::string title = scene.name + " · light " + std::to_string(l) + ": " +
                                      LightLabel(o.light) + " · " + m.method;
            std::vector<spatial::Cascade> cascades;
            for (const spatial::CascadeOutcome& c : m.cascades) cascades.push_back(c.cascade);
            // A virtual shadow map knows its uncovered pixels (no page serves them).
            const std::vector<std::uint8_t> uncovered =
                m.pages ? m.buffers.uncoveredPixels
                        : spatial::UncoveredPixels(
                              evaluator.frame(), lightSpace, scene.camera, m.buffers.shades,
                              m.buffers.map.matrix, m.buffers.map.resolution, cascades,
                              m.buffers.map.warp ? &*m.buffers.map.warp : nullptr);
            write(l, m.method, "frame",
                  spatial::FrameImage(evaluator.frame(), lightSpace, m.buffers.shades, uncovered),
                  FrameFigure(title + " · frame", o, m, false));
            write(l, m.method, "errors",
                  spatial::MisclassificationImage(evaluator.frame(), lightSpace, m.buffers.shades,
                                                  o.truth, uncovered),
                  FrameFigure(title + " · errors", o, m, true));
            if (m.pages) {
                write(l, m.method, "map", spatial::ShadowMapImage(m.buffers.map, {}),
                      PoolFigure(title, m));
                continue;
            }
            if (m.cascades.empty()) {
                write(l, m.method, "map", spatial::ShadowMapImage(m.buffers.map, o.samples),
                      MapFigure(title + " · shadow map", m.method + "'s shadow map", m.buffers.map,
                                o.samples));
                continue;
            }
            // One image per cascade, with the samples it serves.
            for (std::size_t c = 0; c < m.buffers.cascadeMaps.size(); ++c) {
                const spatial::LightSamples served = spatial::SamplesOfCascade(
                    o.samples, evaluator.readback().wsRelevant, scene.camera, cascades, c);
                const spatial::CascadeOutcome& cascade = m.cascades[c];
                const std::string what = m.method + "'s cascade " + std::to_string(c) + " of " +
                                         std::to_string(m.cascades.size()) + " (depth [" +
                                         Significant(cascade.cascade.zNear, 4) + ", " +
                                         Significant(cascade.cascade.zFar, 4) + "), serving " +
                                         Count(cascade.pixels, "pixels") + ", h " +
                                         Significant(cascade.h, 4) + ")";
                write(l, m.method, "map" + std::to_string(c),
                      spatial::ShadowMapImage(m.buffers.cascadeMaps[c], served),
                      MapFigure(title + " · cascade " + std::to_string(c), what,
                                m.buffers.cascadeMaps[c], served));
            }
        }
    }
    return files;
}

}  // namespace lexel::cases
