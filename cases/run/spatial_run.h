// `lexel run` on a 3D case (report §3 for its fixed lights): per light and method the
// misclassified pixels against exact shadow rays, h and time; the buffers the images need; and the
// temporal-hysteresis study along the case's camera_path.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lexel/cases/run/backend.h"
#include "lexel/cases/run/camera_path.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

struct SpatialRunOptions {
    std::vector<std::string> methods;  // names from SpatialMethodNames
    bool mapTruth = true;              // also the report's focused 4000² truth map
    bool keepBuffers = false;          // keep shades and maps (for images)
    BackendKind backend = BackendKind::kCpu;
    // Called after each step SpatialRunSteps counts (a progress bar); may be empty.
    std::function<void()> onStep;
};

// The methods of the camera-path study: `methods` without the case's own (their matrices are for
// the case's camera, not for the path's poses).
std::vector<std::string> CameraPathMethods(const spatial::Scene& scene,
                                           const std::vector<std::string>& methods);

// The steps of RunSpatialCase: one per fixed light and method, and the camera-path study's
// (CameraPathSteps) when the case has a camera_path.
std::size_t SpatialRunSteps(const spatial::Scene& scene, const SpatialRunOptions& options);

struct SpatialRun {
    std::unique_ptr<spatial::RenderBackend> backend;
    std::unique_ptr<spatial::Evaluator> evaluator;  // the frame and bounds, for images
    std::vector<spatial::LightOutcome> outcomes;    // per fixed light
    std::vector<CameraPathStudy> cameraPath;        // per fixed light; empty without a path
};

// Everything is computed before anything is reported or written. Throws InputError naming the
// field (/lights: none; /lights/k, /camera, /geometry) for input the evaluation cannot serve, and
// BackendUnavailable when the backend cannot be made.
SpatialRun RunSpatialCase(const spatial::Scene& scene, const SpatialRunOptions& options);

}  // namespace lexel::cases
