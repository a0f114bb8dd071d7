#include "lexel/flatland/baselines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/methods.h"
#include "test_scenes.h"

namespace lexel::flatland {
namespace {

// Per-segment spread of footprints: max over segments of (max f / min f − 1).
double PerSegmentSpread(const SamplingPass& pass, const std::vector<double>& f) {
    std::map<int, std::pair<double, double>> range;
    for (std::size_t i = 0; i < f.size(); ++i) {
        auto [it, inserted] = range.try_emplace(pass.samples[i].segment, f[i], f[i]);
        it->second.first = std::min(it->second.first, f[i]);
        it->second.second = std::max(it->second.second, f[i]);
    }
    double spread = 0;
    for (const auto& [segment, r] : range) spread = std::max(spread, r.second / r.first - 1);
    return spread;
}

// Proposition 3 (miner's headlamp): a light on the view plane with its lexel plane parallel to
// the view plane gives a constant footprint on each segment, for arbitrary geometry.
TEST(Baselines, MinersHeadlampIsConstantPerSegment) {
    FlatScene scene = testing::ExampleScene();
    const Vec2 viewPlane{-scene.camera.wsDirection.y(), scene.camera.wsDirection.x()};
    for (double offset : {2.0, 5.0, 11.0}) {
        scene.wsLight = scene.camera.wsPosition + offset * viewPlane;
        const SamplingPass pass = RunSamplingPass(scene, 800);
        const double axis = std::atan2(scene.camera.wsDirection.y(), scene.camera.wsDirection.x());
        const auto f = FootprintsFromScratch(pass, scene.wsLight, axis, scene.lexels);
        ASSERT_TRUE(f.has_value());
        EXPECT_LT(PerSegmentSpread(pass, *f), 1e-9) << "offset " << offset;
        // ...and not constant across segments of different orientation.
        const auto [lo, hi] = std::minmax_element(f->begin(), f->end());
        EXPECT_GT(*hi / *lo - 1, 1e-3);
        // A tilted lexel plane breaks the per-segment constancy.
        const auto tilted = FootprintsFromScratch(pass, scene.wsLight, axis + 0.1, scene.lexels);
        EXPECT_GT(PerSegmentSpread(pass, *tilted), 1e-3);
    }
}

TEST(Baselines, NormalAxisBisectsTheSweep) {
    const FlatScene scene = testing::ExampleScene();
    const SamplingPass pass = RunSamplingPass(scene, 1000);
    double lo = 1e9, hi = -1e9;
    for (const auto& s : pass.samples) {
        const Vec2 d = s.wsPoint - scene.wsLight;
        const double a = std::atan2(d.y(), d.x());
        lo = std::min(lo, a), hi = std::max(hi, a);
    }
    EXPECT_NEAR(NormalAxis(pass).wsAxis, 0.5 * (lo + hi), 1e-12);
}

// Theorem 1's construction by hand for the example floor (test_scenes.h): the view plane through
// (0, 2) with normal (1, −0.25) meets y = 0 at q = (−0.5, 0); the light (−3, 10) to q is (2.5,
// −10), so the lexel plane is atan(2.5/10) = 14.036° from vertical.
TEST(Baselines, PlaneOptimalByHand) {
    const FlatScene scene = testing::ExampleScene();
    const double axis = PlaneOptimalAxis(scene).wsAxis;
    EXPECT_NEAR(LexelPlaneDegFromAxis(axis), std::atan(0.25) * 180 / std::numbers::pi, 1e-12);
}

// Thesis §2.2.3, "Ideal performance": with a point light on the view plane and a single plane,
// the light is directional in post-projective space and PSM gets the lexel plane right.
TEST(Baselines, PsmIsOptimalForALightOnTheViewPlaneOverOnePlane) {
    FlatScene scene = testing::ExampleScene();
    scene.geometry = {{{-50, 0}, {200, 0}}};
    const Vec2 viewPlane{-scene.camera.wsDirection.y(), scene.camera.wsDirection.x()};
    scene.wsLight = scene.camera.wsPosition + 6.0 * viewPlane;
    const CaseReport report =
        RunFlatlandCase(scene, std::vector<std::string>{"psm", "optimal-l1"}, Metric::kL1);
    EXPECT_LT(report.methods[0].stats.worst() / report.methods[0].stats.average - 1, 1e-9);
    EXPECT_NEAR(report.methods[0].stats.average, report.methods[1].stats.average, 1e-9);
}

// PSM in general is no optimum: on the example it loses to the L1 optimum.
TEST(Baselines, PsmIsWorseThanOptimalOnTheExample) {
    const FlatScene scene = testing::ExampleScene();
    const CaseReport report =
        RunFlatlandCase(scene, std::vector<std::string>{"psm", "optimal-l1"}, Metric::kL1);
    EXPECT_GT(report.methods[0].stats.average, report.methods[1].stats.average * 1.05);
}

}  // namespace
}  // namespace lexel::flatland
