#include "lexel/flatland/angle_solvers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lexel/flatland/baselines.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/errors.h"
#include "test_scenes.h"

namespace lexel::flatland {
namespace {

using testing::Describe;
using testing::RandomScene;
using testing::SingleSegmentScene;

double Deg(double radians) { return radians * 180.0 / std::numbers::pi; }

// Theorem 1: on a single segment, every optimum makes the footprint constant, at the geometric
// angle (lexel plane parallel to the line from the light to the segment's view-plane point).
TEST(AngleSolvers, Theorem1SingleSegmentGivesConstantFootprint) {
    for (std::uint64_t seed = 0; seed < 25; ++seed) {
        const FlatScene scene = SingleSegmentScene(seed);
        SCOPED_TRACE(Describe(scene));
        const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "optimal-linf",
                                                  "plane-optimal"};
        const CaseReport report = RunFlatlandCase(scene, methods, Metric::kL1);
        const double geometric = report.methods[3].lexelPlaneDeg;
        for (int m = 0; m < 3; ++m) {
            const auto& r = report.methods[m];
            EXPECT_LT(r.stats.worst() / r.stats.average - 1.0, 1e-9) << r.method;
            double diff = std::remainder(r.lexelPlaneDeg - geometric, 180.0);
            EXPECT_LT(std::abs(diff), 1e-7)
                << r.method << " " << r.lexelPlaneDeg << " vs " << geometric;
        }
    }
}

// The exact solvers never lose to the dense sweep (which refines its best cell), and the three
// L2 solvers agree, over 200 seeded random scenes.
TEST(AngleSolvers, OptimaMatchSweepOnRandomScenes) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        const FlatScene scene = RandomScene(seed, 160);
        SCOPED_TRACE(Describe(scene));
        const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
        const LexelSamples samples = MakeLexelSamples(pass, scene.lexels);
        SweepOptions sweepOptions;
        sweepOptions.cells = 1024;
        const AngleSolution l1 = SolveL1Exact(samples);
        const AngleSolution l2 = SolveL2Exact(samples);
        const AngleSolution linf = SolveLinfExact(samples);
        EXPECT_LE(l1.objective,
                  SolveSweep(samples, Metric::kL1, sweepOptions).objective * (1 + 1e-6));
        EXPECT_LE(l2.objective,
                  SolveSweep(samples, Metric::kL2, sweepOptions).objective * (1 + 1e-6));
        EXPECT_LE(linf.objective,
                  SolveSweep(samples, Metric::kLinf, sweepOptions).objective * (1 + 1e-6));
        EXPECT_TRUE(l1.note.empty() && l2.note.empty() && linf.note.empty());
        const AngleSolution newton = SolveL2Newton(samples);
        const AngleSolution ceres = SolveL2Ceres(samples);
        EXPECT_NEAR(newton.objective / l2.objective, 1.0, 1e-9);
        EXPECT_NEAR(ceres.objective / l2.objective, 1.0, 1e-9);
        // Objectives reported are the direct per-sample sums at the returned angle.
        EXPECT_DOUBLE_EQ(l1.objective, AngleObjective(samples, Metric::kL1, l1.t));
    }
}

// L∞ is exact: its objective equals the sweep's to the sweep's refinement, and its angle to 1e-9°.
TEST(AngleSolvers, LinfAngleMatchesGoldenSectionToNanodegrees) {
    for (std::uint64_t seed = 0; seed < 30; ++seed) {
        const FlatScene scene = RandomScene(seed, 200);
        SCOPED_TRACE(Describe(scene));
        const LexelSamples samples = MakeLexelSamples(RunSamplingPass(scene, 200), scene.lexels);
        const AngleSolution linf = SolveLinfExact(samples);
        SweepOptions fine;
        fine.cells = 4096;
        fine.refineIterations = 200;
        const AngleSolution sweep = SolveSweep(samples, Metric::kLinf, fine);
        EXPECT_LE(linf.objective, sweep.objective * (1 + 1e-12));
        EXPECT_LT(std::abs(Deg(std::atan(linf.t) - std::atan(sweep.t))), 1e-6);
        // Moving 1e-9° either way never lowers the maximum.
        const double x = std::atan(linf.t), step = 1e-9 * std::numbers::pi / 180;
        EXPECT_GE(AngleObjective(samples, Metric::kLinf, std::tan(x + step)),
                  linf.objective * (1 - 1e-15));
        EXPECT_GE(AngleObjective(samples, Metric::kLinf, std::tan(x - step)),
                  linf.objective * (1 - 1e-15));
    }
}

