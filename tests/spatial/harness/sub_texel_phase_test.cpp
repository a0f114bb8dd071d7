// Sub-texel phase averaging: the phases, the mean and its standard error, and the
// Evaluator's phase means against a brute-force reference (each phase's map measured alone).
#include "lexel/spatial/harness/sub_texel_phase.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <span>
#include <stdexcept>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {
namespace {

TEST(SubTexelPhases, StartUnshiftedAndStayWithinHalfATexel) {
    const std::vector<glm::dvec2> phases = SubTexelPhases(64);
    ASSERT_EQ(phases.size(), 64u);
    EXPECT_EQ(phases[0], glm::dvec2(0.0));
    for (const glm::dvec2& d : phases) {
        EXPECT_GE(d.x, -0.5);
        EXPECT_LT(d.x, 0.5);
        EXPECT_GE(d.y, -0.5);
        EXPECT_LT(d.y, 0.5);
    }
    // A larger K extends a smaller one.
    const std::vector<glm::dvec2> first = SubTexelPhases(16);
    for (std::size_t k = 0; k < first.size(); ++k) EXPECT_EQ(first[k], phases[k]);
    EXPECT_THROW(SubTexelPhases(0), std::invalid_argument);
}

// The oracle's phases are the next K of the sequence: none is among the K the mean is reported
// over, and they cover the texel as well (each quarter of the square holds 4 ± 2 of 16).
TEST(SubTexelPhases, HeldOutAreTheNextKAndNoneOfTheReported) {
    for (const int k : {1, 2, 16}) {
        const std::vector<glm::dvec2> reported = SubTexelPhases(k);
        const std::vector<glm::dvec2> heldOut = HeldOutSubTexelPhases(k);
        const std::vector<glm::dvec2> both = SubTexelPhases(2 * k);
        ASSERT_EQ(heldOut.size(), static_cast<std::size_t>(k));
        for (int i = 0; i < k; ++i) {
            EXPECT_EQ(heldOut[i], both[k + i]) << "K " << k << ", phase " << i;
            for (const glm::dvec2& r : reported) EXPECT_NE(heldOut[i], r) << "K " << k;
        }
    }
    int quarters[2][2] = {};
    for (const glm::dvec2& d : HeldOutSubTexelPhases(16)) ++quarters[d.x >= 0.0][d.y >= 0.0];
    for (const auto& row : quarters)
        for (int n : row) {
            EXPECT_GE(n, 2);
            EXPECT_LE(n, 6);
        }
    EXPECT_THROW(HeldOutSubTexelPhases(0), std::invalid_argument);
}

// R2 covers the square evenly: of the first 64, each of the 4 × 4 cells holds 4 ± 2, and the
// mean of each coordinate is within a low-discrepancy set's quadrature error, ln N / N = 0.065,
// of a uniform phase's 0 (measured 0.018; 64 independent uniform phases give 0.036 typically).
TEST(SubTexelPhases, CoverTheTexelEvenly) {
    const std::vector<glm::dvec2> phases = SubTexelPhases(64);
    int cells[4][4] = {};
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& d : phases) {
        ++cells[static_cast<int>((d.x + 0.5) * 4)][static_cast<int>((d.y + 0.5) * 4)];
        mean += d / 64.0;
    }
    for (const auto& row : cells)
        for (int n : row) {
            EXPECT_GE(n, 2);
            EXPECT_LE(n, 6);
        }
    EXPECT_LT(std::abs(mean.x), std::log(64.0) / 64.0);
    EXPECT_LT(std::abs(mean.y), std::log(64.0) / 64.0);
}

TEST(MeanOverPhases, IsTheMeanAndItsStandardError) {
    const std::int64_t counts[] = {10, 12, 14};
    const PhaseMean m = MeanOverPhases(counts);
    EXPECT_DOUBLE_EQ(m.mean, 12.0);
    // s = 2 (the sample standard deviation), s / √3.
    EXPECT_DOUBLE_EQ(m.standardError, 2.0 / std::sqrt(3.0));
    const std::int64_t one[] = {7};
    EXPECT_EQ(MeanOverPhases(one).mean, 7.0);
    EXPECT_EQ(MeanOverPhases(one).standardError, 0.0);
}

