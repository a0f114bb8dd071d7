#include "lexel/cases/run/sweep.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "lexel/cases/load/memory_budget.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/camera_path.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/memory_estimate.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/sub_texel_phase.h"

namespace lexel::cases {

using spatial::Light;

std::string LightLabel(const Light& light) {
    const glm::dvec3 v = light.type == Light::Type::kPoint ? light.position : light.direction;
    // A light's coordinates are finite (the loader's check): "%.4g" each, as the reports'
    // Significant(x, 4) prints them.
    char text[128];
    std::snprintf(text, sizeof text, "%s (%.4g, %.4g, %.4g)",
                  light.type == Light::Type::kPoint ? "point" : "directional", v.x, v.y, v.z);
    return text;
}

std::vector<Light> SweepLightsOf(const spatial::Scene& scene, int lights,
                                 std::optional<Light::Type> type) {
    if (!scene.lightSweep)
        throw InputError("/light_sweep: the case has none; add {\"count\", \"seed\", \"radius\"}");
    spatial::LightSweep sweep = *scene.lightSweep;
    if (lights > 0) sweep.count = lights;
    if (type) sweep.type = *type;
    return spatial::SweepLights(sweep, scene.geometry.ComputeBounds().Center());
}

namespace {

// What one light's evaluation and the frames shared by all need (with shimmer poses, one frame
// per pose beside the case camera's, and the shades kept).
spatial::EvaluationMemory SweepMemory(const spatial::Scene& scene, std::size_t methods,
                                      int shimmerPoses) {
    spatial::EvaluationSizes sizes;
    sizes.frame = scene.camera.resolution;
    sizes.readback = scene.readback;
    sizes.shadowMap = scene.shadowMap;
    sizes.triangles = scene.geometry.triangles.size();
    sizes.methods = static_cast<int>(methods);
    sizes.keepBuffers = shimmerPoses > 0;  // the poses' shades
    spatial::EvaluationMemory memory = spatial::EstimateEvaluationMemory(sizes);
    memory.shared *= 1.0 + shimmerPoses;
    return memory;
}

// Lights evaluated at once: as many as there are, unless their buffers together would exceed the
// memory budget (memory_budget.h) beside the shared frames; at least one (the loader refused
// cases where one does not fit without poses, SweepMemoryExcess those that do not with them).
int LightsInFlight(const spatial::Scene& scene, std::size_t methods, int shimmerPoses) {
    const spatial::EvaluationMemory memory = SweepMemory(scene, methods, shimmerPoses);
    const double fit = std::floor((kMemoryBudgetBytes - memory.shared) / memory.perLight);
    return static_cast<int>(std::clamp(fit, 1.0, 1e9));
}

// Per method of `methods`, the shimmer of `light` along `poses` (ShimmerAlong); NaN for a case's
// own matrices (Scene::methods), which are given for the case camera alone and do not refit along
// the path (lexel run's study leaves them out likewise: CameraPathMethods). Empty without poses.
std::vector<double> LightShimmer(const PathPoses& poses, const spatial::Scene& scene,
                                 const std::vector<std::string>& methods,
                                 spatial::EvaluationOptions options, const Light& light,
                                 const std::string& lightField) {
    if (poses.evaluators.empty()) return {};
    options.methods = CameraPathMethods(scene, methods);
    const std::vector<double> along = ShimmerAlong(poses, light, options, lightField);
    std::vector<double> shimmer(methods.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < along.size(); ++k)
        shimmer[std::find(methods.begin(), methods.end(), options.methods[k]) - methods.begin()] =
            along[k];
    return shimmer;
}

// The poses the shimmer is measured over: none for shimmerPoses 0.
PathPoses ShimmerPoses(const spatial::Scene& scene, const spatial::RenderBackend& backend,
                       int shimmerPoses) {
    if (shimmerPoses == 0) return {};
    if (shimmerPoses < 2 || shimmerPoses > kMaxShimmerPoses ||
        static_cast<std::size_t>(shimmerPoses) > scene.cameraPath.size())
        throw InputError("/camera_path: the shimmer is measured along 2 to " +
                         std::to_string(kMaxShimmerPoses) + " of its poses; asked for " +
                         std::to_string(shimmerPoses) + ", the case has " +
                         std::to_string(scene.cameraPath.size()));
    return MakePathPoses(scene, backend, static_cast<std::size_t>(shimmerPoses));
}

}  // namespace

std::string SweepMemoryExcess(const spatial::Scene& scene, std::size_t methods, int shimmerPoses) {
    return MemoryBudgetExcess(SweepMemory(scene, methods, shimmerPoses).Total(1),
                              std::to_string(shimmerPoses) + " camera_path frames besides the " +
                                  "camera's, one light in flight");
}

SweepResult RunSweep(const spatial::Scene& scene, const std::vector<std::string>& methods,
                     const std::vector<Light>& lights, const SweepLightDone& onLightDone,
                     BackendKind backendKind, const std::vector<std::size_t>& indices,
                     int shimmerPoses) {
    const Stopwatch timer;
    const auto backend = MakeRenderBackend(backendKind, scene.geometry);
    const std::unique_ptr<spatial::Evaluator> evaluator = MakeEvaluator(scene, *backend);
    // No poses to render when no light is left to evaluate (a resumed sweep that had finished).
    const PathPoses poses = ShimmerPoses(scene, *backend, lights.empty() ? 0 : shimmerPoses);
    SweepResult r;
    r.caseName = scene.name;
    r.methods = methods;
    r.lights = lights;
    r.indices = indices;
    if (r.indices.size() != lights.size()) {
        r.indices.resize(lights.size());
        for (std::size_t l = 0; l < lights.size(); ++l) r.indices[l] = l;
    }
    r.cells.assign(lights.size(), std::vector<SweepCell>(methods.size()));
    r.receiverPixels.assign(lights.size(), 0);
    r.phases = scene.phases;
    r.maxPhases = spatial::MostPhases(scene.phases, scene.maxPhases);
    r.shimmerPoses = shimmerPoses;
    spatial::EvaluationOptions options;
    options.methods = methods;
    options.phases = scene.phases;
    options.maxPhases = scene.maxPhases;
    // Lights in batches of what the memory budget holds at once; with the usual sizes one batch of
    // all lights, evaluated in parallel as they come.
    const auto batch =
        static_cast<std::size_t>(LightsInFlight(scene, methods.size(), shimmerPoses));
    for (std::size_t first = 0; first < lights.size(); first += batch) {
        const std::size_t last = std::min(lights.size(), first + batch);
        tbb::parallel_for(first, last, [&](std::size_t l) {
            spatial::LightOutcome outcome;
            // The case's matrices for light l: its matrix of the whole sweep's light r.indices[l].
            spatial::EvaluationOptions lightOptions = options;
            lightOptions.given =
                spatial::GivenMatricesOf(scene.methods, methods, true, r.indices[l]);
            const std::string light =
                "light " + std::to_string(r.indices[l]) + " " + LightLabel(lights[l]);
            try {
                outcome = evaluator->Evaluate(lights[l], lightOptions);
            } catch (const DomainError& e) {
                throw InputError(SpatialErrorField(e, light) + ": " + e.what());
            }
            const std::vector<double> shimmer =
                LightShimmer(poses, scene, methods, options, lights[l], light);
            for (std::size_t m = 0; m < methods.size(); ++m) {
                const spatial::MethodOutcome& o = outcome.methods[m];
                r.cells[l][m] = {o.metrics.misclassified,
                                 o.metrics.h,
                                 o.metrics.ms,
                                 o.metrics.hGrazing,
                                 o.trace.winner,
                                 o.metrics.footprintMean,
                                 o.metrics.footprintMax,
                                 o.metrics.uncovered,
                                 std::max(1, static_cast<int>(o.cascades.size())),
                                 o.emptyPartitions,
                                 o.metrics.storageFactor};
                r.cells[l][m].misclassifiedMean = o.metrics.misclassifiedMean;
                r.cells[l][m].misclassifiedError = o.metrics.misclassifiedError;
                r.cells[l][m].phases = o.metrics.phases;
                r.cells[l][m].e = o.metrics.e;
                r.cells[l][m].storageFactorP99 = o.metrics.storageFactorP99;
                if (!shimmer.empty()) r.cells[l][m].shimmer = shimmer[m];
                if (o.pages) {
                    SweepCell& c = r.cells[l][m];
                    c.cascades = static_cast<int>(o.pages->resident);
                    c.pagesRequested = o.pages->requested;
                    c.pagesResident = o.pages->resident;
                    c.pagesDropped = o.pages->dropped;
                    c.lodBias = o.pages->lodBias;
                }
            }
            r.receiverPixels[l] = outcome.receiverPixels;
            if (onLightDone) onLightDone(l, r.cells[l], r.receiverPixels[l]);
        });
    }
    r.seconds = timer.Ms() / 1000.0;
    return r;
}

}  // namespace lexel::cases
