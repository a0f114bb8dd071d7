#include "lexel/solvers/lagrange_allocation.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>
#include <stdexcept>

#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

// The real allocation is the Lagrange closed form and achieves (Σ e^(1/(k+1)))^(k+1) / L^k.
TEST(LagrangeAllocation, RealClosedForm) {
    const std::vector<double> e = {4.0, 1.0, 9.0};
    for (int k : {1, 2}) {
        const auto x = AllocateLexelsReal(e, k, 120);
        EXPECT_NEAR(std::accumulate(x.begin(), x.end(), 0.0), 120, 1e-12);
        double total = 0, termSum = 0;
        for (std::size_t j = 0; j < e.size(); ++j)
            total += e[j] / std::pow(x[j], k), termSum += AllocationTerm(e[j], k);
        EXPECT_NEAR(total, AllocatedTotal(termSum, k, 120), 1e-12);
        // Stationarity: k e_j / x_j^(k+1) is the same multiplier λ for every frustum.
        for (std::size_t j = 1; j < e.size(); ++j)
            EXPECT_NEAR(k * e[j] / std::pow(x[j], k + 1), k * e[0] / std::pow(x[0], k + 1), 1e-12);
    }
    // L1 with e = (4, 1, 9): x ∝ (2, 1, 3).
    const auto x = AllocateLexelsReal(e, 1, 120);
    EXPECT_NEAR(x[0], 40, 1e-12);
    EXPECT_NEAR(x[1], 20, 1e-12);
    EXPECT_NEAR(x[2], 60, 1e-12);
}

// Moving one lexel between any two frusta never lowers the integer allocation's total.
TEST(LagrangeAllocation, IntegerAllocationIsExchangeOptimal) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const int n = 1 + trial % 7;
        std::vector<double> e(n);
        for (double& v : e) v = u(rng) < 0.15 ? 0.0 : std::pow(10.0, -3 + 6 * u(rng));
        const int occupied =
            static_cast<int>(std::count_if(e.begin(), e.end(), [](double v) { return v > 0; }));
        const int lexels = std::max(occupied, 1) + static_cast<int>(200 * u(rng));
        for (int k : {1, 2}) {
            const auto alloc = AllocateLexelsInteger(e, k, lexels);
            ASSERT_EQ(std::accumulate(alloc.begin(), alloc.end(), 0), lexels) << "trial " << trial;
            const double total = AllocationError(e, alloc, k);
            for (int j = 0; j < n; ++j) {
                if (e[j] > 0) {
                    EXPECT_GE(alloc[j], 1);
                }
                for (int i = 0; i < n; ++i) {
                    if (i == j || alloc[j] <= (e[j] > 0 ? 1 : 0)) continue;
                    auto moved = alloc;
                    --moved[j], ++moved[i];
                    EXPECT_GE(AllocationError(e, moved, k), total * (1 - 1e-12))
                        << "trial " << trial;
                }
            }
        }
    }
}

TEST(LagrangeAllocation, TooFewLexelsIsAnError) {
    EXPECT_THROW(AllocateLexelsInteger(std::vector<double>{1, 2, 3}, 1, 2), std::invalid_argument);
}

}  // namespace
}  // namespace lexel
