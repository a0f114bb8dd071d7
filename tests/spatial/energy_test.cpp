// The energy family (energy.h) against references: the edge summand against J⁻¹ inverted
// explicitly, its no-normal fallback against the mean over edge directions, the closed-form
// ∂/∂p4 against Ceres Jets and central differences on seeded random samples, the prior, the
// bounded search energy, and the collapse guard's predicate.
#include "lexel/spatial/energy.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/temporal.h"

namespace lexel::spatial {
namespace {

// Random samples in front of p4 = (0, 0, 1), each with a random unit edge normal (every fifth
// without one), and as many prior points, as optimizer_test's RandomSamples.
LightSamples RandomSamples(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    LightSamples s;
    const auto point = [&](std::vector<glm::dvec3>* x, std::vector<glm::dvec3>* d1,
                           std::vector<glm::dvec3>* d2) {
        x->push_back({2 * uni(rng), 2 * uni(rng), 7.5 + 2.5 * uni(rng)});
        d1->push_back({0.05 + 0.01 * uni(rng), 0.01 * uni(rng), 0.02 * uni(rng)});
        d2->push_back({0.01 * uni(rng), 0.05 + 0.01 * uni(rng), 0.02 * uni(rng)});
    };
    for (int i = 0; i < count; ++i) {
        point(&s.lsX, &s.dXdx1, &s.dXdx2);
        s.lsRelevant.push_back(s.lsX.back());
        const double angle = std::numbers::pi * uni(rng);
        s.edgeNormal.push_back(i % 5 == 4 ? glm::dvec2(0.0)
                                          : glm::dvec2(std::cos(angle), std::sin(angle)));
        point(&s.lsPrior, &s.priorDXdx1, &s.priorDXdx2);
        s.lsRelevant.push_back(s.lsPrior.back());
    }
    return s;
}

std::string Describe(const LightMatrix& m, const LightSamples& s, std::uint64_t seed) {
    std::ostringstream out;
    out.precision(17);
    out << "seed " << seed << ", p1 (" << m.p1.x << ", " << m.p1.y << ", " << m.p1.z << "), p2 ("
        << m.p2.x << ", " << m.p2.y << ", " << m.p2.z << "), p4 (" << m.p4.x << ", " << m.p4.y
        << ", " << m.p4.z << "), " << s.lsX.size() << " samples; first X (" << s.lsX[0].x << ", "
        << s.lsX[0].y << ", " << s.lsX[0].z << "), n (" << s.edgeNormal[0].x << ", "
        << s.edgeNormal[0].y << ")";
    return out.str();
}

Eigen::Matrix2d InverseJacobian(const LightMatrix& m, const glm::dvec3& X, const glm::dvec3& d1,
                                const glm::dvec3& d2) {
    glm::dvec2 r1, r2;
    SampleJacobian(m, X, d1, d2, &r1, &r2);
    Eigen::Matrix2d j;
    j << r1.x, r1.y, r2.x, r2.y;
    return j.inverse();
}

LightMatrix MatrixFor(const LightSamples& s, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.1 * uni(rng), 0.1 * uni(rng), 1.0));
    const std::optional<LightMatrix> m = FitMapToPoints(p4, s.lsRelevant, {400, 300});
    if (!m) throw std::runtime_error("MatrixFor: no fit");
    return *m;
}

TEST(EdgeEnergy, SummandIsTheNormalRowOfTheInverseJacobian) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        std::mt19937_64 rng(seed);
        const LightSamples s = RandomSamples(rng, 20);
        const LightMatrix m = MatrixFor(s, rng);
        const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
        for (std::size_t k = 0; k < s.lsX.size(); ++k) {
            const Eigen::Matrix2d inv = InverseJacobian(m, s.lsX[k], s.dXdx1[k], s.dXdx2[k]);
            const glm::dvec2 n = s.edgeNormal[k];
            const double expected = n == glm::dvec2(0.0)
                                        ? inv.norm() / std::sqrt(2.0)
                                        : (Eigen::RowVector2d(n.x, n.y) * inv).norm();
            const double f = SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4,
                                              s.lsX[k], s.dXdx1[k], s.dXdx2[k], n);
            EXPECT_NEAR(f, expected, 1e-12 * expected) << Describe(m, s, seed) << ", sample " << k;
        }
    }
}

