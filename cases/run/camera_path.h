// Along a case's camera_path, per fixed light: Algorithm 1 step 5 (report §2.3, temporal
// hysteresis) — per pose whether `optimal` replaces the previous matrix, and the misclassified
// pixels with and without the hysteresis — and every method's shimmer: the share of the pixels
// counted at two consecutive poses whose ray truth is the same at both but whose shadow decision
// changes (texels crawling across the view as the map refits; SDSM §5.3).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// The shimmering share between two poses, in percent: of the pixels counted (lit or shadowed) at
// both with the same ray truth at both, those whose decision differs (0 when there are none).
// The four spans are per frame pixel, of one size (std::invalid_argument otherwise).
double ShimmerPercent(std::span<const spatial::Shade> before,
                      std::span<const std::uint8_t> truthBefore,
                      std::span<const spatial::Shade> after,
                      std::span<const std::uint8_t> truthAfter);

struct PoseOutcome {
    bool changed = true;                       // the new matrix replaced the kept one
    double medianKept = 0.0, medianNew = 0.0;  // median badness (+inf when nothing is kept)
    std::int64_t misclassifiedHysteresis = 0;  // with the matrix the hysteresis chose
    std::int64_t misclassifiedFresh = 0;       // with a fresh `optimal` matrix
};

// The name the shimmer table gives `optimal` under the report's hysteresis.
inline constexpr const char* kOptimalWithHysteresis = "optimal + hysteresis";

struct CameraPathStudy {
    std::vector<PoseOutcome> poses;
    std::vector<std::string> methods;  // the run's methods, then kOptimalWithHysteresis
    // Per method: the mean over consecutive pose pairs of the shimmering share of the pixels
    // counted at both poses with unchanged truth, in percent (0 with fewer than two poses).
    std::vector<double> shimmerPercent;
    int Changes() const;
};

// One study per fixed light of the scene, over scene.cameraPath, for `methods` (optimal is run
// for the hysteresis whether listed or not). Throws InputError naming the pose (/camera_path/k)
// or the light for input the evaluation cannot serve.
// `onMethodDone` (may be empty) is called after each method of each pose is measured
// (CameraPathSteps calls in all: a progress bar).
std::vector<CameraPathStudy> RunCameraPathStudy(const spatial::Scene& scene,
                                                const spatial::RenderBackend& backend,
                                                const std::vector<std::string>& methods,
                                                const std::function<void()>& onMethodDone = {});
// The calls RunCameraPathStudy makes to onMethodDone: lights × poses × (methods, and optimal when
// they lack it).
std::size_t CameraPathSteps(const spatial::Scene& scene, const std::vector<std::string>& methods);

// The first poses of scene.cameraPath, each as the scene seen from it and that scene's evaluator
// (which holds a reference to it: keep the two together; moving PathPoses keeps them valid).
struct PathPoses {
    std::vector<spatial::Scene> scenes;
    std::vector<std::unique_ptr<spatial::Evaluator>> evaluators;
};
// Poses 0 ... count − 1 (count ≤ scene.cameraPath.size()). Throws InputError naming the pose
// (/camera_path/k) as MakeEvaluator does.
PathPoses MakePathPoses(const spatial::Scene& scene, const spatial::RenderBackend& backend,
                        std::size_t count);

// The shimmer of `light` along `poses`, per method of options.methods in percent: the mean over
// consecutive pose pairs of the share of the pixels counted at both with unchanged truth whose
// decision changes (as CameraPathStudy::shimmerPercent, without the hysteresis). Each pose is
// measured at phase 0 alone (options.phases and keepBuffers are set here). With fewer than two
// poses every share is 0. Throws InputError naming `lightField` and the pose for input the
// evaluation cannot serve.
std::vector<double> ShimmerAlong(const PathPoses& poses, const spatial::Light& light,
                                 spatial::EvaluationOptions options, const std::string& lightField);

}  // namespace lexel::cases
