// `lexel sweep`: the experiment of Chong & Gortler's report §3 over a case's light sweep — per
// light and method the misclassified pixels, h and time, the data of the report's Table 1.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lexel/cases/run/backend.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// The most camera_path poses a sweep's shimmer is measured over: each pose keeps its own frame
// and evaluator in memory for the whole sweep (EvaluationMemory::shared apiece).
inline constexpr int kMaxShimmerPoses = 16;

// Per light and method, what a sweep keeps (matrices and buffers are dropped).
struct SweepCell {
    std::int64_t misclassified = 0;
    double h = 0.0;
    double ms = 0.0;
    double hGrazing = 0.0;  // the part of h from grazing samples (spatial/harness/evaluation.h)
    std::string winner;     // optimal, optimal-refined: the start that won
    double footprintMean = 0.0, footprintMax = 0.0;  // σ₁(J⁻¹) over counted pixels
    std::int64_t uncovered = 0;                      // counted pixels no map covers
    int cascades = 1;  // maps (partitioned methods: k; virtual shadow maps: resident pages)
    int emptyPartitions = 0;
    // Lloyd 2006's storage factor measured (MethodOutcome::storageFactor): texels for a worst
    // perspective aliasing of 1 over the frame's pixels.
    double storageFactor = 0.0;
    double storageFactorP99 = 0.0;  // the same for the 99th percentile of the pixels' aliasing
    // Virtual shadow maps (vsm*): pages requested, resident and dropped, and the LOD bias; -1
    // for the other methods.
    std::int64_t pagesRequested = -1, pagesResident = -1, pagesDropped = -1;
    double lodBias = 0.0;
    // Over the scene's sub-texel phases (MethodOutcome::misclassifiedMean): the mean misclassified
    // pixels and its standard error (0 for one phase); `misclassified` is phase 0's count.
    double misclassifiedMean = 0.0, misclassifiedError = 0.0;
    int phases = 1;  // the phases they are over: K, or more where adaptive (Scene::maxPhases)
    // The edge energy e (MethodOutcome::e; NaN for warped and virtual maps).
    double e = std::numeric_limits<double>::quiet_NaN();
    // With shimmer poses (RunSweep): the shimmer along the camera path's first poses, in % of the
    // stable pixels per step (ShimmerAlong, camera_path.h); NaN when not measured and for a case's
    // own matrices (Scene::methods: given for the case camera alone, they do not refit).
    double shimmer = std::numeric_limits<double>::quiet_NaN();
};

struct SweepResult {
    std::string caseName;
    std::vector<std::string> methods;
    std::vector<spatial::Light> lights;
    // Each light's index in the whole sweep (SweepLightsOf's order): 0, 1, ... for a whole sweep;
    // a shard's share (sweep_share.h) holds the lights i with i mod N = K.
    std::vector<std::size_t> indices;
    std::vector<std::vector<SweepCell>> cells;  // [light][method]
    std::vector<std::int64_t> receiverPixels;   // per light
    double seconds = 0.0;                       // wall time of the whole sweep
    int phases = 1;     // the sub-texel phases each cell's mean is over (Scene::phases) at least,
    int maxPhases = 1;  // ... and at most (Scene::maxPhases; SweepCell::phases: how many)
    // The camera_path poses each cell's shimmer is over (0: shimmer not measured).
    int shimmerPoses = 0;
};

// The lights of the sweep: the case's light_sweep, its count overridden by `lights` when > 0 and
// its light type by `type` when given. Throws InputError (/light_sweep) when the case has none.
std::vector<spatial::Light> SweepLightsOf(const spatial::Scene& scene, int lights,
                                          std::optional<spatial::Light::Type> type = {});

// Called (from any thread, possibly at once from several) when light `light` (an index into the
// lights given) is evaluated, with its cells per method and its receiver pixels.
using SweepLightDone = std::function<void(std::size_t light, const std::vector<SweepCell>& cells,
                                          std::int64_t receiverPixels)>;

// Evaluates every light, in parallel over lights, deterministically for the case's seed: a
// light's numbers depend on that light alone (not on the others given, their number or order;
// times aside); light l of the whole sweep uses the case's own methods' matrix l
// (Scene::methods, checked with CheckCaseMethodLights). Calls `onLightDone` after each. Throws
// InputError naming the camera or the light
// for input the evaluation cannot serve, BackendUnavailable when `backend` cannot be made. With
// the GL backend the lights still run in parallel; their GPU passes take turns on the one context.
// `indices`: each light's index in the whole sweep (r.indices, and the light an error names);
// empty: 0, 1, ... `shimmerPoses` in 2 ... kMaxShimmerPoses: each cell's shimmer along the first
// that many poses of scene.cameraPath, each pose at phase 0 (one more evaluation per pose and
// light, not in the cells' times; InputError naming /camera_path when the case has fewer); 0: none.
SweepResult RunSweep(const spatial::Scene& scene, const std::vector<std::string>& methods,
                     const std::vector<spatial::Light>& lights,
                     const SweepLightDone& onLightDone = {},
                     BackendKind backend = BackendKind::kCpu,
                     const std::vector<std::size_t>& indices = {}, int shimmerPoses = 0);

// With `shimmerPoses` pose frames besides the camera's (RunSweep) and one light in flight:
// MemoryBudgetExcess's text when the sweep exceeds the memory budget, else empty.
std::string SweepMemoryExcess(const spatial::Scene& scene, std::size_t methods, int shimmerPoses);

// "point (x, y, z)" or "directional (x, y, z)", 4 significant digits.
std::string LightLabel(const spatial::Light& light);

}  // namespace lexel::cases