TEST(EdgeEnergy, FallbackIsTheRootMeanSquareOverEdgeDirections) {
    // Equally spaced directions average nnᵀ to I/2 exactly, so the mean of ||nᵀJ⁻¹||² over them
    // is ||J⁻¹||_F²/2.
    std::mt19937_64 rng(7);
    const LightSamples s = RandomSamples(rng, 5);
    const LightMatrix m = MatrixFor(s, rng);
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    const auto f = [&](const glm::dvec2& n) {
        return SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, s.lsX[0],
                                s.dXdx1[0], s.dXdx2[0], n);
    };
    constexpr int kDirections = 64;
    double meanSquare = 0.0;
    for (int i = 0; i < kDirections; ++i) {
        const double a = 2.0 * std::numbers::pi * i / kDirections;
        meanSquare += f({std::cos(a), std::sin(a)}) * f({std::cos(a), std::sin(a)}) / kDirections;
    }
    EXPECT_NEAR(f(glm::dvec2(0.0)), std::sqrt(meanSquare), 1e-12 * std::sqrt(meanSquare));
}

TEST(EdgeEnergy, ExponentRaisesEverySummandAndTheTexelLaw) {
    // e_p = Σ ||nᵀJ⁻¹||^p + w · mean (||J⁻¹||_F/√2)^p with J⁻¹ inverted explicitly; halving p1
    // and p2 doubles every J⁻¹ (a map with a quarter of the texels), so e_p doubles as 2^p: the
    // N^(−p/2) of EnergyExponent.
    std::mt19937_64 rng(17);
    const LightSamples s = RandomSamples(rng, 30);
    const LightMatrix m = MatrixFor(s, rng);
    for (const double p : {0.5, kDefaultEdgeExponent, 0.7, 0.75, 1.0, 1.5}) {  // 0.7: std::pow's
        double reference = 0.0, prior = 0.0;
        for (std::size_t k = 0; k < s.lsX.size(); ++k) {
            const Eigen::Matrix2d inv = InverseJacobian(m, s.lsX[k], s.dXdx1[k], s.dXdx2[k]);
            const Eigen::RowVector2d n(s.edgeNormal[k].x, s.edgeNormal[k].y);
            const double band = n.isZero() ? inv.norm() / std::sqrt(2.0) : (n * inv).norm();
            reference += std::pow(band, p);
        }
        for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
            const Eigen::Matrix2d inv =
                InverseJacobian(m, s.lsPrior[k], s.priorDXdx1[k], s.priorDXdx2[k]);
            prior += std::pow(inv.norm() / std::sqrt(2.0), p) / double(s.lsPrior.size());
        }
        const EnergyOptions options{EnergyKind::kEdge, 2.0, p};
        const double e = Energy(m, s, options);
        EXPECT_NEAR(e, reference + 2.0 * prior, 1e-12 * e) << "exponent " << p;
        EXPECT_EQ(SearchEnergy(s, options)(m), e) << "exponent " << p;
        LightMatrix coarser = m;
        coarser.p1 *= 0.5, coarser.p2 *= 0.5;
        EXPECT_NEAR(Energy(coarser, s, options), std::pow(2.0, p) * e, 1e-12 * e)
            << "exponent " << p;
        EXPECT_EQ(EnergyExponent(options), 0.5 * p);
    }
    EXPECT_EQ(EnergyExponent(EnergyOptions{}), 1.0);  // h: texel areas
}

