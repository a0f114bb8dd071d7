#include "lexel/cases/studies/timing/timing_study.h"

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/frame_schedule.h"

namespace lexel::cases {

using spatial::FrameTimes;

FrameTimes MeanTimes(const std::vector<FrameTimes>& frames) {
    FrameTimes m;
    if (frames.empty()) return m;
    for (const FrameTimes& f : frames) {
        m.total += f.total;
        m.cameraPass += f.cameraPass;
        m.readback += f.readback;
        m.extraction += f.extraction;
        m.hull += f.hull;
        m.search += f.search;
        m.shadowMap += f.shadowMap;
        m.shading += f.shading;
    }
    const double n = static_cast<double>(frames.size());
    for (double* v : {&m.total, &m.cameraPass, &m.readback, &m.extraction, &m.hull, &m.search,
                      &m.shadowMap, &m.shading})
        *v /= n;
    return m;
}

std::vector<spatial::Light> TimingLightsOf(const spatial::Scene& scene, int count) {
    std::vector<spatial::Light> lights = scene.lights;
    if (static_cast<int>(lights.size()) < count && scene.lightSweep) {
        const std::vector<spatial::Light> sweep =
            SweepLightsOf(scene, count - static_cast<int>(lights.size()));
        lights.insert(lights.end(), sweep.begin(), sweep.end());
    }
    if (static_cast<int>(lights.size()) < count)
        throw InputError("/lights: --lights " + std::to_string(count) + " needs " +
                         std::to_string(count) + " lights; the case has " +
                         std::to_string(lights.size()) +
                         (scene.lightSweep ? "" : " and no light_sweep"));
    lights.resize(static_cast<std::size_t>(count));
    return lights;
}

spatial::FrameOptions ScheduleOf(const TimingOptions& options, int frame) {
    const spatial::UpdatePolicy policy{.updateEvery = options.updateEvery,
                                       .standardEvery = options.standardEvery};
    return policy.At(frame, {.optimal = options.optimal});
}

TimingRun RunTiming(const spatial::Scene& scene, const TimingOptions& options) {
    TimingRun run;
    run.caseName = scene.name;
    run.lights = TimingLightsOf(scene, options.lights);
    const std::unique_ptr<spatial::FramePipeline> pipeline =
        MakeFramePipeline(options.backend, scene.geometry);
    run.backend = DescribeBackend(options.backend);
    run.passClock = pipeline->PassClock();
    run.poses = scene.cameraPath.empty() ? 1 : static_cast<int>(scene.cameraPath.size());
    run.updateEvery = options.updateEvery;
    run.standardEvery = options.standardEvery;
    run.optimizer = options.optimal;
    // Frame -1 warms up (shader compilation, caches) and is not reported.
    for (int k = -1; k < options.frames; ++k) {
        const std::size_t pose = static_cast<std::size_t>(std::max(k, 0) % run.poses);
        spatial::Camera camera = scene.camera;
        if (!scene.cameraPath.empty()) camera = scene.cameraPath[pose];
        const std::string cameraField =
            scene.cameraPath.empty() ? "/camera" : CameraPathField(pose);
        FrameTimes focused, optimal;
        try {
            focused =
                pipeline->RenderFrame(scene, camera, run.lights, spatial::FrameMethod::kFocused);
            optimal =
                pipeline->RenderFrame(scene, camera, run.lights, spatial::FrameMethod::kOptimal,
                                      ScheduleOf(options, std::max(k, 0)));
        } catch (const DomainError& e) {
            throw InputError(SpatialErrorField(e, "/lights", cameraField) + ": " + e.what());
        }
        if (options.onFrameDone) options.onFrameDone();
        if (k < 0) continue;
        run.focused.push_back(focused);
        run.optimal.push_back(optimal);
    }
    return run;
}

}  // namespace lexel::cases
