#include "lexel/cases/report/spatial_report.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "lexel/cases/report/figures.h"
#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/images.h"
#include "lexel/spatial/harness/warped_methods.h"

namespace lexel::cases {

std::vector<std::string> LightHeaderLines(std::size_t l, const spatial::LightOutcome& o) {
    std::vector<std::string> lines = {
        "light " + std::to_string(l) + ": " + LightLabel(o.light) + " — " +
        std::to_string(o.receiverPixels) + " pixels face it, " + std::to_string(o.truthShadowed) +
        " shadowed (Embree rays), " + std::to_string(o.samples.lsX.size()) + " boundary samples"};
    if (o.mapTruthDisagree >= 0)
        lines.push_back(
            "the report's focused 4000² truth map disagrees with the rays on " +
            std::to_string(o.mapTruthDisagree) +
            (o.mapTruthDisagree == 1 ? " pixel (" : " pixels (") +
            Fixed(100.0 * o.mapTruthDisagree / std::max<std::int64_t>(1, o.receiverPixels), 3) +
            "%)");
    return lines;
}

// "mean ± 95% half-width" of a phase mean (sub_texel_phase.h): 1.96 standard errors.
std::string PhaseMeanText(double mean, double standardError) {
    return Fixed(mean, 1) + " ± " + Fixed(1.96 * standardError, 1);
}

TextTable SpatialMethodTable(const spatial::LightOutcome& o) {
    std::vector<std::string> header = {
        "method",        "misclassified", "false\nshadow",   "false\nlight", "uncovered",
        "mean\nσ1(J⁻¹)", "max\nσ1(J⁻¹)",  "storage\nfactor", "h\n(eq. 6)",   "ms"};
    // Over several phases: the mean and its 95% interval beside phase 0's count.
    const bool phased = o.phases > 1;
    if (phased)
        header.insert(header.begin() + 2,
                      "mean over\n" + std::to_string(o.phases) + " phases\n(95% CI)");
    TextTable table(header);
    for (const auto& m : o.methods) {
        std::vector<std::string> row = {m.method,
                                        std::to_string(m.misclassified),
                                        std::to_string(m.falseShadow),
                                        std::to_string(m.misclassified - m.falseShadow),
                                        std::to_string(m.uncovered),
                                        Significant(m.footprintMean, 4),
                                        Significant(m.footprintMax, 4),
                                        Significant(m.storageFactor, 4),
                                        Significant(m.h, 6),
                                        Fixed(m.ms, 3)};
        if (phased)
            row.insert(row.begin() + 2, PhaseMeanText(m.misclassifiedMean, m.misclassifiedError));
        table.AddRow(row);
    }
    return table;
}

std::vector<std::string> IterationLines(const spatial::LightOutcome& o) {
    std::vector<std::string> lines;
    for (const auto& m : o.methods) {
        if (m.trace.hAfterIteration.empty()) continue;
        std::string line = m.method + ": h by Algorithm 1 iteration";
        for (std::size_t i = 0; i < m.trace.hAfterIteration.size(); ++i)
            line += (i ? " → " : " ") + Significant(m.trace.hAfterIteration[i], 6);
        if (m.h < m.trace.hBeforeRefine) line += "; refined " + Significant(m.h, 6);
        lines.push_back(line);
    }
    return lines;
}

std::optional<TextTable> CascadeTable(const spatial::LightOutcome& o) {
    TextTable table({"method", "cascade", "depth\nfrom", "depth\nto", "map", "readback\npoints",
                     "pixels", "h"});
    bool any = false;
    for (const auto& m : o.methods)
        for (std::size_t c = 0; c < m.cascades.size(); ++c) {
            const spatial::CascadeOutcome& cascade = m.cascades[c];
            table.AddRow({c == 0 ? m.method : "", std::to_string(c),
                          Significant(cascade.cascade.zNear, 4),
                          Significant(cascade.cascade.zFar, 4),
                          std::to_string(cascade.cascade.map.width) + "×" +
                              std::to_string(cascade.cascade.map.height),
                          std::to_string(cascade.cascade.visiblePoints),
                          std::to_string(cascade.pixels), Significant(cascade.h, 4)});
            any = true;
        }
    if (!any) return std::nullopt;
    return table;
}

std::optional<TextTable> PageTable(const spatial::LightOutcome& o) {
    TextTable table({"method", "page", "pool\npages", "pages\nrequested", "pages\nresident",
                     "pages\ndropped", "LOD\nbias"});
    bool any = false;
    for (const auto& m : o.methods) {
        if (!m.pages) continue;
        const spatial::PageOutcome& p = *m.pages;
        table.AddRow({m.method, std::to_string(p.pageTexels) + "²", std::to_string(p.poolPages),
                      std::to_string(p.requested), std::to_string(p.resident),
                      std::to_string(p.dropped), Fixed(p.lodBias, 3)});
        any = true;
    }
    if (!any) return std::nullopt;
    return table;
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
        for (const auto& m : o.methods) {
            nlohmann::json method = {{"method", m.method},
                                     {"misclassified", m.misclassified},
                                     {"false_shadow", m.falseShadow},
                                     {"false_light", m.misclassified - m.falseShadow},
                                     {"uncovered", m.uncovered},
                                     {"mean_footprint", m.footprintMean},
                                     {"max_footprint", FiniteOrNull(m.footprintMax)},
                                     {"max_perspective_aliasing", m.perspectiveMax},
                                     {"p99_perspective_aliasing", m.perspectiveP99},
                                     {"texels", m.texels},
                                     {"storage_factor", m.storageFactor},
                                     {"storage_factor_p99", m.storageFactorP99},
                                     {"h", FiniteOrNull(m.h)},
                                     {"ms", m.ms}};
            if (o.phases > 1) {
                method["phases"] = o.phases;
                method["misclassified_mean"] = m.misclassifiedMean;
                method["misclassified_standard_error"] = m.misclassifiedError;
                method["false_shadow_mean"] = m.falseShadowMean;
            }
            if (!m.trace.hAfterIteration.empty())
                method["h_after_iteration"] = m.trace.hAfterIteration;
            const spatial::Resolution map =
                m.pages ? spatial::Resolution{m.pages->pageTexels, m.pages->pageTexels}
                        : scene.shadowMap;
            method["map_kind"] = MapKind(m);
            method["clip_from_world"] =
                RowMajor(run.evaluator->ClipFromWorldOf(o.light, m.matrix, map));
            for (const spatial::CascadeOutcome& c : m.cascades)
                method["cascades"].push_back(
                    {{"clip_from_world", RowMajor(run.evaluator->ClipFromWorldOf(
                                             o.light, c.cascade.matrix, c.cascade.map))},
                     {"z_near", c.cascade.zNear},
                     {"z_far", FiniteOrNull(c.cascade.zFar)},
                     {"width", c.cascade.map.width},
                     {"height", c.cascade.map.height},
                     {"visible_points", c.cascade.visiblePoints},
                     {"pixels", c.pixels},
                     {"h", FiniteOrNull(c.h)}});
            if (m.pages)
                method["pages"] = {
                    {"page_texels", m.pages->pageTexels}, {"pool_pages", m.pages->poolPages},
                    {"requested", m.pages->requested},    {"resident", m.pages->resident},
                    {"dropped", m.pages->dropped},        {"lod_bias", m.pages->lodBias}};
            light["methods"].push_back(method);
        }
        doc["lights"].push_back(light);
    }
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l) {
        const CameraPathStudy& study = run.cameraPath[l];
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
        doc["camera_path"].push_back({{"light", l},
                                      {"poses", poses.size()},
                                      {"changes", study.Changes()},
                                      {"frames", poses},
                                      {"shimmer_percent", shimmer}});
    }
    return doc;
}