TEST(EdgeEnergy, SingularJacobianIsUnbounded) {
    std::mt19937_64 rng(3);
    LightSamples s = RandomSamples(rng, 3);
    const LightMatrix m = MatrixFor(s, rng);
    s.dXdx2[1] = s.dXdx1[1];  // parallel screen directions: det J = 0
    EXPECT_TRUE(std::isinf(Energy(m, s, {EnergyKind::kEdge, 0.0})));
    s.edgeNormal[1] = glm::dvec2(0.0);
    EXPECT_TRUE(std::isinf(Energy(m, s, {EnergyKind::kEdge, 0.0})));
}

TEST(EnergyFamily, GradientsMatchJetsAndCentralDifferences) {
    const EnergyOptions kinds[] = {{EnergyKind::kEdge, 0.0},
                                   {EnergyKind::kEdge, kDefaultPriorWeight},
                                   {EnergyKind::kEdge, 5.0},
                                   {EnergyKind::kEdge, 0.0, 0.5},
                                   {EnergyKind::kEdge, kDefaultPriorWeight, 0.75},
                                   {EnergyKind::kEdge, 2.0, 1.5},
                                   kEdgeEnergy,  // the shipped p = 5/8
                                   {EnergyKind::kReport, 0.0},
                                   {EnergyKind::kReport, 2.0}};
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        const LightSamples s = RandomSamples(rng, 40);
        const LightMatrix m = MatrixFor(s, rng);
        for (const EnergyOptions& options : kinds) {
            const std::string what = Describe(m, s, seed) + ", kind " +
                                     std::to_string(static_cast<int>(options.kind)) + ", prior " +
                                     std::to_string(options.priorWeight) + ", exponent " +
                                     std::to_string(options.exponent);
            const glm::dvec3 analytic = EnergyGradient(m, s, options);
            const glm::dvec3 jets = EnergyGradientJets(m, s, options);
            const double scale = glm::length(analytic);
            ASSERT_GT(scale, 0.0) << what;
            EXPECT_NEAR(glm::length(analytic - jets), 0.0, 1e-10 * scale) << what;
            for (int c = 0; c < 3; ++c) {
                const double step = 1e-6;
                LightMatrix plus = m, minus = m;
                plus.p4[c] += step;
                minus.p4[c] -= step;
                const double fd =
                    (Energy(plus, s, options) - Energy(minus, s, options)) / (2 * step);
                EXPECT_NEAR(analytic[c], fd, 1e-5 * scale) << what << ", component " << c;
            }
        }
    }
}

TEST(EnergyFamily, ReportOptionsAreEnergyBitForBit) {
    std::mt19937_64 rng(11);
    const LightSamples s = RandomSamples(rng, 100);
    const LightMatrix m = MatrixFor(s, rng);
    const EnergyOptions report;
    EXPECT_TRUE(report.IsReport());
    EXPECT_EQ(Energy(m, s, report), Energy(m, s));
    EXPECT_EQ(EnergyGradient(m, s, report), EnergyGradientAnalytic(m, s));
    EXPECT_EQ(SearchEnergy(s, report)(m), BoundedEnergy(s)(m));
}

TEST(EnergyFamily, SearchEnergyEqualsEnergyBelowTheBoundAndStopsAboveIt) {
    std::mt19937_64 rng(5);
    const LightSamples s = RandomSamples(rng, 200);
    const LightMatrix m = MatrixFor(s, rng);
    for (const EnergyOptions options :
         {EnergyOptions{EnergyKind::kEdge, 0.0}, EnergyOptions{EnergyKind::kEdge, 1.0},
          EnergyOptions{EnergyKind::kEdge, 1.0, 0.75}, kEdgeEnergy,
          EnergyOptions{EnergyKind::kReport, 1.0}}) {
        const SearchEnergy search(s, options);
        const double e = Energy(m, s, options);
        EXPECT_EQ(search(m), e);
        EXPECT_EQ(search(m, 2.0 * e), e);
        const double stopped = search(m, 0.5 * e);
        EXPECT_GE(stopped, 0.5 * e);
        EXPECT_LT(stopped, e);  // it stopped before the last sample
    }
}