// SubTexelPhases(n, first) is the slice [first, first + n) of the one sequence.
TEST(SubTexelPhases, FromFirstAreTheSequenceFromThere) {
    const std::vector<glm::dvec2> all = SubTexelPhases(40);
    const std::vector<glm::dvec2> slice = SubTexelPhases(8, 32);
    ASSERT_EQ(slice.size(), 8u);
    for (std::size_t k = 0; k < slice.size(); ++k) EXPECT_EQ(slice[k], all[32 + k]) << k;
    EXPECT_THROW(SubTexelPhases(4, -1), std::invalid_argument);
}

// Settled: a standard error of at most 2% of the mean, or of at most one pixel.
TEST(PhaseMeanSettled, TwoPercentOfTheMeanOrOnePixel) {
    EXPECT_TRUE(PhaseMeanSettled({1000.0, 20.0}));
    EXPECT_FALSE(PhaseMeanSettled({1000.0, 20.01}));
    EXPECT_TRUE(PhaseMeanSettled({10.0, 1.0}));  // 10% of the mean, but a pixel
    EXPECT_FALSE(PhaseMeanSettled({10.0, 1.01}));
    EXPECT_TRUE(PhaseMeanSettled({0.0, 0.0}));
}

// Counts alternating 90, 110 over n phases (n even): mean 100, s = 10 √(n/(n−1)), so the standard
// error is 10/√(n−1): 2.58 at 16 (not settled), 1.80 at 32. From K = 4 the measurement doubles
// to 8, 16, 32 and stops there; capped at 24 it stops at 16 + 8; with no cap above K it is K.
TEST(CountOverPhases, DoublesUntilSettledUpToTheMost) {
    std::vector<int> visited;
    const auto alternating = [&](int k, const glm::dvec2& phase) -> std::int64_t {
        visited.push_back(k);
        EXPECT_EQ(phase, SubTexelPhases(1, k).front()) << "phase " << k;
        return k % 2 == 0 ? 90 : 110;
    };
    const std::vector<std::int64_t> counts = CountOverPhases(4, 256, 6, alternating);
    EXPECT_EQ(counts.size(), 32u);
    ASSERT_EQ(visited.size(), 32u);
    for (int i = 0; i < 32; ++i) EXPECT_EQ(visited[i], 6 + i);  // each phase once, in order
    EXPECT_NEAR(MeanOverPhases(counts).standardError, 10.0 / std::sqrt(31.0), 1e-12);
    EXPECT_EQ(CountOverPhases(4, 24, 0, alternating).size(), 24u);
    EXPECT_EQ(CountOverPhases(4, 0, 0, alternating).size(), 4u);
    EXPECT_EQ(CountOverPhases(4, 4, 0, alternating).size(), 4u);
    // Already settled at K: a constant count is measured K times.
    EXPECT_EQ(CountOverPhases(4, 256, 0, [](int, const glm::dvec2&) { return 500; }).size(), 4u);
    EXPECT_THROW(CountOverPhases(0, 4, 0, alternating), std::invalid_argument);
}

const Scene& Walkthrough() {
    static const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) /
                                                       "spatial/walkthrough.json");
    return scene;
}

