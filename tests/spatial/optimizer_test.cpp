// Algorithm 1's pieces against references: the Appendix A gradient against Ceres Jets and central
// differences, the hull-once fit (from all points and from the frame's 3D hull vertices) against
// the naive fit, and the search's monotone progress.
#include "lexel/spatial/optimizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/min_area_parallelogram.h"
#include "lexel/spatial/energy_gradient.h"
#include "lexel/spatial/multi_start.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

// A floor with a box, seen by a camera near the floor (a 180² readback): real samples for the
// searches below.
struct BoxOnFloor {
    TriangleMesh scene = [] {
        TriangleMesh m = testing::FloorQuad(20.0);
        m.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 2.0, 1.0}));
        return m;
    }();
    std::unique_ptr<RenderBackend> renderer = MakeCpuRenderer(scene);
    Camera camera = [] {
        Camera c;
        c.position = {0.0, 1.7, 12.0};
        c.target = {0.0, 0.5, 0.0};
        return c;
    }();
    Readback readback = RenderReadback(*renderer, camera, {180, 180});
    Bounds bounds = scene.ComputeBounds();
};

// Random samples in front of the plane p4 = (0, 0, 1): points in a box at depth 5..10 and random
// screen derivatives.
LightSamples RandomSamples(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    LightSamples s;
    for (int i = 0; i < count; ++i) {
        s.lsX.push_back({2 * uni(rng), 2 * uni(rng), 7.5 + 2.5 * uni(rng)});
        s.dXdx1.push_back({0.05 + 0.01 * uni(rng), 0.01 * uni(rng), 0.02 * uni(rng)});
        s.dXdx2.push_back({0.01 * uni(rng), 0.05 + 0.01 * uni(rng), 0.02 * uni(rng)});
        s.lsRelevant.push_back(s.lsX.back());
    }
    return s;
}

TEST(EnergyGradient, AnalyticMatchesJetsAndCentralDifferences) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> uni(-1.0, 1.0);
        const LightSamples s = RandomSamples(rng, 50);
        const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.1 * uni(rng), 0.1 * uni(rng), 1.0));
        const auto m = FitMapToPoints(p4, s.lsRelevant, {400, 300});
        ASSERT_TRUE(m) << "seed " << seed;
        const glm::dvec3 analytic = EnergyGradientAnalytic(*m, s);
        const glm::dvec3 jets = EnergyGradientJets(*m, s);
        const double scale = glm::length(analytic);
        ASSERT_GT(scale, 0.0);
        EXPECT_NEAR(glm::length(analytic - jets), 0.0, 1e-10 * scale) << "seed " << seed;
        // Central differences of h with p1, p2 fixed (p4 need not stay unit for ∂h/∂p4).
        for (int c = 0; c < 3; ++c) {
            const double step = 1e-6;
            LightMatrix plus = *m, minus = *m;
            plus.p4[c] += step;
            minus.p4[c] -= step;
            const double fd = (Energy(plus, s) - Energy(minus, s)) / (2 * step);
            EXPECT_NEAR(analytic[c], fd, 1e-5 * scale) << "seed " << seed << " component " << c;
        }
        // Energy (the template's closed form) equals the sum of SampleBadness, which inverts J
        // through the metric layer (solvers/footprint_metrics): an independent reference.
        double h = 0.0;
        for (std::size_t k = 0; k < s.lsX.size(); ++k)
            h += SampleBadness(*m, s.lsX[k], s.dXdx1[k], s.dXdx2[k]);
        EXPECT_NEAR(h, Energy(*m, s), 1e-12 * h);
    }
}

TEST(RelevantHull, FitFromHullVerticesEqualsTheNaiveFit) {
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> uni(-1.0, 1.0);
        LightSamples s = RandomSamples(rng, 2000);
        const RelevantHull hull = *RelevantHull::Of(s.lsRelevant, {0, 0, 1});
        EXPECT_LT(hull.Vertices().size(), 60u);
        for (int k = 0; k < 20; ++k) {
            const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.6 * uni(rng), 0.6 * uni(rng), 1.0));
            const auto naive = FitMapToPoints(p4, s.lsRelevant, {400, 300}, {0.02});
            const auto fast = hull.Fit(p4, {400, 300}, {0.02});
            ASSERT_EQ(naive.has_value(), fast.has_value()) << "seed " << seed << " k " << k;
            if (!naive) continue;
            // Same map up to rounding: every relevant point lands at the same texel position.
            for (std::size_t i = 0; i < s.lsRelevant.size(); i += 97) {
                const glm::dvec2 a = naive->Map(s.lsRelevant[i]), b = fast->Map(s.lsRelevant[i]);
                ASSERT_NEAR(glm::length(a - b), 0.0, 1e-7) << "seed " << seed << " k " << k;
            }
        }
    }
}

