// PredictAverageFromRows (flatland/studies/table_consistency.h): on lexel's own numbers the window
// holds the true half sweep and the true average at a third angle; on the thesis's printed tables
// the PSM row's average is predicted from the Normal and L1 rows.
#include "lexel/flatland/studies/table_consistency.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/geometry.h"
#include "test_scenes.h"

namespace lexel::flatland {
namespace {

TEST(TableConsistency, WindowHoldsTheTruthOnRandomScenes) {
    int checked = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        FlatScene scene = testing::RandomScene(seed, 400);
        scene.decisionPixels = 0;  // the L1 optimum of exactly the measured pixels
        const std::vector<std::string> methods = {"normal", "optimal-l1"};
        const CaseReport report = RunFlatlandCase(scene, methods, Metric::kL1);
        const MethodReport& normal = report.methods[0];
        const MethodReport& l1 = report.methods[1];
        // The average at a third valid angle, a third of the way from Normal to the optimum's far
        // side.
        const LexelSamples samples = MakeLexelSamples(*report.fullPass, scene.lexels);
        const ValidInterval valid = ValidTInterval(samples);
        const double t = valid.lo + 0.7 * (valid.hi - valid.lo);
        double other = 0.0;
        for (double f : RemappedFootprints(samples, t)) other += f;
        other /= samples.size();
        const double otherDeg = LexelPlaneDegFromAxis(WsAxisFromT(samples, t));
        if (std::abs(std::remainder(l1.lexelPlaneDeg - normal.lexelPlaneDeg, 180.0)) < 0.5)
            continue;  // the optimum at the Normal angle says nothing about the sweep
        const SweepWindow w =
            PredictAverageFromRows(normal.lexelPlaneDeg, normal.stats.average, l1.lexelPlaneDeg,
                                   l1.stats.average, otherDeg, 200000);
        const double halfSweepDeg = Degrees(report.fullPass->halfSweep);
        ASSERT_TRUE(w.feasible) << testing::Describe(scene);
        EXPECT_GE(halfSweepDeg, w.halfSweepLoDeg - 0.01) << testing::Describe(scene);
        EXPECT_LE(halfSweepDeg, w.halfSweepHiDeg + 0.01) << testing::Describe(scene);
        EXPECT_GE(other, w.predictedLo * (1 - 1e-4)) << testing::Describe(scene);
        EXPECT_LE(other, w.predictedHi * (1 + 1e-4)) << testing::Describe(scene);
        ++checked;
    }
    EXPECT_GE(checked, 8);
}

// Chong 2003, §4.1.3: the printed Perspective SM averages follow from the Normal and L1 rows
// through the remapping alone, under any geometry.
TEST(TableConsistency, ThesisPsmAveragesFollowFromTheOtherRows) {
    // Light from Top: printed 44.4; the sweep must be 2 × 11.2°–11.6° with the footprint mass at
    // its edge.
    const SweepWindow top = PredictAverageFromRows(83.1, 46.2, 5.11, 3.38, 77.3);
    ASSERT_TRUE(top.feasible);
    EXPECT_NEAR(top.predictedLo, 44.386, 0.001);
    EXPECT_NEAR(top.predictedHi, 44.387, 0.001);
    EXPECT_NEAR(top.halfSweepLoDeg, 11.18, 0.01);
    EXPECT_NEAR(top.halfSweepHiDeg, 11.57, 0.01);
    EXPECT_GT(top.edgeConcentrationLo, 0.96);
    // Projection Aliasing: printed 22.1.
    const SweepWindow aliasing = PredictAverageFromRows(83.7, 25.3, 33.9, 17.7, 67.7);
    ASSERT_TRUE(aliasing.feasible);
    EXPECT_NEAR(aliasing.predictedLo, 22.109, 0.001);
    EXPECT_NEAR(aliasing.predictedHi, 22.141, 0.001);
    // Single Plane: printed 1.88 lies inside the predicted 1.817–1.889.
    const SweepWindow plane = PredictAverageFromRows(51, 1.17, 9, 0.96, 91);
    ASSERT_TRUE(plane.feasible);
    EXPECT_LT(plane.predictedLo, 1.88);
    EXPECT_GT(plane.predictedHi, 1.88);
    // A misprinted L1 average (above Normal's) is no optimum of any pixel set.
    EXPECT_FALSE(PredictAverageFromRows(83.1, 46.2, 5.11, 50.0, 77.3).feasible);
}

}  // namespace
}  // namespace lexel::flatland
