#include "lexel/flatland/frustum_split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/lexel_remap.h"
#include "lexel/solvers/errors.h"
#include "test_scenes.h"

namespace lexel::flatland {
namespace {

using testing::Describe;
using testing::RandomScene;

// dp ≤ greedy always (on the planning objective, the real-valued Lagrange total).
TEST(FrustumSplit, DynamicProgramNeverLosesToGreedy) {
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
        const FlatScene scene = RandomScene(seed, 200);
        SCOPED_TRACE(Describe(scene));
        const SamplingPass pass = RunSamplingPass(scene, 200);
        for (Metric metric : {Metric::kL1, Metric::kL2})
            for (int budget : {1, 2, 3, 5}) {
                const FrustaOptions options{12, budget, metric};
                const SplitResult greedy =
                    SplitLightFrustum(pass, scene.lexels, options, SplitStrategy::kGreedy);
                const SplitResult dp =
                    SplitLightFrustum(pass, scene.lexels, options, SplitStrategy::kDynamicProgram);
                EXPECT_LE(dp.realTotal, greedy.realTotal * (1 + 1e-12)) << "budget " << budget;
                EXPECT_LE(static_cast<int>(dp.frusta.size()), budget);
                EXPECT_LE(static_cast<int>(greedy.frusta.size()), budget);
                int lexels = 0;
                for (const auto& f : dp.frusta) {
                    lexels += f.lexels;
                    EXPECT_GE(f.lexels, 1);
                }
                EXPECT_EQ(lexels, scene.lexels);
            }
    }
}

// budget = 1 reproduces the single-frustum optimum exactly.
TEST(FrustumSplit, BudgetOneIsTheSingleFrustumOptimum) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const FlatScene scene = RandomScene(seed);
        SCOPED_TRACE(Describe(scene));
        const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
        for (auto strategy : {SplitStrategy::kGreedy, SplitStrategy::kDynamicProgram}) {
            const SplitResult split =
                SplitLightFrustum(pass, scene.lexels, {16, 1, Metric::kL1}, strategy);
            ASSERT_EQ(split.frusta.size(), 1u);
            const MethodReport r = EvaluateSplit(scene, pass, split);
            const AngleSolution single = SolveL1Exact(MakeLexelSamples(pass, scene.lexels));
            EXPECT_NEAR(r.stats.l1 / single.objective, 1.0, 1e-12);
            EXPECT_NEAR(split.frusta[0].wsAxis, single.wsAxis, 1e-12);
            EXPECT_EQ(split.frusta[0].lexels, scene.lexels);
        }
    }
}

// The per-frustum numbers, recomputed independently from the samples' (α, g) with (R1), and the
// totals over Ω.
TEST(FrustumSplit, ReportedFrustaRecomputeFromScratch) {
    const FlatScene scene = RandomScene(9, 400);
    const SamplingPass pass = RunSamplingPass(scene, 400);
    const SplitResult split =
        SplitLightFrustum(pass, scene.lexels, {16, 3, Metric::kL1}, SplitStrategy::kDynamicProgram);
    const MethodReport r = EvaluateSplit(scene, pass, split);
    ASSERT_EQ(r.frusta.size(), split.frusta.size());
    double total = 0;
    std::size_t count = 0;
    for (std::size_t j = 0; j < r.frusta.size(); ++j) {
        const FrustumReport& fr = r.frusta[j];
        const double lo = fr.wsRayLowDeg * std::numbers::pi / 180,
                     hi = fr.wsRayHighDeg * std::numbers::pi / 180;
        const double width = std::tan(hi - fr.wsAxis) - std::tan(lo - fr.wsAxis);  // W(θ)
        double l1 = 0, worst = 0;
        std::size_t n = 0;
        for (const auto& s : pass.samples) {
            const double alpha = pass.wsAxis0 + s.lsAngle;
            if (alpha < lo - 1e-12 || alpha > hi + 1e-12) continue;
            const double c = std::cos(alpha - fr.wsAxis);
            const double f = PixelsPerRadian(pass, s) * width * c * c / fr.lexels;  // (R1)
            l1 += f, worst = std::max(worst, f), ++n;
        }
        EXPECT_EQ(n, fr.stats.count);
        EXPECT_NEAR(l1 / fr.stats.l1, 1.0, 1e-9);
        EXPECT_NEAR(worst / fr.stats.linf, 1.0, 1e-9);
        total += l1, count += n;
    }
    EXPECT_EQ(count, pass.samples.size());
    EXPECT_NEAR(total / r.stats.l1, 1.0, 1e-9);
    // Splitting helps: three frusta beat one.
    const AngleSolution single = SolveL1Exact(MakeLexelSamples(pass, scene.lexels));
    EXPECT_LT(r.stats.l1, single.objective);
}

TEST(FrustumSplit, LinfMetricIsRejected) {
    const FlatScene scene = RandomScene(1);
    const SamplingPass pass = RunSamplingPass(scene, 100);
    EXPECT_THROW(SplitLightFrustum(pass, 100, {16, 2, Metric::kLinf}, SplitStrategy::kGreedy),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lexel::flatland