// A single map's phase mean is the mean of the same matrix moved by each phase and measured alone
// (Evaluator::Misclassified); phase 0 is the count of one measurement, bit for bit.
TEST(EvaluatorPhases, SingleMapMeanIsTheMeanOfShiftedMatrices) {
    const Scene& scene = Walkthrough();
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions once, phased;
    once.methods = phased.methods = {"focused-tight", "lispsm-tight"};
    phased.phases = 5;
    const std::vector<glm::dvec2> phases = SubTexelPhases(5);
    for (const Light& light : cases::SweepLightsOf(scene, 2)) {
        const LightOutcome a = evaluator.Evaluate(light, once);
        const LightOutcome b = evaluator.Evaluate(light, phased);
        EXPECT_EQ(b.phases, 5);
        for (std::size_t m = 0; m < a.methods.size(); ++m) {
            const MethodOutcome& mo = b.methods[m];
            EXPECT_EQ(a.methods[m].metrics.misclassified, mo.metrics.misclassified) << mo.method;
            EXPECT_EQ(a.methods[m].metrics.misclassifiedMean,
                      static_cast<double>(a.methods[m].metrics.misclassified));
            EXPECT_EQ(a.methods[m].metrics.misclassifiedError, 0.0);
            std::vector<std::int64_t> counts;
            for (const glm::dvec2& d : phases)
                counts.push_back(evaluator.Misclassified(light, mo.matrix.Shifted(d)));
            const PhaseMean expected = MeanOverPhases(counts);
            EXPECT_EQ(mo.metrics.misclassifiedMean, expected.mean) << mo.method;
            EXPECT_EQ(mo.metrics.misclassifiedError, expected.standardError) << mo.method;
            // The phases move the count (an edge quantized to texels moves with them).
            EXPECT_GT(mo.metrics.misclassifiedError, 0.0) << mo.method;
        }
    }
}

// With adaptive phases each method's mean is over its own first 2^j K phases (the brute-force mean
// of the shifted matrices, each measured alone): settled there, or at the most; and not settled
// at half as many, or it would have stopped.
TEST(EvaluatorPhases, AdaptiveMeanIsOverTheFirstPhasesThatSettleIt) {
    const Scene& scene = Walkthrough();
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"focused-tight", "lispsm-tight", "normal"};
    options.phases = 2;
    options.maxPhases = 16;
    const Light light = cases::SweepLightsOf(scene, 1).front();
    const LightOutcome o = evaluator.Evaluate(light, options);
    EXPECT_EQ(o.phases, 2);
    EXPECT_EQ(o.maxPhases, 16);
    int raised = 0;
    for (const MethodOutcome& mo : o.methods) {
        const int k = mo.metrics.phases;
        ASSERT_TRUE(k == 2 || k == 4 || k == 8 || k == 16) << mo.method << ": " << k;
        raised += k > 2;
        std::vector<std::int64_t> counts;
        for (const glm::dvec2& d : SubTexelPhases(k))
            counts.push_back(evaluator.Misclassified(light, mo.matrix.Shifted(d)));
        const PhaseMean expected = MeanOverPhases(counts);
        EXPECT_EQ(mo.metrics.misclassifiedMean, expected.mean) << mo.method;
        EXPECT_EQ(mo.metrics.misclassifiedError, expected.standardError) << mo.method;
        EXPECT_TRUE(k == 16 || PhaseMeanSettled(expected)) << mo.method;
        if (k > 2) {
            const std::span<const std::int64_t> half(counts.data(), counts.size() / 2);
            EXPECT_FALSE(PhaseMeanSettled(MeanOverPhases(half))) << mo.method;
        }
    }
    EXPECT_GT(raised, 0);  // two phases leave some mean unsettled on this light
}

// Cascades, a virtual map's pages and a warped map move with the phase too: phase 0 keeps the
// single measurement, the mean is over counts that differ.
TEST(EvaluatorPhases, CascadesPagesAndWarpsMoveWithThePhase) {
    const Scene& scene = Walkthrough();
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions once, phased;
    once.methods = phased.methods = {"sdsm", "vsm", "rtw"};
    phased.phases = 4;
    const Light light = cases::SweepLightsOf(scene, 1).front();
    const LightOutcome a = evaluator.Evaluate(light, once);
    const LightOutcome b = evaluator.Evaluate(light, phased);
    for (std::size_t m = 0; m < a.methods.size(); ++m) {
        const MethodOutcome& mo = b.methods[m];
        EXPECT_EQ(a.methods[m].metrics.misclassified, mo.metrics.misclassified) << mo.method;
        EXPECT_GT(mo.metrics.misclassifiedError, 0.0) << mo.method;
        EXPECT_GT(mo.metrics.misclassifiedMean, 0.0) << mo.method;
        EXPECT_LE(mo.metrics.falseShadowMean, mo.metrics.misclassifiedMean) << mo.method;
    }
}

}  // namespace
}  // namespace lexel::spatial
