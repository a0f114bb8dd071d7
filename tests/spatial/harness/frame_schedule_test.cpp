// The one frame schedule (report §2.4): the update policy frame by frame, the plan of a frame
// light by light, and the passes a pipeline runs for it — counted on the CPU pipeline through a
// recording backend, frame by frame over the report's own schedule (U = 3, S = 2).
#include "lexel/spatial/harness/frame_schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {
namespace {

TEST(UpdatePolicy, UpdatesEveryUFramesAndStandardMapsEverySUpdates) {
    const UpdatePolicy report{.updateEvery = 3, .standardEvery = 2};
    const bool optimize[] = {true, false, false, true, false, false, true, false, false, true};
    const bool standard[] = {true, false, false, false, false, false, true, false, false, false};
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(report.At(k).optimize, optimize[k]) << "frame " << k;
        EXPECT_EQ(report.At(k).standardMap, standard[k]) << "frame " << k;
    }
    // U = 1, S = 3: every frame updates, every third from a standard map.
    const UpdatePolicy everyFrame{.updateEvery = 1, .standardEvery = 3};
    for (int k = 0; k < 7; ++k) {
        EXPECT_TRUE(everyFrame.At(k).optimize) << "frame " << k;
        EXPECT_EQ(everyFrame.At(k).standardMap, k % 3 == 0) << "frame " << k;
    }
    EXPECT_TRUE(UpdatePolicy{}.At(5).standardMap);
    // The other options pass through.
    const FrameOptions o = report.At(1, {.optimal = "optimal-shear", .timePasses = false});
    EXPECT_EQ(o.optimal, "optimal-shear");
    EXPECT_FALSE(o.timePasses);
    EXPECT_FALSE(o.optimize);
}

using enum LightStep;

TEST(PlanFrame, FocusedFramesRunNoAlgorithm1AndKeepNothing) {
    const FramePlan plan = PlanFrame(FrameMethod::kFocused, {}, {true, false});
    EXPECT_FALSE(plan.readback);
    EXPECT_FALSE(plan.keepMaps);
    EXPECT_EQ(plan.lights, (std::vector<LightStep>{kFocused, kFocused}));
}

TEST(PlanFrame, OptimalFramesFollowTheUpdateAndEachLightsKeptState) {
    const FrameOptions full;  // optimize, standard map
    const FrameOptions keep{.optimize = false, .standardMap = false};
    const FrameOptions previous{.optimize = true, .standardMap = false};
    FramePlan plan = PlanFrame(FrameMethod::kOptimal, full, {true, false});
    EXPECT_TRUE(plan.readback);
    EXPECT_TRUE(plan.keepMaps);
    EXPECT_EQ(plan.lights, (std::vector<LightStep>{kUpdateFromStandard, kUpdateFromStandard}));
    plan = PlanFrame(FrameMethod::kOptimal, previous, {true, false});
    EXPECT_EQ(plan.lights, (std::vector<LightStep>{kUpdateFromPrevious, kUpdateFromStandard}));
    // Between updates only a light without a kept P runs Algorithm 1, and the readback is
    // rendered for it alone.
    plan = PlanFrame(FrameMethod::kOptimal, keep, {true, true});
    EXPECT_FALSE(plan.readback);
    EXPECT_EQ(plan.lights, (std::vector<LightStep>{kKeep, kKeep}));
    plan = PlanFrame(FrameMethod::kOptimal, keep, {true, false});
    EXPECT_TRUE(plan.readback);
    EXPECT_EQ(plan.lights, (std::vector<LightStep>{kKeep, kUpdateFromStandard}));
    // No light, no readback (both pipelines used to render one on an update, the CPU one also
    // between updates).
    EXPECT_FALSE(PlanFrame(FrameMethod::kOptimal, keep, {}).readback);
    EXPECT_FALSE(PlanFrame(FrameMethod::kOptimal, full, {}).readback);
}

// The CPU renderer, each pass written into `log`: "cam<width>", "map", "boundary",
// "shade<width>".
class RecordingBackend final : public RenderBackend {
  public:
    RecordingBackend(const TriangleMesh& geometry, std::string* log)
        : cpu_(MakeCpuRenderer(geometry)), log_(log) {}
    std::string_view Name() const override { return "recording"; }
    CameraBuffer RenderCamera(const Camera& camera, Resolution resolution) const override {
        *log_ += " cam" + std::to_string(resolution.width);
        return cpu_->RenderCamera(camera, resolution);
    }
    ShadowMap RenderShadowMap(const LightSpace& lightSpace, const LightMatrix& matrix,
                              Resolution resolution) const override {
        *log_ += " map";
        return cpu_->RenderShadowMap(lightSpace, matrix, resolution);
    }
    std::vector<Shade> ShadePixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                   const ShadowMap& map) const override {
        *log_ += " shade" + std::to_string(frame.resolution.width);
        return cpu_->ShadePixels(frame, lightSpace, map);
    }
    LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                 const ShadowMap& map) const override {
        *log_ += " boundary";
        return cpu_->BoundarySamples(readback, lightSpace, map);
    }

  private:
    std::unique_ptr<RenderBackend> cpu_;
    std::string* log_;
};

