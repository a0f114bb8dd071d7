// The warp abstraction (map_warp.h) and rectilinear texture warping (rtw.h): each axis warp is a
// strictly increasing bijection whose inverse and slope agree with it (finite differences), a
// linear MapWarp is its light matrix texel for texel, a warp's Jacobian is the finite
// difference of Forward, and RTW's warps (Rosen 2012) are monotone, map [0, 1] onto [0, 1] and
// give each bin texels in proportion to its blurred importance.
#include "lexel/spatial/map_warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "lexel/spatial/rtw.h"

namespace lexel::spatial {
namespace {

LightMatrix SomeProjectiveMatrix() {
    LightMatrix m;
    m.p1 = {310.0, 12.0, 190.0};
    m.p2 = {-8.0, 295.0, 205.0};
    m.p4 = glm::normalize(glm::dvec3(0.12, -0.07, 1.0));
    return m;
}

std::vector<AxisWarp> SomeAxisWarps() {
    return {AxisWarp(), AxisWarp::Affine(2.5, -7.0),
            AxisWarp::Piecewise(0.0, 400.0, {0.0, 10.0, 150.0, 160.0, 400.0}),
            AxisWarp::Logarithmic(-50.0, 1.0, 120.0, -300.0),
            AxisWarp::Logarithmic(900.0, -1.0, 80.0, 40.0)};
}

TEST(AxisWarp, InverseAndSlopeAgreeWithApply) {
    for (const AxisWarp& w : SomeAxisWarps()) {
        for (double b = -100.0; b <= 500.0; b += 7.3) {
            if (w.kind() == AxisWarp::Kind::kLogarithmic && w.sign() * (b - w.pole()) <= 1.0)
                continue;
            const double u = w.Apply(b);
            EXPECT_NEAR(w.Invert(u), b, 1e-9 * (1.0 + std::abs(b)))
                << "kind " << static_cast<int>(w.kind()) << " b " << b;
            const double step = 1e-4;
            const double numeric = (w.Apply(b + step) - w.Apply(b - step)) / (2.0 * step);
            // Piecewise: away from the knots the slope is the segment's.
            if (w.kind() == AxisWarp::Kind::kPiecewise && std::fmod(b, 100.0) < 1e-3) continue;
            EXPECT_NEAR(w.Slope(b), numeric, 1e-6 * (1.0 + std::abs(numeric)))
                << "kind " << static_cast<int>(w.kind()) << " b " << b;
            EXPECT_GT(w.Slope(b), 0.0);
        }
    }
}

TEST(AxisWarp, LogarithmicIsOffTheMapAtAndBeyondItsPole) {
    const AxisWarp w = AxisWarp::Logarithmic(10.0, 1.0, 1.0, 0.0);
    EXPECT_EQ(w.Apply(10.0), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(w.Apply(3.0), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(w.Slope(3.0), 0.0);
    EXPECT_NEAR(w.Apply(10.0 + std::exp(2.0)), 2.0, 1e-15);
    // Below a pole (sign −1) the warp still increases, toward +∞ at the pole.
    const AxisWarp below = AxisWarp::Logarithmic(10.0, -1.0, 1.0, 0.0);
    EXPECT_EQ(below.Apply(10.0), std::numeric_limits<double>::infinity());
    EXPECT_NEAR(below.Apply(10.0 - std::exp(-2.0)), 2.0, 1e-14);
    EXPECT_LT(below.Apply(0.0), below.Apply(5.0));
}

TEST(AxisWarp, RejectsNonIncreasingKnots) {
    EXPECT_THROW(AxisWarp::Piecewise(0.0, 1.0, {0.0, 0.5, 0.5}), std::invalid_argument);
    EXPECT_THROW(AxisWarp::Piecewise(1.0, 1.0, {0.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(AxisWarp::Affine(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(AxisWarp::Logarithmic(0.0, 2.0, 1.0, 0.0), std::invalid_argument);
}

TEST(MapWarp, LinearIsItsLightMatrix) {
    const LightMatrix m = SomeProjectiveMatrix();
    const MapWarp w = MapWarp::Linear(m);
    EXPECT_TRUE(w.IsLinear());
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 X(d(rng), d(rng), 2.0 + d(rng));
        const auto u = w.Forward(X);
        ASSERT_TRUE(u);
        EXPECT_EQ(*u, m.Map(X));
        const glm::dvec3 back = w.Inverse(*u);
        const glm::dvec3 expected = m.Unmap(*u);
        EXPECT_EQ(back, expected);
        glm::dvec3 a1, a2, e1, e2;
        ASSERT_TRUE(w.Jacobian(X, &a1, &a2));
        m.MapJacobian(X, &e1, &e2);
        EXPECT_EQ(a1, e1);
        EXPECT_EQ(a2, e2);
    }
    // Behind the plane p4·X = 0 nothing maps.
    EXPECT_FALSE(w.Forward(-glm::dvec3(0.1, 0.0, 1.0)));
}

TEST(MapWarp, ForwardInverseAndJacobianOfAWarpedMap) {
    MapWarp w = MapWarp::Linear(SomeProjectiveMatrix());
    w.x = AxisWarp::Piecewise(-200.0, 800.0, {-200.0, 100.0, 150.0, 500.0, 800.0});
    w.y = AxisWarp::Logarithmic(-400.0, 1.0, 150.0, -700.0);
    w.phase = {0.25, -0.375};
    EXPECT_FALSE(w.IsLinear());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> d(-0.6, 0.6);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 X(d(rng), d(rng), 1.0 + 0.3 * d(rng));
        const auto u = w.Forward(X);
        ASSERT_TRUE(u);
        // The inverse is the ray: a positive multiple of X.
        const glm::dvec3 ray = w.Inverse(*u);
        EXPECT_NEAR(glm::length(glm::cross(glm::normalize(ray), glm::normalize(X))), 0.0, 1e-12);
        EXPECT_GT(glm::dot(ray, X), 0.0);
        glm::dvec3 du1, du2;
        ASSERT_TRUE(w.Jacobian(X, &du1, &du2));
        for (int c = 0; c < 3; ++c) {
            glm::dvec3 step(0.0);
            step[c] = 1e-6;
            const glm::dvec2 numeric = (*w.Forward(X + step) - *w.Forward(X - step)) / 2e-6;
            EXPECT_NEAR(du1[c], numeric.x, 1e-5 * (1.0 + std::abs(numeric.x)));
            EXPECT_NEAR(du2[c], numeric.y, 1e-5 * (1.0 + std::abs(numeric.y)));
        }
    }
    // The phase moves every texel coordinate by itself.
    const glm::dvec3 X(0.1, 0.2, 1.0);
    EXPECT_NEAR(w.Shifted({0.5, 0.5}).Forward(X)->x - w.Forward(X)->x, 0.5, 1e-12);
}

// ---- RTW (Rosen 2012) ----------------------------------------------------------------------

TEST(Rtw, WarpsAreMonotoneAndMapTheUnitIntervalOntoItself) {
    std::mt19937_64 rng(3);
    std::exponential_distribution<double> importance(1.0);
    std::bernoulli_distribution empty(0.5);
    for (int trial = 0; trial < 20; ++trial) {
        // Sparse importance (half the bins empty), and for every third trial none at all.
        const int n = 1 + trial * 20;
        std::vector<double> v(n, 0.0);
        if (trial % 3 != 0)
            for (double& x : v) x = empty(rng) ? 0.0 : importance(rng);
        const std::vector<double> w =
            CumulativeWarp(FlooredDensity(GaussianBlur(v, kRtwBlurSigma * n), kRtwDensityFloor));
        ASSERT_EQ(w.size(), v.size() + 1u);
        EXPECT_EQ(w.front(), 0.0) << "n " << n;
        EXPECT_EQ(w.back(), 1.0) << "n " << n;
        for (std::size_t i = 1; i < w.size(); ++i) EXPECT_GT(w[i], w[i - 1]) << "n " << n;
    }
}

TEST(Rtw, TexelDensityIsProportionalToTheBlurredImportance) {
    // A 400-texel axis: two bright bands on a dim background, one sharp spike.
    const int n = 400;
    std::vector<double> importance(n, 0.0);
    for (int i = 40; i < 80; ++i) importance[i] = 8.0;
    for (int i = 200; i < 330; ++i) importance[i] = 2.0 + 0.01 * i;
    importance[370] = 50.0;
    const double sigma = kRtwBlurSigma * n;
    const std::vector<double> blurred = GaussianBlur(importance, sigma);
    const std::vector<double> density = FlooredDensity(blurred, kRtwDensityFloor);
    const double total = std::accumulate(density.begin(), density.end(), 0.0);
    LightMatrix base;  // u = X.xy / X.z: base texels are light-space directions on z = 1
    const MapWarp warp = RectilinearWarp(base, {n, n}, {importance, importance});
    // Where the blurred importance is above the floor, the warp's slope (warped texels per base
    // texel) is n × blurred / Σ density: density ∝ blurred importance, to rounding.
    const double floorValue =
        kRtwDensityFloor * std::accumulate(blurred.begin(), blurred.end(), 0.0) / n;
    int checked = 0;
    for (int i = 0; i < n; ++i) {
        const double slope = warp.x.Slope(i + 0.5);
        EXPECT_NEAR(slope, n * density[i] / total, 1e-12 * n) << "bin " << i;
        if (blurred[i] > floorValue) {
            EXPECT_NEAR(slope / blurred[i], n / total, 1e-12 * n / total) << "bin " << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 150);
    // Counted in texels: the warped texel centres falling in each base bin are n × its share of
    // the density, within one texel.
    std::vector<int> texels(n, 0);
    for (int t = 0; t < n; ++t) {
        const double b = warp.x.Invert(t + 0.5);
        ++texels[std::clamp(static_cast<int>(b), 0, n - 1)];
    }
    double worst = 0.0;
    int bandTexels = 0;
    for (int i = 0; i < n; ++i)
        worst = std::max(worst, std::abs(texels[i] - n * density[i] / total));
    for (int i = 40; i < 80; ++i) bandTexels += texels[i];
    EXPECT_LT(worst, 1.0);
    // The blur leaves the bright band's texels within its tolerance: the band holds the share of
    // the blurred density over it, ±2σ of spill at each end.
    double bandShare = 0.0;
    for (int i = 40; i < 80; ++i) bandShare += density[i] / total;
    EXPECT_NEAR(bandTexels, n * bandShare, 2.0);
    EXPECT_GE(bandTexels, 3 * 40);  // the band (10% of the axis) got 30% of the texels or more
}

TEST(Rtw, NoImportanceGivesNoWarp) {
    const std::vector<double> zeros(50, 0.0);
    const std::vector<double> w = CumulativeWarp(FlooredDensity(zeros, kRtwDensityFloor));
    for (std::size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(w[i], i / 50.0, 1e-15);
}

TEST(Rtw, GaussianBlurKeepsConstantsAndMass) {
    const std::vector<double> c(30, 3.0);
    for (double v : GaussianBlur(c, 2.5)) EXPECT_NEAR(v, 3.0, 1e-14);
    std::vector<double> spike(101, 0.0);
    spike[50] = 1.0;
    const std::vector<double> b = GaussianBlur(spike, 3.0);
    EXPECT_NEAR(std::accumulate(b.begin(), b.end(), 0.0), 1.0, 1e-12);
    EXPECT_NEAR(b[50] / b[53], std::exp(0.5), 1e-12);  // one σ away: e^(-1/2)
}

TEST(Rtw, LagrangeDensitiesFollowTheCubeRootOfHsCost) {
    // k = 2 (h): d_i ∝ C_i^(1/3); the total Σ C_i / d_i² is least there (perturbations raise it).
    const std::vector<double> cost = {8.0, 1.0, 27.0, 0.0, 64.0};
    const AxisProfile d = LagrangeDensities({cost, cost}, 2);
    const double norm = 2.0 + 1.0 + 3.0 + 0.0 + 4.0;
    for (std::size_t i = 0; i < cost.size(); ++i)
        EXPECT_NEAR(d.x[i], cost.size() * std::cbrt(cost[i]) / norm, 1e-12);
    const auto total = [&](std::vector<double> dens) {
        double t = 0.0;
        for (std::size_t i = 0; i < cost.size(); ++i)
            if (cost[i] > 0.0) t += cost[i] / (dens[i] * dens[i]);
        return t;
    };
    const double best = total(d.x);
    for (std::size_t i = 0; i + 1 < cost.size(); ++i) {
        if (cost[i] == 0.0 || cost[i + 1] == 0.0) continue;
        std::vector<double> moved = d.x;
        moved[i] += 0.01, moved[i + 1] -= 0.01;
        EXPECT_GT(total(moved), best);
    }
}

TEST(Rtw, HsSeparableCostIsTheEnergyOfTheWarpedMap) {
    // For a sample and axis densities (dx, dy), ‖J_w⁻¹‖_F² = c_x/dx² + c_y/dy² exactly, J_w the
    // Jacobian of the warped map.
    LightSamples samples;
    samples.lsX = {{0.1, -0.05, 1.0}};
    samples.dXdx1 = {{0.003, 0.0004, -0.001}};
    samples.dXdx2 = {{-0.0005, 0.0021, 0.0007}};
    LightMatrix base;
    base.p1 = {400.0, 0.0, 200.0};
    base.p2 = {0.0, 400.0, 200.0};
    const Resolution map{400, 400};
    const AxisProfile costs = LagrangeAxisCosts(samples, base, map, map, EnergyHCost());
    const glm::dvec2 b = base.Map(samples.lsX[0]);
    const double cx = costs.x[static_cast<int>(b.x)], cy = costs.y[static_cast<int>(b.y)];
    MapWarp warp = MapWarp::Linear(base);
    warp.x = AxisWarp::Affine(1.7, 3.0);
    warp.y = AxisWarp::Affine(0.6, -1.0);
    EXPECT_NEAR(WarpEnergy(warp, samples), cx / (1.7 * 1.7) + cy / (0.6 * 0.6),
                1e-12 * WarpEnergy(warp, samples));
    EXPECT_NEAR(WarpEnergy(MapWarp::Linear(base), samples), Energy(base, samples),
                1e-12 * Energy(base, samples));
}

}  // namespace
}  // namespace lexel::spatial