// Samples whose relevant points fill a random skewed, tapered slab in front of p4 = (0, 0, 1), so
// that the hull of their projection is far from a rectangle and the shear has work to do.
LightSamples SkewedSamples(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    const double skew = 1.5 * uni(rng), taper = 0.8 * uni(rng), twist = 0.6 * uni(rng);
    LightSamples s;
    for (int i = 0; i < count; ++i) {
        const double a = uni(rng), b = 0.4 * uni(rng), depth = 7.5 + 2.5 * uni(rng);
        const double x = 2 * a + skew * b, y = (1 + taper * a) * b + twist * a * a;
        s.lsX.push_back({x, y, depth});
        s.dXdx1.push_back({0.05 + 0.01 * uni(rng), 0.01 * uni(rng), 0.02 * uni(rng)});
        s.dXdx2.push_back({0.01 * uni(rng), 0.05 + 0.01 * uni(rng), 0.02 * uni(rng)});
        s.lsRelevant.push_back(s.lsX.back());
    }
    return s;
}

std::string DescribeAxis(std::uint64_t seed, int trial, const glm::dvec3& p4) {
    std::ostringstream out;
    out << std::setprecision(17) << "seed " << seed << " trial " << trial << " p4 (" << p4.x << ", "
        << p4.y << ", " << p4.z << ")";
    return out.str();
}

// The sheared fit maps the minimum-area parallelogram of the projected points onto the map: its
// corners land on the map's corners (shrunk by the margin about the centre), every point inside.
TEST(FitMapToPoints, ShearMapsTheMinimumAreaParallelogramOntoTheMap) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> uni(-1.0, 1.0);
        const LightSamples s = SkewedSamples(rng, 300);
        const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.2 * uni(rng), 0.2 * uni(rng), 1.0));
        SCOPED_TRACE(DescribeAxis(seed, 0, p4));
        glm::dvec3 b1, b2;
        PlaneBasis(p4, &b1, &b2);
        std::vector<Eigen::Vector2d> y;
        for (const glm::dvec3& X : s.lsRelevant)
            y.emplace_back(glm::dot(b1, X) / glm::dot(p4, X), glm::dot(b2, X) / glm::dot(p4, X));
        const Parallelogram2 par = MinAreaParallelogram(y);
        for (const double margin : {0.0, 0.02}) {
            const Resolution map{400, 300};
            const auto m = FitMapToPoints(p4, s.lsRelevant, map, {margin, true});
            ASSERT_TRUE(m);
            for (const Eigen::Vector2d& c : par.Corners()) {
                // The plane point y = c is the light-space direction c.x b1 + c.y b2 + p4.
                const glm::dvec2 u = m->Map(c.x() * b1 + c.y() * b2 + p4);
                const glm::dvec2 fromCentre = u - glm::dvec2(200, 150);
                EXPECT_NEAR(std::abs(fromCentre.x), 200 / (1 + margin), 1e-7);
                EXPECT_NEAR(std::abs(fromCentre.y), 150 / (1 + margin), 1e-7);
            }
            for (const glm::dvec3& X : s.lsRelevant) {
                const glm::dvec2 u = m->Map(X);
                EXPECT_TRUE(u.x > -1e-7 && u.x < 400 + 1e-7 && u.y > -1e-7 && u.y < 300 + 1e-7)
                    << u.x << ", " << u.y;
            }
        }
    }
}

