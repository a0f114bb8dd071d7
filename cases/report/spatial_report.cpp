#include "lexel/cases/report/spatial_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/images.h"

namespace lexel::cases {

namespace {

nlohmann::json FiniteOrNull(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

std::string LightHeader(std::size_t l, const spatial::LightOutcome& o) {
    std::ostringstream text;
    text << "light " << l << ": " << LightLabel(o.light) << " — " << o.receiverPixels
         << " pixels face it, " << o.truthShadowed << " shadowed (Embree rays), "
         << o.samples.lsX.size() << " boundary samples\n";
    if (o.mapTruthDisagree >= 0)
        text << "  the report's focused 4000² truth map disagrees with the rays on "
             << o.mapTruthDisagree << " pixels ("
             << Fixed(100.0 * o.mapTruthDisagree / std::max<std::int64_t>(1, o.receiverPixels), 3)
             << "%)\n";
    return text.str();
}

std::string IterationLines(const spatial::LightOutcome& o) {
    std::ostringstream text;
    for (const auto& m : o.methods) {
        if (m.hAfterIteration.empty()) continue;
        text << m.method << ": h by Algorithm 1 iteration";
        for (std::size_t i = 0; i < m.hAfterIteration.size(); ++i)
            text << (i ? " → " : " ") << Significant(m.hAfterIteration[i], 6);
        if (m.h < m.hBeforeRefine) text << "; refined " << Significant(m.h, 6);
        text << '\n';
    }
    return text.str();
}

// Per partitioned method, its cascades, one line each: depth interval, map, readback points,
// pixels, h.
std::string CascadeLines(const spatial::LightOutcome& o) {
    std::ostringstream text;
    for (const auto& m : o.methods) {
        if (m.cascades.empty()) continue;
        text << m.method << ": " << m.cascades.size() << " cascades";
        if (m.emptyPartitions) text << " (" << m.emptyPartitions << " empty)";
        text << '\n';
        for (std::size_t c = 0; c < m.cascades.size(); ++c) {
            const spatial::CascadeOutcome& cascade = m.cascades[c];
            text << "  " << c << ": depth [" << Significant(cascade.cascade.zNear, 4) << ", "
                 << Significant(cascade.cascade.zFar, 4) << "), map " << cascade.cascade.map.width
                 << "×" << cascade.cascade.map.height << ", " << cascade.cascade.visiblePoints
                 << " readback points, " << cascade.pixels << " pixels, h "
                 << Significant(cascade.h, 4) << '\n';
        }
    }
    return text.str();
}

std::string ShimmerText(const CameraPathStudy& study, std::size_t light) {
    TextTable table({"method", "shimmer (% of stable pixels per step)"});
    for (std::size_t m = 0; m < study.methods.size(); ++m)
        table.AddRow({study.methods[m], Fixed(study.shimmerPercent[m], 3)});
    std::ostringstream text;
    text << "\ncamera path, light " << light
         << ": pixels whose shadow decision changes between consecutive poses where the rays' "
            "does not\n"
         << table.Render();
    return text.str();
}

std::string CameraPathText(const CameraPathStudy& study, std::size_t light) {
    TextTable table({"pose", "P changed", "median badness kept", "median badness new",
                     "misclassified (hysteresis)", "misclassified (fresh)"});
    for (std::size_t k = 0; k < study.poses.size(); ++k) {
        const PoseOutcome& p = study.poses[k];
        table.AddRow({std::to_string(k), p.changed ? "yes" : "no", Significant(p.medianKept, 5),
                      Significant(p.medianNew, 5), std::to_string(p.misclassifiedHysteresis),
                      std::to_string(p.misclassifiedFresh)});
    }
    std::ostringstream text;
    text << "\ncamera path, light " << light << ": P changed in " << study.Changes() << " of "
         << study.poses.size() << " poses (hysteresis: keep P unless the new median "
         << "badness is below 80% of the kept one)\n"
         << table.Render() << ShimmerText(study, light);
    return text.str();
}

}  // namespace

std::string SpatialRunText(const spatial::Scene&, const SpatialRun& run) {
    std::ostringstream text;
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) {
        const auto& o = run.outcomes[l];
        TextTable table({"method", "misclassified", "false\nshadow", "false\nlight", "uncovered",
                         "mean\nσ1(J⁻¹)", "max\nσ1(J⁻¹)", "storage\nfactor", "h\n(eq. 6)", "ms"});
        for (const auto& m : o.methods)
            table.AddRow({m.method, std::to_string(m.misclassified), std::to_string(m.falseShadow),
                          std::to_string(m.misclassified - m.falseShadow),
                          std::to_string(m.uncovered), Significant(m.footprintMean, 4),
                          Significant(m.footprintMax, 4), Significant(m.storageFactor, 4),
                          Significant(m.h, 6), Fixed(m.ms, 3)});
        text << (l ? "\n" : "") << LightHeader(l, o) << table.Render() << IterationLines(o)
             << CascadeLines(o);
    }
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l)
        text << CameraPathText(run.cameraPath[l], l);
    return text.str();
}

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
            if (!m.hAfterIteration.empty()) method["h_after_iteration"] = m.hAfterIteration;
            for (const spatial::CascadeOutcome& c : m.cascades)
                method["cascades"].push_back({{"z_near", c.cascade.zNear},
                                              {"z_far", FiniteOrNull(c.cascade.zFar)},
                                              {"width", c.cascade.map.width},
                                              {"height", c.cascade.map.height},
                                              {"visible_points", c.cascade.visiblePoints},
                                              {"pixels", c.pixels},
                                              {"h", FiniteOrNull(c.h)}});
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
           "max_footprint,maps,max_perspective_aliasing,storage_factor\n";
    for (std::size_t l = 0; l < run.outcomes.size(); ++l)
        for (const auto& m : run.outcomes[l].methods)
            csv << l << ',' << m.method << ',' << m.misclassified << ',' << m.falseShadow << ','
                << m.misclassified - m.falseShadow << ',' << CsvNumber(m.h) << ','
                << CsvNumber(m.ms) << ',' << m.uncovered << ',' << CsvNumber(m.footprintMean) << ','
                << CsvNumber(m.footprintMax) << ',' << std::max<std::size_t>(1, m.cascades.size())
                << ',' << CsvNumber(m.perspectiveMax) << ',' << CsvNumber(m.storageFactor) << '\n';
    return csv.str();
}

