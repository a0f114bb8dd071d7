#include "lexel/solvers/polynomial.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "lexel/solvers/newton.h"

namespace lexel {
namespace {

TEST(Polynomial, QuadraticWithoutCancellation) {
    // x² − (1e8 + 1e-8) x + 1: roots 1e-8 and 1e8; the naive formula loses the small one.
    const auto roots = QuadraticRealRoots(1.0, -(1e8 + 1e-8), 1.0);
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0] / 1e-8, 1.0, 1e-15);
    EXPECT_NEAR(roots[1] / 1e8, 1.0, 1e-15);
    EXPECT_EQ(QuadraticRealRoots(1, 0, 1).size(), 0u);
    EXPECT_EQ(QuadraticRealRoots(1, -2, 1), std::vector<double>{1.0});
    EXPECT_EQ(QuadraticRealRoots(-3, 2, 0), std::vector<double>{1.5});
}

TEST(Polynomial, CompanionRootsOfKnownQuartics) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-5, 5);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<double> roots = {u(rng), u(rng), u(rng), u(rng)};
        std::sort(roots.begin(), roots.end());
        if (roots[1] - roots[0] < 1e-3 || roots[2] - roots[1] < 1e-3 || roots[3] - roots[2] < 1e-3)
            continue;
        Polynomial p = {1.0};
        for (double r : roots) p = PolyMultiply(p, std::vector<double>{-r, 1.0});
        p = PolyScale(p, 0.37);
        const auto found = PolynomialRealRoots(p);
        ASSERT_EQ(found.size(), 4u) << "trial " << trial;
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(found[k], roots[k], 1e-11) << "trial " << trial;
    }
}

TEST(Polynomial, ComplexPairsAndTrimmedLeadingTerms) {
    // (x² + 1)(x − 2) has one real root.
    const Polynomial p = PolyMultiply(std::vector<double>{1, 0, 1}, std::vector<double>{-2, 1});
    EXPECT_EQ(PolynomialRealRoots(p).size(), 1u);
    EXPECT_NEAR(PolynomialRealRoots(p)[0], 2.0, 1e-14);
    // A cubic whose leading coefficient is rounding residue is solved as the quadratic it is.
    const auto roots = PolynomialRealRoots(std::vector<double>{2, -3, 1, 1e-18});
    ASSERT_EQ(roots.size(), 2u);
    EXPECT_NEAR(roots[0], 1, 1e-14);
    EXPECT_NEAR(roots[1], 2, 1e-14);
    EXPECT_DOUBLE_EQ(EvaluatePolynomial(std::vector<double>{1, 2, 3}, 2.0), 17.0);
    EXPECT_EQ(PolyDerivative(std::vector<double>{1, 2, 3}), (Polynomial{2, 6}));
}

TEST(Newton, ConvergesQuadraticallyAndReportsLeavingTheInterval) {
    auto f = [](double x) { return std::pair<double, double>{x * x - 2, 2 * x}; };
    const NewtonResult r = NewtonRoot(f, 1.0);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x, std::sqrt(2.0), 1e-15);
    EXPECT_LE(r.iterations, 7);
    NewtonOptions bounded;
    bounded.lower = 0.0, bounded.upper = 1.2;
    EXPECT_FALSE(NewtonRoot(f, 1.0, bounded).converged);  // first step lands at 1.5
}

}  // namespace
}  // namespace lexel