// optimal-refined's objective is the fit it claims to differentiate: its value equals
// Energy(FitMapToPoints(p4, ...)) with and without the shear, and its Jet gradient equals central
// differences of that energy wherever the fit's structure does not change within the step
// (detected by central differences at two steps disagreeing).
TEST(RefinedObjective, EqualsTheFitsEnergyAndItsGradientMatchesCentralDifferences) {
    int checked[2] = {0, 0}, sheared = 0, trials = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> uni(-1.0, 1.0);
        const LightSamples s = SkewedSamples(rng, 400);
        const RelevantHull hull = *RelevantHull::Of(s.lsRelevant, {0, 0, 1});
        const std::span<const glm::dvec3> vertices = hull.Vertices();
        const Resolution map{400, 300};
        for (int trial = 0; trial < 8; ++trial) {
            const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.3 * uni(rng), 0.3 * uni(rng), 1.0));
            SCOPED_TRACE(DescribeAxis(seed, trial, p4));
            ++trials;
            const auto rect = FitMapToPoints(p4, vertices, map, {0.02, false});
            const auto sheared0 = FitMapToPoints(p4, vertices, map, {0.02, true});
            ASSERT_TRUE(rect && sheared0);
            if (Energy(*sheared0, s) < (1 - 1e-9) * Energy(*rect, s) ||
                Energy(*sheared0, s) > (1 + 1e-9) * Energy(*rect, s))
                ++sheared;
            for (const bool shear : {false, true}) {
                SCOPED_TRACE(shear ? "shear" : "rectangle");
                const FitOptions options{0.02, shear};
                const auto energyAt = [&](const glm::dvec3& q) {
                    const auto m = FitMapToPoints(q, vertices, map, options);
                    return m ? Energy(*m, s) : std::numeric_limits<double>::quiet_NaN();
                };
                glm::dvec3 gradient;
                const std::optional<double> h =
                    RefinedObjective(vertices, s, p4, map, options, &gradient);
                ASSERT_TRUE(h);
                const double reference = energyAt(p4);
                EXPECT_NEAR(*h, reference, 1e-9 * reference);
                // Without a gradient: the double instantiation, the same value to rounding.
                EXPECT_NEAR(*RefinedObjective(vertices, s, p4, map, options), *h, 1e-12 * *h);
                const double scale = glm::length(gradient);
                ASSERT_GT(scale, 0.0);
                bool smooth = true;
                glm::dvec3 fd;
                for (int c = 0; c < 3; ++c) {
                    const auto central = [&](double step) {
                        glm::dvec3 plus = p4, minus = p4;
                        plus[c] += step;
                        minus[c] -= step;
                        return (energyAt(plus) - energyAt(minus)) / (2 * step);
                    };
                    fd[c] = central(1e-6);
                    if (!(std::abs(fd[c] - central(5e-7)) < 1e-7 * scale)) smooth = false;
                }
                // A structure change within the step: a kink or a jump, not a bug. The sheared fit
                // has more of them (light_matrix.h): near a minimum flush on both side pairs, the
                // neighbours of the second flush edge give parallelograms of nearly equal area.
                if (!smooth) continue;
                ++checked[shear];
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(gradient[c], fd[c], 1e-6 * scale) << "component " << c;
            }
        }
    }
    std::cout << sheared << " of " << trials << " axes: the shear changes h; gradients checked at "
              << checked[0] << " (rectangle) and " << checked[1] << " (shear) axes\n";
    EXPECT_GE(sheared, trials / 2);
    EXPECT_GE(checked[0], trials * 3 / 4);
    EXPECT_GE(checked[1], trials * 3 / 4);
}

