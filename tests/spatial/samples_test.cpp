// The optimization samples and the energy h of eq. (6): boundary samples on the analytic shadow
// edge, h against a hand-computed sample, the bounded search energy against Energy.
#include "lexel/spatial/samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/convex_hull_3d.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

TEST(Energy, SampleBadnessIsTheInverseJacobianFrobeniusNorm) {
    // u = (2 X1/X3, 3 X2/X3) with X = (x¹, x², 1) + small depth: J = diag(2, 3) at X3 = 1, so
    // ||J⁻¹||² = 1/4 + 1/9.
    LightMatrix m;
    m.p1 = {2, 0, 0};
    m.p2 = {0, 3, 0};
    m.p4 = {0, 0, 1};
    const glm::dvec3 lsX(0.3, -0.2, 1.0), dX1(1, 0, 0), dX2(0, 1, 0);
    EXPECT_NEAR(SampleBadness(m, lsX, dX1, dX2), 1.0 / 4 + 1.0 / 9, 1e-15);
    // Behind the light's plane: unbounded, never NaN.
    EXPECT_TRUE(std::isinf(SampleBadness(m, {0.3, 0.2, -1.0}, dX1, dX2)));
    // A sample whose screen directions are parallel in the map: singular J, +inf.
    EXPECT_TRUE(std::isinf(SampleBadness(m, lsX, dX1, dX1)));
    LightSamples s;
    s.lsX = {lsX, lsX};
    s.dXdx1 = {dX1, 2.0 * dX1};
    s.dXdx2 = {dX2, dX2};
    EXPECT_NEAR(Energy(m, s), (1.0 / 4 + 1.0 / 9) + (1.0 / 16 + 1.0 / 9), 1e-15);
}

TEST(LightSamples, BoundarySamplesSitOnTheShadowEdge) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    Light light;
    light.position = {-20.0, 30.0, -10.0};
    const Bounds bounds = scene.ComputeBounds();
    const LightSpace ls(light, bounds);
    const LightSamples s = testing::SamplesFromBoundsMap(*renderer, rb, ls, bounds, {1024, 1024});
    ASSERT_GT(s.lsX.size(), 50u);
    EXPECT_EQ(s.lsRelevant.size(), rb.wsRelevant.size());
    // Every boundary sample on the floor is within a few readback pixels' footprint of the
    // analytic shadow edge: the segment to the light grazes the box.
    for (std::size_t k = 0; k < s.lsX.size(); ++k) {
        const std::size_t i = s.pixel[k];
        const glm::dvec3 ws = rb.buffer.wsPosition[i];
        if (std::abs(ws.y) > 1e-9) continue;
        const double step = 2.0 * std::max(glm::length(rb.dWdx1[i]), glm::length(rb.dWdx2[i]));
        bool mixed = false;
        const bool here = testing::SegmentHitsBox(ws, light.position, {-1, 0, -1}, {1, 1.5, 1});
        for (const glm::dvec3 d : {glm::dvec3(step, 0, 0), glm::dvec3(-step, 0, 0),
                                   glm::dvec3(0, 0, step), glm::dvec3(0, 0, -step)})
            mixed = mixed || testing::SegmentHitsBox(ws + d, light.position, {-1, 0, -1},
                                                     {1, 1.5, 1}) != here;
        EXPECT_TRUE(mixed) << "sample at " << ws.x << "," << ws.z;
    }
}
TEST(BoundedEnergy, EqualsEnergyBitForBitBelowTheBound) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    Light light;
    light.position = {-20.0, 30.0, -10.0};
    const LightSpace ls(light, scene.ComputeBounds());
    const Resolution mapRes{400, 400};
    const LightSamples s =
        testing::SamplesFromBoundsMap(*renderer, rb, ls, scene.ComputeBounds(), mapRes);
    ASSERT_GT(s.lsX.size(), 130u);  // more than two blocks of 64
    const BoundedEnergy energy(s);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    int finite = 0, behind = 0;
    for (int k = 0; k < 200; ++k) {
        // Random light matrices, some with a sample not in front of p4 (h = +inf).
        LightMatrix m;
        m.p4 = glm::normalize(glm::dvec3(uni(rng), uni(rng), 1.0));
        if (k % 5 == 0)  // one sample on the plane p4·X = 0: not in front
            m.p4 = glm::normalize(glm::cross(s.lsX[(k * 7) % s.lsX.size()], m.p4));
        m.p1 = glm::dvec3(uni(rng), uni(rng), uni(rng)) + 200.0 * m.p4;
        m.p2 = glm::dvec3(uni(rng), uni(rng), uni(rng)) + 200.0 * m.p4;
        const double h = Energy(m, s);
        EXPECT_EQ(energy(m), h) << "k " << k;  // the same bits
        if (std::isinf(h)) {
            ++behind;
            EXPECT_GE(energy(m, 1.0), 1.0);  // may stop before the sample that is not in front
            continue;
        }
        ++finite;
        EXPECT_EQ(energy(m, std::nextafter(h, 2.0 * h)), h);  // just above: the full sum
        for (double fraction : {0.999999, 0.5, 1e-3}) {
            const double bound = fraction * h;
            const double partial = energy(m, bound);
            EXPECT_GE(partial, bound);  // stopped at the bound, never below it
            EXPECT_LE(partial, h);
        }
        EXPECT_GE(energy(m, h), h);
    }
    EXPECT_GT(finite, 50);
    EXPECT_GT(behind, 5);
}

}  // namespace
}  // namespace lexel::spatial