// The search's packed gradient is EnergyGradient's value bit for bit, over block edges (200
// samples: three blocks of 64 and 8), with a sample behind the plane and a singular one skipped.
TEST(EnergyFamily, SearchGradientIsEnergyGradientBitForBit) {
    const EnergyOptions edge[] = {{EnergyKind::kEdge, 0.0},
                                  {EnergyKind::kEdge, 1.0},
                                  {EnergyKind::kEdge, 1.0, 0.75},
                                  kEdgeEnergy,
                                  {EnergyKind::kEdge, 2.0, 0.3}};
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        std::mt19937_64 rng(seed);
        LightSamples s = RandomSamples(rng, 200);
        const LightMatrix m = MatrixFor(s, rng);
        s.lsX[70] = -s.lsX[70];       // behind the plane: skipped
        s.dXdx2[130] = s.dXdx1[130];  // det J = 0: skipped
        s.priorDXdx2[3] = s.priorDXdx1[3];
        const auto check = [&](const LightSamples& samples, const EnergyOptions& options) {
            const glm::dvec3 expected = EnergyGradient(m, samples, options);
            ASSERT_GT(glm::length(expected), 0.0) << Describe(m, samples, seed);
            ASSERT_TRUE(std::isfinite(glm::length(expected))) << Describe(m, samples, seed);
            EXPECT_EQ(SearchEnergy(samples, options).Gradient(m), expected)
                << Describe(m, samples, seed) << ", exponent " << options.exponent << ", prior "
                << options.priorWeight;
        };
        for (const EnergyOptions& options : edge) check(s, options);
        check(s, {EnergyKind::kReport, 1.0});
        check(s, {});
        // J of order 1e-85 at two points: det² underflows to 0 while f_e = √q/|det| stays
        // finite, so the summand is +inf and the point adds nothing to e's gradient (it made the
        // gradient NaN when f_e^(p−1) was std::pow'd and the summand not checked).
        LightSamples tiny = s;
        tiny.dXdx1[40] *= 1e-85;
        tiny.dXdx2[40] *= 1e-85;
        tiny.priorDXdx1[5] *= 1e-85;
        tiny.priorDXdx2[5] *= 1e-85;
        for (const EnergyOptions& options : edge) check(tiny, options);
    }
}

TEST(FootprintPrior, IsTheWeightedMeanOfTheNoNormalSummand) {
    std::mt19937_64 rng(13);
    LightSamples s = RandomSamples(rng, 30);
    const LightMatrix m = MatrixFor(s, rng);
    double edgeMean = 0.0, reportMean = 0.0;
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
        const Eigen::Matrix2d inv =
            InverseJacobian(m, s.lsPrior[k], s.priorDXdx1[k], s.priorDXdx2[k]);
        edgeMean += inv.norm() / std::sqrt(2.0) / double(s.lsPrior.size());
        reportMean += inv.squaredNorm() / double(s.lsPrior.size());
    }
    EXPECT_NEAR(PriorEnergy(m, s, {EnergyKind::kEdge, 3.0}), 3.0 * edgeMean, 1e-12 * edgeMean);
    EXPECT_NEAR(PriorEnergy(m, s, {EnergyKind::kReport, 3.0}), 3.0 * reportMean,
                1e-12 * reportMean);
    EXPECT_EQ(PriorEnergy(m, s, {EnergyKind::kEdge, 0.0}), 0.0);
    EXPECT_NEAR(*RelevantFootprint(m, s), std::sqrt(2.0) * edgeMean, 1e-12 * edgeMean);
    // Without boundary samples the prior is all the energy there is, and it still differs
    // between maps (h would be 0 for every one).
    s.lsX.clear(), s.dXdx1.clear(), s.dXdx2.clear(), s.edgeNormal.clear();
    EXPECT_EQ(Energy(m, s), 0.0);
    EXPECT_NEAR(Energy(m, s, {EnergyKind::kEdge, 1.0}), edgeMean, 1e-12 * edgeMean);
    LightMatrix coarser = m;
    coarser.p1 *= 0.5, coarser.p2 *= 0.5;  // J halves, J⁻¹ doubles everywhere
    EXPECT_NEAR(Energy(coarser, s, {EnergyKind::kEdge, 1.0}), 2.0 * edgeMean, 1e-12 * edgeMean);
}

