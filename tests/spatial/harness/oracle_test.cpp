// optimal-oracle (issue 25): the compass search finds a known best axis, and on a shipped scene
// the oracle's measured error is at most every fair single-map method's (it starts from their
// matrices, scored on held-out phases).
#include "lexel/spatial/harness/oracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

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

// The oracle chooses its matrix on phases held out of the reported mean (HeldOutSubTexelPhases),
// so it is no longer at most every start by construction; at 2 phases it is not on this light
// (792.5 against optimal's 780: with two phases the choice is mostly the grid's luck, the winner's
// curse the held-out phases keep out of the bound). At 8 phases it measures at most every fair
// single map on the reported ones.
TEST(OracleMethod, MeasuresAtMostEveryFairSingleMapAtEightPhases) {
    static const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) /
                                                       "spatial/walkthrough.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = FairMethodNames();
    options.methods.push_back(kOracleMethod);
    options.phases = 8;
    const LightOutcome o = evaluator.Evaluate(cases::SweepLightsOf(scene, 1).front(), options);
    const MethodOutcome& oracle = o.methods.back();
    ASSERT_EQ(oracle.method, kOracleMethod);
    EXPECT_FALSE(oracle.trace.winner.empty());
    for (const MethodOutcome& m : o.methods)
        EXPECT_LE(oracle.metrics.misclassifiedMean, m.metrics.misclassifiedMean) << m.method;
}

}  // namespace
}  // namespace lexel::spatial
