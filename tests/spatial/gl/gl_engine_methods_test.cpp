// What engines ship on the GPU against the CPU backend: `tsm` is one light matrix and
// `vsm` / `vsm-dynamic` a linear map per resident page, each page rendered by the GL shadow pass
// and the frame shaded through the page that serves each pixel. Each backend renders its own
// frame, readback, maps and decisions; the truth is the same Embree rays. On the walkthrough's
// fixed lights and 6 of its sweep's (3 point, 3 directional): the same matrices up to the
// readbacks' differences, pages requested and resident within 2% of the CPU's, misclassified
// pixels within max(5, 5e-4 × counted) — the bound the other GL tests use.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/gl/gl_backend.h"
#include "lexel/spatial/harness/evaluation.h"
#include "spatial/gl/gl_test_support.h"

namespace lexel::spatial {
namespace {

using testing::GlTest;
using testing::Walkthrough;

TEST_F(GlTest, TsmAndVirtualShadowMapsAgreeWithTheCpuBackend) {
    const Scene& scene = Walkthrough();
    const auto cpu = MakeCpuRenderer(scene.geometry);
    const auto gpu = gl::MakeGlBackend(scene.geometry);
    const Evaluator cpuEval(scene, *cpu), gpuEval(scene, *gpu);
    EvaluationOptions options;
    options.methods = {"tsm", "vsm", "vsm-dynamic"};
    std::vector<Light> lights = scene.lights;
    for (const Light::Type type : {Light::Type::kPoint, Light::Type::kDirectional})
        for (const Light& l : cases::SweepLightsOf(scene, 3, type)) lights.push_back(l);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightOutcome c = cpuEval.Evaluate(lights[l], options);
        const LightOutcome g = gpuEval.Evaluate(lights[l], options);
        const std::int64_t bound = std::max<std::int64_t>(5, c.receiverPixels / 2000);
        for (std::size_t m = 0; m < options.methods.size(); ++m) {
            const MethodOutcome &co = c.methods[m], &go = g.methods[m];
            const std::string what = co.method + ", " + cases::LightLabel(lights[l]);
            EXPECT_LE(std::abs(go.metrics.misclassified - co.metrics.misclassified), bound)
                << what << ": " << go.metrics.misclassified << " (gl) and "
                << co.metrics.misclassified << " (cpu) of " << c.receiverPixels;
            EXPECT_LE(std::abs(go.metrics.uncovered - co.metrics.uncovered), bound) << what;
            std::cout << "[   INFO   ] " << what << ": misclassified " << co.metrics.misclassified
                      << " / " << go.metrics.misclassified << " (cpu / gl)";
            if (co.pages) {
                ASSERT_TRUE(go.pages) << what;
                const double tolerance = 0.02 * static_cast<double>(co.pages->requested) + 1.0;
                EXPECT_LE(std::abs(go.pages->requested - co.pages->requested), tolerance) << what;
                EXPECT_LE(std::abs(go.pages->resident - co.pages->resident), tolerance) << what;
                EXPECT_LE(go.pages->resident, go.pages->poolPages) << what;
                EXPECT_LE(go.metrics.texels, static_cast<std::int64_t>(scene.shadowMap.Count()))
                    << what;
                std::cout << ", pages requested " << co.pages->requested << " / "
                          << go.pages->requested << ", resident " << co.pages->resident << " / "
                          << go.pages->resident;
            }
            std::cout << '\n';
        }
    }
}

}  // namespace
}  // namespace lexel::spatial
