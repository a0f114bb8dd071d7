// Algorithm 1 step 5 (report §2.3, temporal hysteresis) along a case's camera_path: per light and
// pose, whether `optimal` replaces the previous matrix, and the misclassified pixels with and
// without the hysteresis.
#pragma once

#include <cstdint>
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

struct CameraPathStudy {
    std::vector<PoseOutcome> poses;
    int Changes() const;
};

// One study per fixed light of the scene, over scene.cameraPath. Throws InputError naming the
// pose (/camera_path/k) or the light for input the evaluation cannot serve.
std::vector<CameraPathStudy> RunCameraPathStudy(const spatial::Scene& scene,
                                                const spatial::RenderBackend& backend);

}  // namespace lexel::cases