// optimal-shear: Algorithm 1 with the sheared fit keeps its invariants on real samples.
TEST(Optimizer, ShearedSearchKeepsEveryRelevantPointOnTheMap) {
    const BoxOnFloor box;
    const RenderBackend& renderer = *box.renderer;
    const Readback& rb = box.readback;
    const Bounds& bounds = box.bounds;
    for (const glm::dvec3 lightPos : {glm::dvec3(-30, 25, -25), glm::dvec3(40, 15, 10)}) {
        Light light;
        light.position = lightPos;
        const LightSpace ls(light, bounds);
        const LightSamples s = testing::SamplesFromBoundsMap(renderer, rb, ls, bounds, {400, 300});
        ASSERT_GT(s.lsX.size(), 20u);
        OptimizerOptions options;
        options.shear = true;
        const OptimizerResult r = OptimizeLightMatrix(s, {0, 0, 1}, {400, 300}, options);
        for (std::size_t i = 1; i < r.hAfterIteration.size(); ++i)
            EXPECT_LE(r.hAfterIteration[i], r.hAfterIteration[i - 1]);
        EXPECT_NEAR(r.h, Energy(r.matrix, s), 1e-9 * r.h);
        for (const glm::dvec3& X : s.lsRelevant) {
            ASSERT_TRUE(InFront(r.matrix.p4, X));
            const glm::dvec2 u = r.matrix.Map(X);
            ASSERT_TRUE(u.x > -1e-6 && u.x < 400 + 1e-6 && u.y > -1e-6 && u.y < 300 + 1e-6)
                << u.x << ", " << u.y;
        }
        const OptimizerResult plain = OptimizeLightMatrix(s, {0, 0, 1}, {400, 300});
        std::cout << "light (" << lightPos.x << ", " << lightPos.y << ", " << lightPos.z << "): h "
                  << plain.h << " (rectangle) vs " << r.h << " (shear)\n";
    }
}

TEST(Optimizer, SearchNeverIncreasesHAndRefinementNeverHurts) {
    // BoxOnFloor lit from the side: real samples.
    const BoxOnFloor box;
    const RenderBackend& renderer = *box.renderer;
    const Readback& rb = box.readback;
    const Bounds& bounds = box.bounds;
    for (const glm::dvec3 lightPos :
         {glm::dvec3(-30, 25, -25), glm::dvec3(40, 15, 10), glm::dvec3(5, 60, -5)}) {
        Light light;
        light.position = lightPos;
        const LightSpace ls(light, bounds);
        const LightSamples s = testing::SamplesFromBoundsMap(renderer, rb, ls, bounds, {400, 400});
        ASSERT_GT(s.lsX.size(), 20u);
        OptimizerOptions options;
        options.refine = true;
        const OptimizerResult r = OptimizeLightMatrix(s, {0, 0, 1}, {400, 400}, options);
        ASSERT_EQ(r.hAfterIteration.size(), 4u);
        for (std::size_t i = 1; i < r.hAfterIteration.size(); ++i)
            EXPECT_LE(r.hAfterIteration[i], r.hAfterIteration[i - 1]);
        // From the side the focused axis is far from optimal; from straight above it is already
        // the best axis the search can find.
        if (lightPos.y < 50) {
            EXPECT_LT(r.hAfterIteration.back(), 0.8 * r.hAfterIteration.front());
        }
        EXPECT_LE(r.h, r.hBeforeRefine);
        EXPECT_NEAR(r.h, Energy(r.matrix, s), 1e-9 * r.h);
        // Every relevant point is inside the map.
        for (const glm::dvec3& X : s.lsRelevant) {
            ASSERT_TRUE(InFront(r.matrix.p4, X));
            const glm::dvec2 u = r.matrix.Map(X);
            ASSERT_GE(u.x, -1e-6);
            ASSERT_LE(u.x, 400 + 1e-6);
            ASSERT_GE(u.y, -1e-6);
            ASSERT_LE(u.y, 400 + 1e-6);
        }
        std::cout << "light (" << lightPos.x << ", " << lightPos.y << ", " << lightPos.z << "): h "
                  << r.hAfterIteration.front() << " -> " << r.hBeforeRefine << " -> refined " << r.h
                  << "\n";
    }
}