std::string Repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

TEST(FrameSchedule, CpuPipelineRunsTheReportsScheduleFrameByFrame) {
    // spatial_small: a 160×120 frame, a 64² readback; two lights.
    const Scene scene =
        cases::LoadSpatialScene(LEXEL_CASES_DIR "/../tests/cases/data/spatial_small.json");
    std::vector<Light> lights = cases::SweepLightsOf(scene, 2);
    std::string log;
    const RecordingBackend backend(scene.geometry, &log);
    const auto pipeline = MakeBackendFramePipeline(backend, scene.geometry);
    const UpdatePolicy report{.updateEvery = 3, .standardEvery = 2};
    // Per light: [standard map, boundary samples], final map, shading of the frame.
    const std::string focused = " cam160" + Repeat(" map shade160", 2);
    const std::string fromStandard = " cam64 cam160" + Repeat(" map boundary map shade160", 2);
    const std::string fromPrevious = " cam64 cam160" + Repeat(" boundary map shade160", 2);
    const std::string kept = " cam160" + Repeat(" map shade160", 2);
    const std::string expected[] = {fromStandard, kept, kept,        fromPrevious,
                                    kept,         kept, fromStandard};
    std::vector<LightMatrix> updated;
    for (int k = 0; k < 7; ++k) {
        // A focused frame between the optimal ones (as `lexel timing` runs them) leaves the
        // optimal frames' kept maps and matrices alone.
        log.clear();
        pipeline->RenderFrame(scene, scene.camera, lights, FrameMethod::kFocused);
        EXPECT_EQ(log, focused) << "focused frame " << k;
        log.clear();
        const FrameTimes t =
            pipeline->RenderFrame(scene, scene.camera, lights, FrameMethod::kOptimal, report.At(k));
        EXPECT_EQ(log, expected[k]) << "optimal frame " << k;
        EXPECT_EQ(t.search > 0.0, k % 3 == 0) << "optimal frame " << k;
        if (k % 3 == 0) updated = pipeline->Matrices();
        for (std::size_t l = 0; l < lights.size(); ++l)
            EXPECT_EQ(pipeline->Matrices()[l].p4, updated[l].p4) << "frame " << k << " light " << l;
    }
    // Other lights: their state is gone, so even a frame without an update runs Algorithm 1 from
    // standard maps for every light.
    std::swap(lights[0], lights[1]);
    log.clear();
    pipeline->RenderFrame(scene, scene.camera, lights, FrameMethod::kOptimal, report.At(1));
    EXPECT_EQ(log, fromStandard);
}

TEST(FrameSchedule, EveryOptimizerMethodDrivesTheOptimalFrames) {
    // The pipeline takes its optimizer from the one list the evaluator uses (methods.h): each of
    // them runs Algorithm 1 for every light of an updating frame; a method that is no optimizer
    // is refused with the reason.
    const Scene scene =
        cases::LoadSpatialScene(LEXEL_CASES_DIR "/../tests/cases/data/spatial_small.json");
    const std::vector<Light> lights = cases::SweepLightsOf(scene, 2);
    std::string log;
    const RecordingBackend backend(scene.geometry, &log);
    const std::vector<std::string> names = OptimizerMethodNames();
    ASSERT_EQ(names.size(), 6u);
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        EXPECT_TRUE(IsSpatialMethod(name));
        const auto pipeline = MakeBackendFramePipeline(backend, scene.geometry);
        const FrameTimes t = pipeline->RenderFrame(scene, scene.camera, lights,
                                                   FrameMethod::kOptimal, {.optimal = name});
        EXPECT_GT(t.search, 0.0);
        ASSERT_EQ(pipeline->Matrices().size(), lights.size());
        for (const LightMatrix& m : pipeline->Matrices())
            EXPECT_TRUE(std::isfinite(m.p4.x) && std::isfinite(m.p4.y) && std::isfinite(m.p4.z));
    }
    EXPECT_FALSE(IsOptimizerMethod("focused-tight"));
    const auto pipeline = MakeBackendFramePipeline(backend, scene.geometry);
    EXPECT_THROW(pipeline->RenderFrame(scene, scene.camera, lights, FrameMethod::kOptimal,
                                       {.optimal = "focused-tight"}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lexel::spatial