std::string SpatialRunCsv(const SpatialRun& run) {
    std::ostringstream csv;
    csv << "light,method,misclassified,false_shadow,false_light,h,ms,uncovered,mean_footprint,"
           "max_footprint,maps,max_perspective_aliasing,storage_factor,pages_requested,"
           "pages_resident,pages_dropped";
    // Over several phases (every light has the case's): the means and the standard error.
    const bool phased = !run.outcomes.empty() && run.outcomes.front().phases > 1;
    if (phased) csv << ",phases,misclassified_mean,misclassified_standard_error,false_shadow_mean";
    csv << '\n';
    for (std::size_t l = 0; l < run.outcomes.size(); ++l)
        for (const auto& m : run.outcomes[l].methods) {
            // A virtual shadow map's maps are its resident pages.
            const std::size_t maps = m.pages ? static_cast<std::size_t>(m.pages->resident)
                                             : std::max<std::size_t>(1, m.cascades.size());
            csv << l << ',' << m.method << ',' << m.misclassified << ',' << m.falseShadow << ','
                << m.misclassified - m.falseShadow << ',' << CsvNumber(m.h) << ','
                << CsvNumber(m.ms) << ',' << m.uncovered << ',' << CsvNumber(m.footprintMean) << ','
                << CsvNumber(m.footprintMax) << ',' << maps << ',' << CsvNumber(m.perspectiveMax)
                << ',' << CsvNumber(m.storageFactor) << ',';
            if (m.pages)
                csv << m.pages->requested << ',' << m.pages->resident << ',' << m.pages->dropped;
            else
                csv << ",,";
            if (phased)
                csv << ',' << run.outcomes[l].phases << ',' << CsvNumber(m.misclassifiedMean) << ','
                    << CsvNumber(m.misclassifiedError) << ',' << CsvNumber(m.falseShadowMean);
            csv << '\n';
        }
    return csv.str();
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
    const std::int64_t falseLight = m.misclassified - m.falseShadow;
    if (errors) {
        figure.lines = {
            "Where " + m.method + "'s shadow decision differs from exact shadow rays: " +
                std::to_string(m.misclassified) + " of " +
                Count(o.receiverPixels, "counted pixels") + " misclassified (" +
                std::to_string(m.falseShadow) + " false shadow, " + std::to_string(falseLight) +
                " false light); " + Count(m.uncovered, "uncovered") + ".",
            "Counted pixels: visible and facing the light; those facing away are in "
            "shadow for every method and the truth alike."};
        figure.key = {
            {"false shadow: a lit pixel shadowed (" + std::to_string(m.falseShadow) + ")",
             spatial::kFalseShadowColour},
            {"false light: a shadowed pixel lit (" + std::to_string(falseLight) + ")",
             spatial::kFalseLightColour},
            {"agrees with the rays (darker where truly shadowed)", {0.6f, 0.6f, 0.6f}},
            {"uncovered: no map covers it, shaded lit (" + std::to_string(m.uncovered) + ")",
             spatial::kUncoveredColour},
            {"no geometry", spatial::kBackgroundColour}};
        return figure;
    }
    figure.lines = {"The frame shaded with " + m.method +
                    "'s shadows: " + Count(o.receiverPixels, "counted pixels") + ", " +
                    Count(m.misclassified, "misclassified") + ", " +
                    Count(m.uncovered, "uncovered") + "; " +
                    Count(o.truthShadowed, "truly shadowed (Embree rays)") + "."};
    figure.key = {{"lit (grey: n·l)", {0.75f, 0.75f, 0.75f}},
                  {"shadowed or facing away (ambient)",
                   {spatial::kAmbient, spatial::kAmbient, spatial::kAmbient}},
                  {"uncovered: no map covers it (" + std::to_string(m.uncovered) + ")",
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