// A uniform scale of the lexel count scales L1 by 1/s and L2 by 1/s², and moves no optimum.
TEST(AngleSolvers, LexelScaleScalesMetricsAndKeepsAngles) {
    FlatScene scene = RandomScene(7);
    const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "optimal-linf", "normal"};
    const CaseReport a = RunFlatlandCase(scene, methods, Metric::kL1);
    scene.lexels *= 4;
    const CaseReport b = RunFlatlandCase(scene, methods, Metric::kL1);
    for (std::size_t m = 0; m < methods.size(); ++m) {
        EXPECT_NEAR(b.methods[m].stats.l1 * 4 / a.methods[m].stats.l1, 1.0, 1e-12);
        EXPECT_NEAR(b.methods[m].stats.l2 * 16 / a.methods[m].stats.l2, 1.0, 1e-12);
        EXPECT_NEAR(b.methods[m].lexelPlaneDeg, a.methods[m].lexelPlaneDeg, 1e-9);
    }
}

// decision_pixels changes only the decision: the same full-resolution pixels are measured, the
// normal angle is unchanged, and no decision beats the full-resolution optimum.
TEST(AngleSolvers, DecisionPixelsChangeOnlyTheDecision) {
    FlatScene scene = testing::ExampleScene();
    const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "normal"};
    const CaseReport full = RunFlatlandCase(scene, methods, Metric::kL1);
    scene.decisionPixels = 20;
    const CaseReport low = RunFlatlandCase(scene, methods, Metric::kL1);
    EXPECT_EQ(low.pixelsVisible, full.pixelsVisible);
    EXPECT_EQ(low.methods[0].stats.count, full.methods[0].stats.count);
    EXPECT_GE(low.methods[0].stats.l1, full.methods[0].stats.l1 * (1 - 1e-12));
    EXPECT_GE(low.methods[1].stats.l2, full.methods[1].stats.l2 * (1 - 1e-12));
    EXPECT_NE(low.methods[0].lexelPlaneDeg, full.methods[0].lexelPlaneDeg);
    // normal bisects the decision pass's (coarser) sweep: close to, not equal to, the full one
    EXPECT_NEAR(low.methods[2].lexelPlaneDeg, full.methods[2].lexelPlaneDeg, 5.0);
}

// Every method's returned angle is valid at full resolution: all footprints finite.
TEST(AngleSolvers, NoReturnedAngleIsInvalid) {
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        FlatScene scene = RandomScene(seed, 200);
        scene.decisionPixels = 15 + static_cast<int>(seed);
        SCOPED_TRACE(Describe(scene));
        CaseReport report;
        try {
            report = RunFlatlandCase(scene, FlatlandMethodNames(), Metric::kL2);
        } catch (const DomainError&) {
            continue;  // too few decision pixels see geometry for this scene
        }
        for (const auto& m : report.methods) {
            EXPECT_TRUE(std::isfinite(m.stats.worst())) << m.method;
            EXPECT_GT(m.stats.worst(), 0.0) << m.method;
            EXPECT_EQ(m.stats.count, static_cast<std::size_t>(report.pixelsVisible)) << m.method;
        }
    }
}

TEST(AngleSolvers, NewtonRestartsAreSeededAndDeterministic) {
    const FlatScene scene = RandomScene(3);
    const LexelSamples samples = MakeLexelSamples(RunSamplingPass(scene, 240), scene.lexels);
    const AngleSolution a = SolveL2Newton(samples), b = SolveL2Newton(samples);
    EXPECT_EQ(a.t, b.t);
    EXPECT_GT(a.iterations, 0);
}

}  // namespace
}  // namespace lexel::flatland
