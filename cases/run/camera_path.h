// Along a case's camera_path, per fixed light: Algorithm 1 step 5 (report §2.3, temporal
// hysteresis) — per pose whether `optimal` replaces the previous matrix, and the misclassified
// pixels with and without the hysteresis — and every method's shimmer: the share of the pixels
// counted at two consecutive poses whose ray truth is the same at both but whose shadow decision
// changes (texels crawling across the view as the map refits; SDSM §5.3).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

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

}  // namespace lexel::cases
