// The timed frame computes what the evaluation computes: the same focused and optimal matrices
// per light (so `lexel timing` times Algorithm 1 as `lexel run` measures it), and the schedule
// keeps P between updates.
#include "lexel/spatial/harness/frame_pipeline.h"

#include <gtest/gtest.h>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"

namespace lexel::spatial {
namespace {

void ExpectSameMatrix(const LightMatrix& a, const LightMatrix& b, const char* what) {
    EXPECT_EQ(a.p1, b.p1) << what;
    EXPECT_EQ(a.p2, b.p2) << what;
    EXPECT_EQ(a.p4, b.p4) << what;
}

TEST(FramePipeline, CpuFrameUsesTheEvaluationsMatricesAndKeepsThemBetweenUpdates) {
    const Scene scene = cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
    const auto cpu = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *cpu);
    EvaluationOptions options;
    options.methods = {"focused", "optimal-report"};
    const auto pipeline = MakeCpuFramePipeline(scene.geometry);

    const FrameTimes focused =
        pipeline->RenderFrame(scene, scene.camera, scene.lights, FrameMethod::kFocused);
    const std::vector<LightMatrix> focusedMatrices = pipeline->Matrices();
    const FrameTimes optimal =
        pipeline->RenderFrame(scene, scene.camera, scene.lights, FrameMethod::kOptimal);
    const std::vector<LightMatrix> optimalMatrices = pipeline->Matrices();
    ASSERT_EQ(optimalMatrices.size(), scene.lights.size());
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const LightOutcome o = evaluator.Evaluate(scene.lights[l], options);
        ExpectSameMatrix(focusedMatrices[l], o.methods[0].matrix, "focused");
        ExpectSameMatrix(optimalMatrices[l], o.methods[1].matrix, "optimal");
    }
    EXPECT_GT(optimal.search, 0.0);
    EXPECT_GT(optimal.extraction, 0.0);
    EXPECT_EQ(focused.search, 0.0);
    EXPECT_EQ(focused.readback, 0.0);
    EXPECT_GE(optimal.total, 0.99 * (optimal.Parts() - optimal.hull));

    // A frame without an update keeps each light's P and does none of Algorithm 1's work.
    const Camera moved = scene.cameraPath.at(1);
    const FrameTimes kept = pipeline->RenderFrame(scene, moved, scene.lights, FrameMethod::kOptimal,
                                                  {.optimize = false, .standardMap = false});
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        ExpectSameMatrix(pipeline->Matrices()[l], optimalMatrices[l], "kept");
    EXPECT_EQ(kept.readback + kept.extraction + kept.search + kept.hull, 0.0);
    // An update from the previous maps renders no standard map: one map pass per light.
    const FrameTimes previous =
        pipeline->RenderFrame(scene, moved, scene.lights, FrameMethod::kOptimal,
                              {.optimize = true, .standardMap = false});
    EXPECT_GT(previous.search, 0.0);
}

}  // namespace
}  // namespace lexel::spatial