TEST(Optimizer, SampleBudgetSearchesOnTheThinnedSamples) {
    // OptimizerOptions::maxSamples: the same matrix, bit for bit, as the search on ThinSamples
    // itself, for one start and for every start; a budget at or above the count changes nothing.
    const BoxOnFloor box;
    const RenderBackend& renderer = *box.renderer;
    const Camera& camera = box.camera;
    const Readback& rb = box.readback;
    const Bounds& bounds = box.bounds;
    Light light;
    light.position = {-30, 25, -25};
    const LightSpace ls(light, bounds);
    const LightSamples s = testing::SamplesFromBoundsMap(renderer, rb, ls, bounds, {400, 400});
    ASSERT_GT(s.lsX.size(), 60u);
    const std::size_t budget = s.lsX.size() / 3;
    OptimizerOptions options = EdgeOptimizerOptions();
    const OptimizerResult all = OptimizeLightMatrix(s, {0, 0, 1}, {400, 400}, options);
    const OptimizerResult thinnedByHand =
        OptimizeLightMatrix(ThinSamples(s, budget), {0, 0, 1}, {400, 400}, options);
    options.maxSamples = s.lsX.size();
    EXPECT_EQ(OptimizeLightMatrix(s, {0, 0, 1}, {400, 400}, options).matrix.p4, all.matrix.p4);
    options.maxSamples = budget;
    const OptimizerResult thinned = OptimizeLightMatrix(s, {0, 0, 1}, {400, 400}, options);
    EXPECT_EQ(thinned.matrix.p4, thinnedByHand.matrix.p4);
    EXPECT_EQ(thinned.matrix.p1, thinnedByHand.matrix.p1);
    EXPECT_EQ(thinned.h, thinnedByHand.h);
    // The energy is over the kept third: about a third of the full search's.
    EXPECT_LT(thinned.h, 0.6 * all.h);

    BaselineContext context;
    context.lightSpace = &ls;
    context.camera = camera;
    context.map = {400, 400};
    context.wsBounds = bounds;
    context.wsRelevant = rb.wsRelevant;
    const std::vector<OptimizerStart> starts = StandardStarts(context);
    const MultiStartResult byHand =
        OptimizeFromStarts(ThinSamples(s, budget), starts, {400, 400}, EdgeOptimizerOptions());
    const MultiStartResult budgeted = OptimizeFromStarts(s, starts, {400, 400}, options);
    EXPECT_EQ(budgeted.result.matrix.p4, byHand.result.matrix.p4);
    EXPECT_EQ(budgeted.winner, byHand.winner);
    EXPECT_EQ(budgeted.startH, byHand.startH);
}

TEST(MultiStart, AStartWhoseMapDoesNotCompeteWinsOnlyByItsSearch) {
    // OptimizerStart::mapCompetes: a start's map with the least energy of all wins when it
    // competes and is passed over when it does not, while the search from its axis still runs.
    // The map: the search's own result from another axis, zoomed twice (u' = 2u), so every
    // footprint halves and h falls to a quarter, below what any search reaches (the zoom leaves
    // the view; nothing in the multi-start checks coverage of a start's map).
    const BoxOnFloor box;
    Light light;
    light.position = {-30, 25, -25};
    const LightSpace ls(light, box.bounds);
    const Resolution map{400, 400};
    const LightSamples s =
        testing::SamplesFromBoundsMap(*box.renderer, box.readback, ls, box.bounds, map);
    const OptimizerResult searched = OptimizeLightMatrix(s, {0, 0, 1}, map, {});
    const glm::dvec3 tilted = glm::normalize(searched.matrix.p4 + glm::dvec3(0.05, 0.0, 0.0));
    const OptimizerResult other = OptimizeLightMatrix(s, tilted, map, {});
    const LightMatrix zoomed = other.matrix.ThenAffine(glm::dmat3(2, 0, 0, 0, 2, 0, 0, 0, 1));
    ASSERT_NEAR(Energy(zoomed, s), other.h / 4, 1e-9 * other.h);

    // The first start's map does not compete either, so only the zoomed map and the searches do.
    std::vector<OptimizerStart> starts = {{"axis", searched.matrix, false},
                                          {"zoomed", zoomed, true}};
    const MultiStartResult competing = OptimizeFromStarts(s, starts, map);
    ASSERT_EQ(competing.winner, "zoomed");
    ASSERT_TRUE(competing.startMapWon);

    starts[1].mapCompetes = false;
    const MultiStartResult passedOver = OptimizeFromStarts(s, starts, map);
    EXPECT_FALSE(passedOver.startMapWon);
    EXPECT_EQ(passedOver.result.h, std::min(passedOver.searchH[0], passedOver.searchH[1]));
    EXPECT_GT(passedOver.result.h, Energy(zoomed, s));
    EXPECT_EQ(passedOver.startH, competing.startH);    // still reported
    EXPECT_EQ(passedOver.searchH, competing.searchH);  // and its axis still searched
    EXPECT_TRUE(std::isfinite(passedOver.searchH[1]));
}

