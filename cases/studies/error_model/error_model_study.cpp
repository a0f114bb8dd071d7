// The error model checked per boundary sample (error_model_study.h).
#include "lexel/cases/studies/error_model/error_model_study.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/error_model.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::cases {

namespace {

using spatial::Shade;

// The readback's shades under the standard (focused) map: the decisions the boundary samples were
// found with (Evaluator::Evaluate's step 1), for their edge normals.
std::vector<Shade> StandardShades(const spatial::Evaluator& evaluator,
                                  const spatial::LightSpace& lightSpace) {
    const spatial::Readback& readback = evaluator.readback();
    const spatial::BaselineContext context =
        spatial::MakeBaselineContext(evaluator.scene(), lightSpace, evaluator.bounds(),
                                     readback.wsRelevant, readback.wsRelevantHull);
    const spatial::ShadowMap map = evaluator.backend().RenderShadowMap(
        lightSpace, spatial::FocusedLightMatrix(context), evaluator.scene().shadowMap);
    return evaluator.backend().ShadePixels(readback.buffer, lightSpace, map);
}

// Whether the map of `matrix` (scene.shadowMap texels) covers a frame pixel's point: in front of
// its plane and inside its texels (ShadePoint shades the others lit).
bool MapCovers(const spatial::LightSpace& lightSpace, const spatial::LightMatrix& matrix,
               spatial::Resolution map, const glm::dvec3& wsPoint) {
    const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
    if (!spatial::InFront(matrix.p4, lsX)) return false;
    const glm::dvec2 u = matrix.Map(lsX);
    return u.x >= 0.0 && u.y >= 0.0 && u.x < map.width && u.y < map.height;
}

// Per frame pixel, summed over the phases: how often it is a misclassified counted pixel the
// phase's map covers, how often one it does not cover (a shifted tight map loses up to half a
// texel at its border: not the model's band), and how often the map shadows it where the rays
// light it (false shadow, covered or not); and the unshifted map's count.
struct PixelErrors {
    std::vector<std::uint16_t> wrong, uncovered, falseShadow;
    std::int64_t singlePhase = 0;
};

PixelErrors WrongPerPixel(const spatial::Evaluator& evaluator, const spatial::Light& light,
                          const spatial::LightMatrix& matrix, std::span<const std::uint8_t> truth,
                          int phases) {
    const spatial::LightSpace lightSpace(light, evaluator.bounds());
    const spatial::Resolution map = evaluator.scene().shadowMap;
    PixelErrors e;
    e.wrong.assign(truth.size(), 0);
    e.uncovered.assign(truth.size(), 0);
    e.falseShadow.assign(truth.size(), 0);
    const std::vector<glm::dvec2> shifts = spatial::SubTexelPhases(phases);
    for (std::size_t k = 0; k < shifts.size(); ++k) {
        const spatial::LightMatrix shifted = matrix.Shifted(shifts[k]);
        const std::vector<Shade> shades = evaluator.ShadeFrame(light, shifted);
        for (std::size_t p = 0; p < shades.size(); ++p) {
            if (shades[p] != Shade::kLit && shades[p] != Shade::kShadowed) continue;
            if ((shades[p] == Shade::kShadowed) == static_cast<bool>(truth[p])) continue;
            e.singlePhase += k == 0;  // phase 0 is the unshifted map (SubTexelPhases)
            e.falseShadow[p] += shades[p] == Shade::kShadowed;
            if (MapCovers(lightSpace, shifted, map, evaluator.frame().wsPosition[p]))
                ++e.wrong[p];
            else
                ++e.uncovered[p];
        }
    }
    return e;
}

// Whether a frame pixel shows the scene's floor plane (Scene::floorPlane; none: no pixel): its
// point on the plane within kFloorTolerance world units per unit of distance from the origin, its
// normal the plane's within kFloorCosine.
constexpr double kFloorTolerance = 1e-6;  // world units per world unit (double-precision points)
constexpr double kFloorCosine = 1.0 - 1e-9;
std::vector<std::uint8_t> FloorPixels(const spatial::Scene& scene,
                                      const spatial::CameraBuffer& frame) {
    std::vector<std::uint8_t> floor(frame.wsPosition.size(), 0);
    if (!scene.floorPlane) return floor;
    const glm::dvec3 n(*scene.floorPlane);
    const double d = scene.floorPlane->w;
    for (std::size_t p = 0; p < floor.size(); ++p) {
        if (!frame.Covered(p)) continue;
        const glm::dvec3& x = frame.wsPosition[p];
        floor[p] = std::abs(glm::dot(n, x) + d) <= kFloorTolerance * (1.0 + glm::length(x)) &&
                   std::abs(glm::dot(n, frame.wsNormal[p])) >= kFloorCosine;
    }
    return floor;
}

struct LightResult {
    std::vector<ErrorModelSample> samples;
    std::vector<ErrorModelTotals> totals;
    std::size_t sampleCount = 0;
};

// The owner of each frame pixel: the nearest sample within its radius (-1: none).
std::vector<std::int32_t> AssignPixels(spatial::Resolution frame, spatial::Resolution readback,
                                       const std::vector<ErrorModelSample>& samples,
                                       const std::vector<double>& radiusReadback) {
    const double sx = static_cast<double>(frame.width) / readback.width;
    const double sy = static_cast<double>(frame.height) / readback.height;
    const double scale = std::max(sx, sy);
    std::vector<std::int32_t> owner(frame.Count(), -1);
    std::vector<float> best(frame.Count(), std::numeric_limits<float>::infinity());
    for (std::size_t s = 0; s < samples.size(); ++s) {
        const std::uint32_t px = samples[s].pixel % static_cast<std::uint32_t>(readback.width);
        const std::uint32_t py = samples[s].pixel / static_cast<std::uint32_t>(readback.width);
        const glm::dvec2 centre((px + 0.5) * sx, (py + 0.5) * sy);
        const double radius = radiusReadback[s] * scale;
        const int x0 = std::max(0, static_cast<int>(std::floor(centre.x - radius)));
        const int x1 = std::min(frame.width - 1, static_cast<int>(std::ceil(centre.x + radius)));
        const int y0 = std::max(0, static_cast<int>(std::floor(centre.y - radius)));
        const int y1 = std::min(frame.height - 1, static_cast<int>(std::ceil(centre.y + radius)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const double d = glm::length(glm::dvec2(x + 0.5, y + 0.5) - centre);
                const std::size_t p = static_cast<std::size_t>(y) * frame.width + x;
                if (d > radius || !(d < best[p])) continue;
                best[p] = static_cast<float>(d);
                owner[p] = static_cast<std::int32_t>(s);
            }
        }
    }
    return owner;
}

LightResult StudyLight(const spatial::Evaluator& evaluator, const spatial::Light& light,
                       std::size_t lightIndex, const std::vector<std::string>& methods,
                       int phaseCount) {
    spatial::EvaluationOptions options;
    options.methods = methods;
    options.mapTruth = false;
    const spatial::LightOutcome outcome = evaluator.Evaluate(light, options);
    // The boundary samples the model is about: no thin-shadow contacts (samples.h).
    const spatial::LightSamples ls = spatial::PublishedSamples(outcome.samples);
    const spatial::LightSpace lightSpace(light, evaluator.bounds());
    const std::vector<Shade> standard = StandardShades(evaluator, lightSpace);
    const std::vector<std::uint8_t> truth = evaluator.TruthShadows(light);
    const spatial::Resolution readback = evaluator.readback().buffer.resolution;
    const spatial::Resolution frame = evaluator.frame().resolution;
    const double phases = phaseCount;
    const std::vector<std::uint8_t> floor = FloorPixels(evaluator.scene(), evaluator.frame());
    LightResult r;
    r.sampleCount = ls.lsX.size();
    for (std::size_t m = 0; m < methods.size(); ++m) {
        const spatial::LightMatrix& matrix = outcome.methods[m].matrix;
        std::vector<ErrorModelSample> samples(ls.lsX.size());
        std::vector<double> radius(ls.lsX.size());
        for (std::size_t s = 0; s < samples.size(); ++s) {
            ErrorModelSample& e = samples[s];
            e.light = lightIndex;
            e.method = m;
            e.sample = s;
            e.pixel = ls.pixel[s];
            e.normal = spatial::EdgeNormalAt(readback, standard, e.pixel);
            glm::dvec2 row1, row2;
            spatial::SampleJacobian(matrix, ls.lsX[s], ls.dXdx1[s], ls.dXdx2[s], &row1, &row2);
            const double length = spatial::EdgeLengthPerBoundaryPixel(e.normal);
            e.predicted = spatial::FramePixelsFromReadbackArea(
                spatial::ExpectedBandWidth(e.normal, row1, row2) * length, readback, frame);
            e.predictedIsotropic = spatial::FramePixelsFromReadbackArea(
                spatial::ExpectedBandWidthIsotropic(e.normal, row1, row2) * length, readback,
                frame);
            const double g = glm::length(spatial::EdgeNormalInTexels(e.normal, row1, row2));
            e.inRange = std::isfinite(g) && 2.0 + 0.5 * g <= kMaxAssignRadius;
            radius[s] = e.inRange ? 2.0 + 0.5 * g : kMaxAssignRadius;
        }
        const PixelErrors errors = WrongPerPixel(evaluator, light, matrix, truth, phaseCount);
        const std::vector<std::int32_t> owner = AssignPixels(frame, readback, samples, radius);
        ErrorModelTotals t;
        t.singlePhase = static_cast<double>(errors.singlePhase);
        for (std::size_t p = 0; p < errors.wrong.size(); ++p) {
            const double all = (errors.wrong[p] + errors.uncovered[p]) / phases;
            if (all == 0.0) continue;
            const double w = errors.wrong[p] / phases;
            t.misclassified += all;
            t.uncovered += errors.uncovered[p] / phases;
            t.falseShadow += errors.falseShadow[p] / phases;
            if (floor[p]) t.onFloor += all;
            if (!floor[p]) t.falseShadowOffFloor += errors.falseShadow[p] / phases;
            if (owner[p] < 0 || w == 0.0) continue;
            t.explained += w;
            samples[static_cast<std::size_t>(owner[p])].measured += w;
        }
        r.totals.push_back(t);
        r.samples.insert(r.samples.end(), samples.begin(), samples.end());
    }
    return r;
}

}  // namespace