TEST(CollapseGuard, RejectsAMapWhoseViewFootprintGrowsBeyondTheFactor) {
    // Shrinking both affine rows by c scales J by c and J⁻¹ by 1/c at every point: the relevant
    // footprint grows by exactly 1/c.
    std::mt19937_64 rng(17);
    const LightSamples s = RandomSamples(rng, 10);
    const LightMatrix m = MatrixFor(s, rng);
    const auto scaled = [&](double c) {
        LightMatrix out = m;
        out.p1 *= c, out.p2 *= c;
        return out;
    };
    EXPECT_NEAR(*RelevantFootprint(scaled(0.25), s), 4.0 * *RelevantFootprint(m, s),
                1e-12 * *RelevantFootprint(m, s));
    EXPECT_TRUE(Collapses(m, scaled(0.25), s, kCollapseFactor));
    EXPECT_TRUE(Collapses(m, scaled(0.45), s, kCollapseFactor));
    EXPECT_FALSE(Collapses(m, scaled(0.55), s, kCollapseFactor));
    EXPECT_FALSE(Collapses(m, scaled(3.0), s, kCollapseFactor));
    EXPECT_FALSE(Collapses(m, scaled(0.25), s, 0.0));  // off
    LightSamples noPrior = s;
    noPrior.lsPrior.clear(), noPrior.priorDXdx1.clear(), noPrior.priorDXdx2.clear();
    EXPECT_FALSE(Collapses(m, scaled(0.25), noPrior, kCollapseFactor));
}

TEST(EdgeNormal, IsTheUnitSobelGradientFromLitToShadowed) {
    const Resolution r{6, 5};
    std::vector<Shade> shades(r.Count(), Shade::kLit);
    for (int y = 0; y < 5; ++y)
        for (int x = 3; x < 6; ++x) shades[y * 6 + x] = Shade::kShadowed;  // right half shadowed
    const glm::dvec2 n = EdgeNormalAt(r, shades, 2 * 6 + 2);
    EXPECT_EQ(n, glm::dvec2(1.0, 0.0));
    // At the image's top row the border is replicated: still across.
    EXPECT_EQ(EdgeNormalAt(r, shades, 0 * 6 + 3), glm::dvec2(1.0, 0.0));
    // A diagonal edge (shadow below-right of x + y = 4): the normal is (1, 1)/√2.
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 6; ++x) shades[y * 6 + x] = x + y > 4 ? Shade::kShadowed : Shade::kLit;
    const glm::dvec2 d = EdgeNormalAt(r, shades, 2 * 6 + 2);
    EXPECT_NEAR(d.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(d.y, std::sqrt(0.5), 1e-15);
    // A one-pixel vertical line of shadow: its two sides cancel, no normal.
    std::fill(shades.begin(), shades.end(), Shade::kLit);
    for (int y = 0; y < 5; ++y) shades[y * 6 + 2] = Shade::kShadowed;
    EXPECT_EQ(EdgeNormalAt(r, shades, 2 * 6 + 2), glm::dvec2(0.0));
    // Neighbours that are neither lit nor shadowed say nothing: a lit pixel next to empty ones.
    std::fill(shades.begin(), shades.end(), Shade::kEmpty);
    shades[2 * 6 + 2] = Shade::kLit;
    shades[2 * 6 + 3] = Shade::kShadowed;
    EXPECT_EQ(EdgeNormalAt(r, shades, 2 * 6 + 2), glm::dvec2(1.0, 0.0));
}