TEST(MultiStart, PlaneOptimalsMapIsTheOnlyStartThatDoesNotCompete) {
    const BoxOnFloor box;
    Light light;
    light.position = {-30, 25, -25};
    const LightSpace ls(light, box.bounds);
    BaselineContext context;
    context.lightSpace = &ls;
    context.camera = box.camera;
    context.map = {400, 400};
    context.wsBounds = box.bounds;
    context.wsRelevant = box.readback.wsRelevant;
    EXPECT_EQ(StandardStarts(context).size(), 5u);  // no floor plane: no plane-optimal
    context.floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    const std::vector<OptimizerStart> starts = StandardStarts(context);
    ASSERT_EQ(starts.size(), 6u);
    for (const OptimizerStart& start : starts)
        EXPECT_EQ(start.mapCompetes, start.name != "plane-optimal") << start.name;
}

TEST(Optimizer, CollapseGuardRejectsARefinementThatStarvesTheView) {
    // The collapse that prompted the guard, in miniature: a light with a handful of boundary
    // samples (7, from one end of the edge), where the refinement on h alone can shrink those
    // samples' texels by turning the axis until the rest of the view's texels blow up.
    const BoxOnFloor box;
    const RenderBackend& renderer = *box.renderer;
    const Readback& rb = box.readback;
    const Bounds& bounds = box.bounds;
    const Resolution map{400, 400};
    int collapsed = 0;
    for (const glm::dvec3 lightPos :
         {glm::dvec3(-30, 25, -25), glm::dvec3(40, 15, 10), glm::dvec3(5, 60, -5)}) {
        Light light;
        light.position = lightPos;
        const LightSpace ls(light, bounds);
        LightSamples s = testing::SamplesFromBoundsMap(renderer, rb, ls, bounds, map);
        ASSERT_GT(s.lsX.size(), 7u);
        for (auto* v : {&s.lsX, &s.dXdx1, &s.dXdx2, &s.wsX}) v->resize(7);
        s.pixel.resize(7);
        s.edgeNormal.resize(7);
        OptimizerOptions options;
        const OptimizerResult searched = OptimizeLightMatrix(s, {0, 0, 1}, map, options);
        options.refine = true;
        const OptimizerResult unguarded = OptimizeLightMatrix(s, {0, 0, 1}, map, options);
        options.collapseFactor = kCollapseFactor;
        const OptimizerResult guarded = OptimizeLightMatrix(s, {0, 0, 1}, map, options);
        const double start = *RelevantFootprint(searched.matrix, s);
        const double unguardedRatio = *RelevantFootprint(unguarded.matrix, s) / start;
        const double guardedRatio = *RelevantFootprint(guarded.matrix, s) / start;
        std::cout << "[   INFO   ] light (" << lightPos.x << ", " << lightPos.y << ", "
                  << lightPos.z << "): h " << searched.h << " -> refined " << unguarded.h
                  << ", view footprint x" << unguardedRatio << "; guarded h " << guarded.h << ", x"
                  << guardedRatio << "\n";
        EXPECT_LE(guardedRatio, kCollapseFactor);
        EXPECT_LE(guarded.h, searched.h);
        EXPECT_EQ(guarded.refineCollapsed, unguardedRatio > kCollapseFactor);
        if (unguardedRatio > kCollapseFactor) {
            ++collapsed;
            EXPECT_EQ(guarded.matrix.p4, searched.matrix.p4);  // the search's matrix is kept
        } else {
            EXPECT_EQ(guarded.h, unguarded.h);  // the guard changes nothing else
        }
    }
    EXPECT_GE(collapsed, 1);  // the construction does produce a collapse to reject
}

// The walkthrough's readback (report §3's scene at the case's 720²) and lights of both kinds
// around it.
struct WalkthroughFrame {
    Scene scene;
    std::unique_ptr<RenderBackend> renderer;
    Bounds bounds;
    Readback readback;
    std::vector<Light> lights;
};

const WalkthroughFrame& Walkthrough() {
    static const WalkthroughFrame frame = [] {
        WalkthroughFrame f;
        f.scene = cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
        f.renderer = MakeCpuRenderer(f.scene.geometry);
        f.bounds = f.scene.geometry.ComputeBounds();
        f.readback = RenderReadback(*f.renderer, f.scene.camera, f.scene.readback);
        for (const glm::dvec3& p :
             {glm::dvec3(30, 60, -20), glm::dvec3(-70, 40, 60), glm::dvec3(90, 15, 10)}) {
            Light light;
            light.position = p;
            f.lights.push_back(light);
        }
        for (const glm::dvec3& d : {glm::dvec3(0.4, -1, 0.6), glm::dvec3(-1, -0.3, 0.2)}) {
            Light light;
            light.type = Light::Type::kDirectional;
            light.direction = d;
            f.lights.push_back(light);
        }
        return f;
    }();
    return frame;
}

