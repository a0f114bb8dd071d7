#include "lexel/solvers/footprint_metrics.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

TEST(FootprintMetrics, HandComputedAggregates) {
    const std::vector<double> f = {1, 2, 3, 6};
    const FootprintStats s = SummarizeFootprints(f);
    EXPECT_EQ(s.count, 4u);
    EXPECT_DOUBLE_EQ(s.l1, 12);
    EXPECT_DOUBLE_EQ(s.l2, 1 + 4 + 9 + 36);
    EXPECT_DOUBLE_EQ(s.linf, 6);
    EXPECT_DOUBLE_EQ(s.average, 3);
    // population σ: sqrt(((−2)² + (−1)² + 0 + 3²)/4) = sqrt(14/4)
    EXPECT_DOUBLE_EQ(s.sigma, std::sqrt(3.5));
    EXPECT_DOUBLE_EQ(s.meanPlusSigma, 3 + std::sqrt(3.5));
    EXPECT_DOUBLE_EQ(s.median, 2.5);
    EXPECT_DOUBLE_EQ(SummarizeFootprints(std::vector<double>{5, 1, 3}).median, 3);
}

TEST(FootprintMetrics, IntegerWeightsEqualRepetition) {
    const std::vector<double> f = {1, 2, 7}, w = {2, 0, 3};
    const FootprintStats weighted = SummarizeFootprints(f, w);
    const FootprintStats repeated = SummarizeFootprints(std::vector<double>{1, 1, 7, 7, 7});
    EXPECT_DOUBLE_EQ(weighted.l1, repeated.l1);
    EXPECT_DOUBLE_EQ(weighted.l2, repeated.l2);
    EXPECT_DOUBLE_EQ(weighted.average, repeated.average);
    EXPECT_DOUBLE_EQ(weighted.sigma, repeated.sigma);
    EXPECT_DOUBLE_EQ(weighted.linf, 7);  // the zero-weight 2 does not count
    EXPECT_DOUBLE_EQ(weighted.median, 7);
    EXPECT_EQ(weighted.count, 2u);
}

// f ∝ 1/N: scaling the lexel count by s scales L1 by 1/s and L2 by 1/s².
TEST(FootprintMetrics, LexelScaleInvariance) {
    const std::vector<double> f = {0.3, 1.7, 2.2, 0.9};
    const double s = 2.5;
    std::vector<double> scaled;
    for (double v : f) scaled.push_back(v / s);
    const FootprintStats a = SummarizeFootprints(f), b = SummarizeFootprints(scaled);
    EXPECT_DOUBLE_EQ(b.l1, a.l1 / s);
    EXPECT_NEAR(b.l2, a.l2 / (s * s), 1e-15);
    EXPECT_DOUBLE_EQ(b.linf, a.linf / s);
}

TEST(FootprintMetrics, BadInputIsAnError) {
    EXPECT_THROW(SummarizeFootprints(std::vector<double>{1, NAN}), std::invalid_argument);
    EXPECT_THROW(SummarizeFootprints(std::vector<double>{1, -1}), std::invalid_argument);
    EXPECT_THROW(SummarizeFootprints(std::vector<double>{1, 2}, std::vector<double>{1}),
                 std::invalid_argument);
    EXPECT_EQ(SummarizeFootprints(std::vector<double>{}).count, 0u);
    EXPECT_FALSE(ParseMetric("l3"));
    EXPECT_EQ(ParseMetric("linf"), Metric::kLinf);
}

TEST(JacobianBadness, DiagonalClosedForms) {
    Eigen::Matrix2d j;
    j << 2, 0, 0, 4;  // J⁻¹ = diag(1/2, 1/4)
    EXPECT_DOUBLE_EQ(JacobianBadness(j, Badness::kFrobeniusInverseSquared), 0.25 + 0.0625);
    EXPECT_DOUBLE_EQ(JacobianBadness(j, Badness::kGeometricStretch),
                     std::sqrt((0.25 + 0.0625) / 2));
    EXPECT_DOUBLE_EQ(JacobianBadness(j, Badness::kLargestSingularValue), 0.5);
}

// Badness depends only on the singular values: rotating screen or map leaves it unchanged.
TEST(JacobianBadness, RotationInvariance) {
    Eigen::Matrix2d j;
    j << 1.3, -0.4, 0.7, 2.1;
    for (double angle : {0.3, 1.1, -2.0}) {
        Eigen::Matrix2d r;
        r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        for (auto b : {Badness::kFrobeniusInverseSquared, Badness::kGeometricStretch,
                       Badness::kLargestSingularValue}) {
            EXPECT_NEAR(JacobianBadness(r * j, b), JacobianBadness(j, b), 1e-14);
            EXPECT_NEAR(JacobianBadness(j * r, b), JacobianBadness(j, b), 1e-14);
        }
    }
    // Frobenius of J⁻¹ equals σ1² + σ2² of J⁻¹, i.e. 1/s1² + 1/s2² for J's singular values s.
    const Eigen::Vector2d s = SingularValues2x2(j);
    EXPECT_NEAR(JacobianBadness(j, Badness::kFrobeniusInverseSquared),
                1 / (s[0] * s[0]) + 1 / (s[1] * s[1]), 1e-14);
    EXPECT_NEAR(s[0] * s[1], std::abs(j.determinant()), 1e-14);
}

TEST(JacobianBadness, SingularJacobianIsInfiniteNotNaN) {
    Eigen::Matrix2d j;
    j << 1, 2, 2, 4;
    EXPECT_EQ(JacobianBadness(j, Badness::kFrobeniusInverseSquared),
              std::numeric_limits<double>::infinity());
    EXPECT_EQ(JacobianBadness(Eigen::Matrix2d::Zero(), Badness::kLargestSingularValue),
              std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace lexel
