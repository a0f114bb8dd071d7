// `lexel timing`: the running-time study of Chong & Gortler's report §3 (Tables 2–3) on a case —
// F frames walking its camera_path, each rendered with focused and with optimal shadows for the
// same N lights, timed pass by pass (frame_pipeline.h) on the chosen backend.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lexel/cases/run/backend.h"
#include "lexel/spatial/harness/frame_pipeline.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

struct TimingOptions {
    BackendKind backend = BackendKind::kCpu;
    int lights = 4;  // the report's Table 3 has 4
    int frames = 8;  // timed frames per method, after one warm-up frame each
    // The report's savings (§2.4, spatial::UpdatePolicy): optimal runs Algorithm 1 on frames k with
    // k mod updateEvery = 0, and of those every standardEvery-th takes step 1 from a fresh
    // standard map (the others from the light's previous map). 1, 1: everything every frame; the
    // report's: 3, 2.
    int updateEvery = 1;
    int standardEvery = 1;
    std::string optimal = spatial::kReportOptimalMethod;  // FrameOptions::optimal
    // Called after each frame (the warm-up one too: frames + 1 calls), both methods rendered; a
    // progress bar. May be empty.
    std::function<void()> onFrameDone;
};

struct TimingRun {
    std::string caseName;
    std::string backend;    // DescribeBackend
    std::string passClock;  // FramePipeline::PassClock
    std::vector<spatial::Light> lights;
    std::vector<spatial::FrameTimes> focused, optimal;  // per timed frame
    int poses = 1;  // distinct camera poses walked (camera_path length, or 1)
    int updateEvery = 1, standardEvery = 1;
    std::string optimizer;  // of the optimal frames (FrameOptions::optimal)
};

// The optimal frames' options for timed frame k ≥ 0 (the warm-up frame runs in full).
spatial::FrameOptions ScheduleOf(const TimingOptions& options, int frame);

// The mean of each column over the frames.
spatial::FrameTimes MeanTimes(const std::vector<spatial::FrameTimes>& frames);

// The first `count` lights of the case: its fixed lights, then its light_sweep's. Throws
// InputError (/lights) when the case has fewer.
std::vector<spatial::Light> TimingLightsOf(const spatial::Scene& scene, int count);

// Frame k is seen from camera_path[k mod length] (the case's camera without a path); focused and
// optimal alternate frame by frame. Throws BackendUnavailable, and InputError naming the camera,
// the pose or the light for input the passes cannot serve.
TimingRun RunTiming(const spatial::Scene& scene, const TimingOptions& options);

}  // namespace lexel::cases