int WriteSpatialImages(const std::filesystem::path& dir, const spatial::Scene& scene,
                       const SpatialRun& run) {
    int images = 0;
    const spatial::Evaluator& evaluator = *run.evaluator;
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) {
        const spatial::LightOutcome& o = run.outcomes[l];
        const spatial::LightSpace lightSpace(o.light, evaluator.bounds());
        for (const auto& m : o.methods) {
            const std::string base =
                (dir / (scene.name + "_light" + std::to_string(l) + "_" + m.method)).string();
            spatial::WriteImage(base + "_frame.png",
                                spatial::FrameImage(evaluator.frame(), lightSpace, m.shades));
            spatial::WriteImage(
                base + "_errors.png",
                spatial::MisclassificationImage(evaluator.frame(), lightSpace, m.shades, o.truth));
            images += 2;
            if (m.cascades.empty()) {
                spatial::WriteImage(base + "_map.png", spatial::ShadowMapImage(m.map, o.samples));
                ++images;
                continue;
            }
            // One image per cascade, with the samples it serves.
            std::vector<spatial::Cascade> cascades;
            for (const spatial::CascadeOutcome& c : m.cascades) cascades.push_back(c.cascade);
            for (std::size_t c = 0; c < m.cascadeMaps.size(); ++c) {
                const spatial::LightSamples served = spatial::SamplesOfCascade(
                    o.samples, evaluator.readback().wsRelevant, scene.camera, cascades, c);
                spatial::WriteImage(base + "_map" + std::to_string(c) + ".png",
                                    spatial::ShadowMapImage(m.cascadeMaps[c], served));
                ++images;
            }
        }
    }
    return images;
}

}  // namespace lexel::cases