// The light's samples with boundary samples from a map fitted to the scene bounds.
LightSamples SamplesFor(const WalkthroughFrame& f, const LightSpace& ls) {
    return testing::SamplesFromBoundsMap(*f.renderer, f.readback, ls, f.bounds, f.scene.shadowMap);
}

bool AllInFront(const glm::dvec3& p4, const std::vector<glm::dvec3>& points) {
    for (const glm::dvec3& X : points)
        if (!InFront(p4, X)) return false;
    return true;
}

TEST(RelevantHull, FitFromFrameHullVerticesEqualsFitFromAllPoints) {
    const WalkthroughFrame& f = Walkthrough();
    ASSERT_GT(f.readback.wsRelevantHull.size(), 8u);
    int rejected = 0, fitted = 0;
    for (const Light& light : f.lights) {
        const LightSpace ls(light, f.bounds);
        const LightSamples s = SamplesFor(f, ls);
        ASSERT_EQ(s.lsRelevantHull.size(), f.readback.wsRelevantHull.size());
        const RelevantHull fromFrame = *RelevantHull::Of(s.lsRelevantHull, {0, 0, 1});
        const RelevantHull fromAll = *RelevantHull::Of(s.lsRelevant, {0, 0, 1});
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> uni(-1.0, 1.0);
        for (int k = 0; k < 60; ++k) {
            // Axes up to about 80° off the light's centre axis: some see every point, some not.
            const glm::dvec3 p4 = glm::normalize(glm::dvec3(4.0 * uni(rng), 4.0 * uni(rng), 1.0));
            // The in-front decision from the vertices is the decision from all points.
            const bool allInFront = AllInFront(p4, s.lsRelevant);
            ASSERT_EQ(AllInFront(p4, s.lsRelevantHull), allInFront) << "k " << k;
            const auto naive = FitMapToPoints(p4, s.lsRelevant, f.scene.shadowMap, {0.02});
            const auto frame = fromFrame.Fit(p4, f.scene.shadowMap, {0.02});
            const auto all = fromAll.Fit(p4, f.scene.shadowMap, {0.02});
            ASSERT_EQ(naive.has_value(), allInFront);
            ASSERT_EQ(frame.has_value(), allInFront) << "k " << k;
            ASSERT_EQ(all.has_value(), allInFront) << "k " << k;
            if (!allInFront) {
                ++rejected;
                continue;
            }
            ++fitted;
            // Same map up to rounding: every relevant point lands at the same texel position.
            for (std::size_t i = 0; i < s.lsRelevant.size(); i += 37) {
                const glm::dvec2 u = naive->Map(s.lsRelevant[i]);
                ASSERT_NEAR(glm::length(frame->Map(s.lsRelevant[i]) - u), 0.0, 1e-7) << "k " << k;
                ASSERT_NEAR(glm::length(all->Map(s.lsRelevant[i]) - u), 0.0, 1e-7) << "k " << k;
            }
        }
    }
    EXPECT_GT(fitted, 100);
    EXPECT_GT(rejected, 10);
}