ErrorModelTotals& ErrorModelTotals::operator+=(const ErrorModelTotals& o) {
    misclassified += o.misclassified;
    explained += o.explained;
    singlePhase += o.singlePhase;
    uncovered += o.uncovered;
    falseShadow += o.falseShadow;
    onFloor += o.onFloor;
    falseShadowOffFloor += o.falseShadowOffFloor;
    return *this;
}

ErrorModelStudy RunErrorModelStudy(const spatial::Scene& scene,
                                   const std::vector<std::string>& methods,
                                   const std::vector<spatial::Light>& lights, int phases,
                                   BackendKind backendKind,
                                   const std::function<void()>& onLightDone) {
    if (phases < 1 || phases > spatial::kMaxPhases)
        throw std::invalid_argument("RunErrorModelStudy: phases must be in [1, kMaxPhases]");
    for (const std::string& m : methods)
        if (spatial::IsPartitionedMethod(m) || spatial::IsVirtualMethod(m) ||
            spatial::IsWarpedMethod(m))
            throw std::invalid_argument("RunErrorModelStudy: " + m + " is not a single-map method");
    const Stopwatch timer;
    const auto backend = MakeRenderBackend(backendKind, scene.geometry);
    const std::unique_ptr<spatial::Evaluator> evaluator = MakeEvaluator(scene, *backend);
    ErrorModelStudy study;
    study.caseName = scene.name;
    study.lights = lights;
    study.methods = methods;
    study.phases = phases;
    study.readback = evaluator->readback().buffer.resolution;
    study.frame = evaluator->frame().resolution;
    std::vector<LightResult> results(lights.size());
    tbb::parallel_for(std::size_t(0), lights.size(), [&](std::size_t l) {
        try {
            results[l] = StudyLight(*evaluator, lights[l], l, methods, phases);
        } catch (const DomainError& e) {
            const std::string light = "light " + std::to_string(l) + " " + LightLabel(lights[l]);
            throw InputError(SpatialErrorField(e, light) + ": " + e.what());
        }
        if (onLightDone) onLightDone();
    });
    study.totals.assign(methods.size(), {});
    for (const LightResult& r : results) {
        study.samplesPerLight.push_back(r.sampleCount);
        study.samples.insert(study.samples.end(), r.samples.begin(), r.samples.end());
        for (std::size_t m = 0; m < methods.size(); ++m) study.totals[m] += r.totals[m];
    }
    study.seconds = timer.Ms() / 1000.0;
    return study;
}

}  // namespace lexel::cases
