// The 3D memory estimate is an upper bound of what the evaluation really holds: the
// peak resident memory of one light's evaluation, every method with its buffers kept, measured
// through Linux's VmHWM (reset by /proc/self/clear_refs), stays under the estimate, and not far
// under it (the estimate would refuse cases that fit).
#include "lexel/spatial/harness/memory_estimate.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;  // its shadow memory and redzones are not lexel's
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// A line "Key:   1234 kB" of /proc/self/status, in bytes.
double StatusBytes(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string word;
    while (status >> word)
        if (word == key + ":") {
            double kb = 0;
            status >> kb;
            return kb * 1024.0;
        }
    return -1;
}

TEST(MemoryEstimate, ScalesWithEverySize) {
    // Doubling each size raises its own term: frame and readback in shared, maps per light.
    EvaluationSizes base{{100, 100}, {50, 50}, {64, 64}, 1000, 10, true, 0};
    const EvaluationMemory m = EstimateEvaluationMemory(base);
    EvaluationSizes frame = base, map = base, triangles = base;
    frame.frame = {200, 100};
    map.shadowMap = {128, 64};
    triangles.triangles = 2000;
    EXPECT_GT(EstimateEvaluationMemory(frame).shared, m.shared);
    EXPECT_GT(EstimateEvaluationMemory(frame).perLight, m.perLight);
    EXPECT_EQ(EstimateEvaluationMemory(map).shared, m.shared);
    EXPECT_GT(EstimateEvaluationMemory(map).perLight, m.perLight);
    EXPECT_GT(EstimateEvaluationMemory(triangles).shared, m.shared);
    EXPECT_EQ(EstimateEvaluationMemory(triangles).perLight, m.perLight);
    // The schema's largest camera (16384²) needs tens of GiB: over any budget lexel states.
    EvaluationSizes largest = base;
    largest.frame = {16384, 16384};
    EXPECT_GT(EstimateEvaluationMemory(largest).Total(1), 30.0 * (1 << 30));
}

TEST(MemoryEstimate, BoundsTheMeasuredPeakOfOneLight) {
    if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory is not lexel's";
    std::ofstream clear("/proc/self/clear_refs");
    ASSERT_TRUE(clear) << "/proc/self/clear_refs is needed to measure the peak";
    Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) /
                                          "spatial/walkthrough.json");
    scene.camera.resolution = {900, 700};
    scene.shadowMap = {1024, 1024};
    scene.readback = {240, 240};
    EvaluationOptions options;
    options.methods = SpatialMethodNames();
    options.keepBuffers = true;
    EvaluationSizes sizes{scene.camera.resolution,
                          scene.readback,
                          scene.shadowMap,
                          scene.geometry.triangles.size(),
                          static_cast<int>(options.methods.size()),
                          true,
                          0};
    const double estimate = EstimateEvaluationMemory(sizes).Total(1);

    const double before = StatusBytes("VmRSS");
    clear << "5" << std::flush;  // VmHWM := VmRSS
    double peak = 0;
    {
        const auto backend = MakeCpuRenderer(scene.geometry);
        const Evaluator evaluator(scene, *backend);
        const LightOutcome outcome = evaluator.Evaluate(scene.lights[0], options);
        ASSERT_EQ(outcome.methods.size(), options.methods.size());
        peak = StatusBytes("VmHWM");
    }
    const double used = peak - before;
    const EvaluationMemory parts = EstimateEvaluationMemory(sizes);
    std::cout << "measured peak " << used / (1 << 20) << " MiB, estimate " << estimate / (1 << 20)
              << " MiB (shared " << parts.shared / (1 << 20) << ", per light "
              << parts.perLight / (1 << 20) << "; " << sizes.triangles << " triangles, "
              << sizes.methods << " methods)\n";
    EXPECT_LE(used, estimate);
    EXPECT_GE(used, estimate / 4) << "the estimate is too loose to be useful";
}

}  // namespace
}  // namespace lexel::spatial
