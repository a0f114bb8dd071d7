// The 95% intervals and the noise rule (statistics.h): Student's t against its published table,
// intervals against their closed forms.
#include "lexel/solvers/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace lexel {
namespace {

TEST(StudentT95, MatchesThePublishedTable) {
    // t₀.₉₇₅(ν), e.g. NIST/SEMATECH e-Handbook of Statistical Methods, Table 1.4.2.7.2 (3 decimals
    // there; ν = 1 and 2 to 1e-9 from their closed forms).
    EXPECT_NEAR(StudentT95(1), std::tan(0.475 * M_PI), 1e-9);  // 12.7062
    // ν = 2: P(|T| ≤ t) = t / √(2 + t²) = 0.95.
    EXPECT_NEAR(StudentT95(2), 0.95 * std::sqrt(2.0 / (1.0 - 0.95 * 0.95)), 1e-9);  // 4.3027
    const std::vector<std::pair<std::size_t, double>> table = {
        {3, 3.182},  {4, 2.776},  {5, 2.571},  {9, 2.262},  {10, 2.228}, {19, 2.093},
        {29, 2.045}, {30, 2.042}, {60, 2.000}, {99, 1.984}, {100, 1.984}};
    for (const auto& [dof, t] : table) EXPECT_NEAR(StudentT95(dof), t, 5e-4) << "dof " << dof;
    EXPECT_NEAR(StudentT95(1000000), 1.959964, 1e-5);  // the normal's quantile in the limit
    EXPECT_TRUE(std::isnan(StudentT95(0)));
}

TEST(MeanInterval95, IsTheMeanAndTTimesTheStandardError) {
    // 1, 2, 3, 4: mean 2.5, s² = 5/3, half-width t(3) · √(5/3 / 4).
    const std::vector<double> values = {1.0, 2.0, 3.0, 4.0};
    const MeanInterval m = MeanInterval95(values);
    EXPECT_DOUBLE_EQ(m.mean, 2.5);
    EXPECT_NEAR(m.halfWidth, StudentT95(3) * std::sqrt(5.0 / 3.0 / 4.0), 1e-12);
    EXPECT_TRUE(std::isnan(MeanInterval95(std::vector<double>{7.0}).halfWidth));
    EXPECT_DOUBLE_EQ(MeanInterval95(std::vector<double>{7.0}).mean, 7.0);
    EXPECT_TRUE(std::isnan(MeanInterval95({}).mean));
}

TEST(PairedDifference95, IsTheIntervalOfTheDifferences) {
    const std::vector<double> ours = {10.0, 12.0, 9.0}, theirs = {11.0, 15.0, 9.0};
    const MeanInterval d = PairedDifference95(ours, theirs);  // differences −1, −3, 0
    EXPECT_DOUBLE_EQ(d.mean, -4.0 / 3.0);
    // s² = ((1/3)² + (5/3)² + (4/3)²) / 2 = 7/3.
    EXPECT_NEAR(d.halfWidth, StudentT95(2) * std::sqrt(7.0 / 3.0 / 3.0), 1e-12);
    EXPECT_THROW(PairedDifference95(ours, std::vector<double>{1.0}), std::invalid_argument);
}

TEST(DifferBeyondNoise, NeedsMoreThan1_96StandardErrorsOfTheDifference) {
    // Errors 3 and 4: the difference's is 5, so 9.8 is the threshold.
    EXPECT_TRUE(DifferBeyondNoise(110.0, 3.0, 100.0, 4.0));
    EXPECT_FALSE(DifferBeyondNoise(109.0, 3.0, 100.0, 4.0));
    EXPECT_TRUE(DifferBeyondNoise(80.0, 3.0, 100.0, 4.0));  // either way
    EXPECT_FALSE(DifferBeyondNoise(std::nan(""), 3.0, 100.0, 4.0));
}

}  // namespace
}  // namespace lexel