TEST(Optimizer, FrameHullPathGivesTheSameMatrixAsAllPointsAndTheNaivePath) {
    const WalkthroughFrame& f = Walkthrough();
    for (const Light& light : f.lights) {
        const LightSpace ls(light, f.bounds);
        const LightSamples s = SamplesFor(f, ls);
        ASSERT_GT(s.lsX.size(), 100u);
        LightSamples allPoints = s;
        allPoints.lsRelevantHull.clear();  // RelevantHull from every relevant point
        OptimizerOptions naiveOptions;
        naiveOptions.hullOnce = false;  // every candidate fitted from every relevant point
        const OptimizerResult frame = OptimizeLightMatrix(s, {0, 0, 1}, f.scene.shadowMap);
        const OptimizerResult all = OptimizeLightMatrix(allPoints, {0, 0, 1}, f.scene.shadowMap);
        const OptimizerResult naive =
            OptimizeLightMatrix(s, {0, 0, 1}, f.scene.shadowMap, naiveOptions);
        EXPECT_EQ(frame.coneGenerators, s.lsRelevantHull.size());
        EXPECT_EQ(all.coneGenerators, s.lsRelevant.size());
        EXPECT_LE(frame.hullVertices, all.hullVertices);
        for (const OptimizerResult* other : {&all, &naive}) {
            EXPECT_EQ(frame.candidatesRejected, other->candidatesRejected);
            ASSERT_EQ(frame.hAfterIteration.size(), other->hAfterIteration.size());
            for (std::size_t i = 0; i < frame.hAfterIteration.size(); ++i)
                EXPECT_NEAR(frame.hAfterIteration[i], other->hAfterIteration[i],
                            1e-9 * other->hAfterIteration[i]);
            for (std::size_t i = 0; i < s.lsRelevant.size(); i += 37) {
                const glm::dvec2 u = other->matrix.Map(s.lsRelevant[i]);
                ASSERT_NEAR(glm::length(frame.matrix.Map(s.lsRelevant[i]) - u), 0.0, 1e-7);
            }
        }
        // The search's early-stopping energy is Energy itself, bit for bit, below the bound.
        EXPECT_EQ(frame.h, Energy(frame.matrix, s));
        EXPECT_EQ(frame.hAfterIteration.back(), frame.h);
        EXPECT_LT(frame.h, frame.hAfterIteration.front());
    }
}

TEST(Optimizer, FloorOnlyViewFitsFromThePlanarHull) {
    // Nothing but the floor in view (a flat 3D hull, see samples.h); the shadow of a box behind
    // the camera falls into the view, so there are boundary samples.
    TriangleMesh scene = testing::FloorQuad(100.0);
    scene.Append(testing::BoxMesh({-2.0, 0.0, 8.0}, {2.0, 8.0, 12.0}));
    const auto renderer = MakeCpuRenderer(scene);
    Camera camera;
    camera.position = {3.0, 4.0, 5.0};
    camera.target = {2.0, 0.0, -1.0};
    camera.resolution = {180, 180};
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    for (const glm::dvec3& p : rb.wsRelevant) ASSERT_EQ(p.y, 0.0);
    ASSERT_GE(rb.wsRelevantHull.size(), 4u);
    ASSERT_LE(rb.wsRelevantHull.size(), 8u);
    Light light;
    light.type = Light::Type::kDirectional;
    light.direction = {0.1, -1.0, -1.3};
    const Bounds bounds = scene.ComputeBounds();
    const LightSpace ls(light, bounds);
    const Resolution mapSize{400, 400};
    const LightSamples s = testing::SamplesFromBoundsMap(*renderer, rb, ls, bounds, mapSize);
    ASSERT_GT(s.lsX.size(), 20u);
    LightSamples allPoints = s;
    allPoints.lsRelevantHull.clear();
    const OptimizerResult frame = OptimizeLightMatrix(s, {0, 0, 1}, mapSize);
    const OptimizerResult all = OptimizeLightMatrix(allPoints, {0, 0, 1}, mapSize);
    EXPECT_EQ(frame.coneGenerators, rb.wsRelevantHull.size());
    EXPECT_EQ(frame.candidatesRejected, all.candidatesRejected);
    ASSERT_EQ(frame.hAfterIteration.size(), all.hAfterIteration.size());
    for (std::size_t i = 0; i < frame.hAfterIteration.size(); ++i)
        EXPECT_NEAR(frame.hAfterIteration[i], all.hAfterIteration[i],
                    1e-9 * all.hAfterIteration[i]);
    for (std::size_t i = 0; i < s.lsRelevant.size(); i += 37) {
        const glm::dvec2 u = all.matrix.Map(s.lsRelevant[i]);
        ASSERT_NEAR(glm::length(frame.matrix.Map(s.lsRelevant[i]) - u), 0.0, 1e-7);
        ASSERT_GE(u.x, -1e-6);
        ASSERT_LE(u.x, 400 + 1e-6);
    }
}

}  // namespace
}  // namespace lexel::spatial