TEST(Hysteresis, EdgeMedianAndThresholdAskTheSameAreaImprovementAsH) {
    // Scaling the candidate's affine rows by c scales J by c: h's median by 1/c², e's by 1/c.
    // Both replace the previous matrix exactly when c > 1/√0.8 ≈ 1.118.
    std::mt19937_64 rng(19);
    const LightSamples s = RandomSamples(rng, 41);
    const LightMatrix m = MatrixFor(s, rng);
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    std::vector<double> values;
    for (std::size_t k = 0; k < s.lsX.size(); ++k)
        values.push_back(SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, s.lsX[k],
                                          s.dXdx1[k], s.dXdx2[k], s.edgeNormal[k]));
    std::nth_element(values.begin(), values.begin() + 20, values.end());
    EXPECT_EQ(MedianBadness(m, s, EnergyKind::kEdge), values[20]);
    const Resolution map{400, 300};
    const std::optional<LightMatrix> kept = RescaleToCover(m, s, map, 0.02);
    ASSERT_TRUE(kept);
    for (const EnergyKind kind : {EnergyKind::kReport, EnergyKind::kEdge})
        for (const double c : {1.10, 1.13}) {
            LightMatrix candidate = *kept;
            candidate.p1 *= c, candidate.p2 *= c;
            const HysteresisDecision d = ApplyHysteresis(m, candidate, s, map, 0.02, kind);
            EXPECT_EQ(d.changed, c > 1.118) << "kind " << static_cast<int>(kind) << ", c " << c;
        }
}

TEST(Partitions, CascadeSamplesCarryTheirNormalsAndPriorPoints) {
    Camera camera;
    camera.position = {0.0, 0.0, 0.0};
    camera.target = {0.0, 0.0, -1.0};
    std::vector<Cascade> cascades(2);
    cascades[0].zFar = cascades[1].zNear = 5.0;
    LightSamples s;
    for (const double z : {3.0, 7.0, 4.0}) {
        s.lsX.push_back({0.0, 0.0, z});
        s.dXdx1.push_back({1.0, 0.0, 0.0});
        s.dXdx2.push_back({0.0, 1.0, 0.0});
        s.pixel.push_back(static_cast<std::uint32_t>(s.pixel.size()));
        s.wsX.push_back({0.0, 0.0, -z});
        s.edgeNormal.push_back({z / 10.0, 0.0});
    }
    for (const double z : {2.0, 8.0, 9.0}) {
        s.lsPrior.push_back({0.0, 0.0, z});
        s.priorDXdx1.push_back({z, 0.0, 0.0});
        s.priorDXdx2.push_back({0.0, z, 0.0});
        s.wsPrior.push_back({0.0, 0.0, -z});
    }
    const LightSamples near = SamplesOfCascade(s, {}, camera, cascades, 0);
    EXPECT_EQ(near.edgeNormal, (std::vector<glm::dvec2>{{0.3, 0.0}, {0.4, 0.0}}));
    EXPECT_EQ(near.lsPrior, (std::vector<glm::dvec3>{{0.0, 0.0, 2.0}}));
    const LightSamples far = SamplesOfCascade(s, {}, camera, cascades, 1);
    EXPECT_EQ(far.edgeNormal, (std::vector<glm::dvec2>{{0.7, 0.0}}));
    EXPECT_EQ(far.priorDXdx1, (std::vector<glm::dvec3>{{8.0, 0.0, 0.0}, {9.0, 0.0, 0.0}}));
    EXPECT_EQ(far.wsPrior.size(), 2u);
}

}  // namespace
}  // namespace lexel::spatial
