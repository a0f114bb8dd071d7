// optimal-oracle: the compass search finds a known best axis, and on a shipped scene
// the oracle's measured error is at most every fair single-map method's (it starts from their
// matrices, scored on held-out phases).
#include "lexel/spatial/harness/oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {
namespace {

double AngleDeg(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) *
           180.0 / 3.14159265358979323846;
}

// A scorer whose best matrix is the one with axis `target`: the search, started 7° away, ends
// within its final step (0.25°) times √2 (the compass moves along two axes) of it.
TEST(OracleSearch, CompassSearchFindsTheBestAxis) {
    std::vector<glm::dvec3> lsPoints;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j) lsPoints.push_back({0.05 * i, 0.05 * j, 1.0});
    const std::optional<RelevantHull> hull = RelevantHull::Of(lsPoints, {0, 0, 1});
    ASSERT_TRUE(hull);
    const glm::dvec3 target = glm::normalize(glm::dvec3(0.06, -0.03, 1.0));
    const glm::dvec3 startAxis = RotateAxis(target, {1, 0, 0}, 7.0 * 3.14159265358979 / 180.0);
    LightMatrix start;
    start.p4 = startAxis;
    const OracleStart starts[] = {{"start", start}};
    const auto score = [&](const LightMatrix& m) { return AngleDeg(m.p4, target); };
    OracleOptions options;
    options.budget = 400;
    const OracleResult r = SearchOracleMatrix(starts, *hull, {64, 64}, score, options);
    EXPECT_LT(r.score, 0.25 * std::sqrt(2.0)) << "after " << r.scored << " candidates";
    EXPECT_LE(r.scored, options.budget);
    EXPECT_EQ(r.start, "start");  // its re-fit for the same axis scores the same, not better
}

TEST(OracleSearch, StopsAtItsBudget) {
    std::vector<glm::dvec3> lsPoints = {{-0.1, -0.1, 1}, {0.1, -0.1, 1}, {0, 0.1, 1}};
    const std::optional<RelevantHull> hull = RelevantHull::Of(lsPoints, {0, 0, 1});
    ASSERT_TRUE(hull);
    int calls = 0;
    const auto score = [&](const LightMatrix&) { return static_cast<double>(-++calls); };
    OracleOptions options;
    options.budget = 10;
    const OracleStart starts[] = {{"a", LightMatrix{}}};
    const OracleResult r = SearchOracleMatrix(starts, *hull, {32, 32}, score, options);
    EXPECT_EQ(r.scored, 10);
    EXPECT_EQ(calls, 10);
    EXPECT_EQ(r.score, -10.0);
}

// The fair single maps and the oracle on the walkthrough's first sweep light at K phases.
LightOutcome FairMapsAndOracle(int phases, int maxPhases = 0) {
    static const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) /
                                                       "spatial/walkthrough.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = FairMethodNames();
    options.methods.push_back(kOracleMethod);
    options.phases = phases;
    options.maxPhases = maxPhases;
    return evaluator.Evaluate(cases::SweepLightsOf(scene, 1).front(), options);
}

// The oracle chooses its matrix on phases held out of the reported mean (HeldOutSubTexelPhases),
// so it is not at most every start by construction: at 2 phases, where the choice is mostly the
// grid's luck, it measures 792.5 on this light against optimal's 780 (chosen on the reported
// phases, as before, it would be at most every start's mean: the winner's curse the held-out
// phases keep out of the bound).
TEST(OracleMethod, IsChosenOnHeldOutPhases) {
    const LightOutcome o = FairMapsAndOracle(2);
    const MethodOutcome& oracle = o.methods.back();
    ASSERT_EQ(oracle.method, kOracleMethod);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < o.methods.size(); ++k)
        best = std::min(best, o.methods[k].metrics.misclassifiedMean);
    EXPECT_GT(oracle.metrics.misclassifiedMean, best);
}

// At 8 phases the oracle measures at most every fair single map on the reported phases.
TEST(OracleMethod, MeasuresAtMostEveryFairSingleMapAtEightPhases) {
    const LightOutcome o = FairMapsAndOracle(8);
    const MethodOutcome& oracle = o.methods.back();
    ASSERT_EQ(oracle.method, kOracleMethod);
    EXPECT_FALSE(oracle.trace.winner.empty());
    for (const MethodOutcome& m : o.methods)
        EXPECT_LE(oracle.metrics.misclassifiedMean, m.metrics.misclassifiedMean) << m.method;
}

// From 2 phases raised to settle (up to 32), the oracle's candidates and every reported mean
// alike, the 2-phase choice above (792.5 against optimal's 780, beyond the noise of 2 phases) is
// no longer luck: no fair single map measures below it beyond the noise of the two means (1.96
// standard errors of their difference; measured 774.2 against lispsm-tight's 770.8 ± 15).
TEST(OracleMethod, WithAdaptivePhasesNoFairSingleMapIsBelowItBeyondTheNoise) {
    const LightOutcome o = FairMapsAndOracle(2, 32);
    const MethodOutcome& oracle = o.methods.back();
    ASSERT_EQ(oracle.method, kOracleMethod);
    EXPECT_GT(oracle.metrics.phases, 2);
    for (const MethodOutcome& m : o.methods) {
        const double noise =
            1.96 * std::hypot(oracle.metrics.misclassifiedError, m.metrics.misclassifiedError);
        EXPECT_LE(oracle.metrics.misclassifiedMean, m.metrics.misclassifiedMean + noise)
            << m.method << " at " << m.metrics.phases << " phases";
    }
}

}  // namespace
}  // namespace lexel::spatial
