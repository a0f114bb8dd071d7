// The readback derivatives of Appendix A against the exact screen → surface map, the
// discontinuity rejection, and the energy h of eq. (6) against a hand-computed sample.
#include "lexel/spatial/samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "lexel/cases/spatial_case.h"
#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/convex_hull_3d.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

Camera ReadbackCamera() {
    Camera c;
    c.position = {0.5, 1.7, 9.0};
    c.target = {0.0, 0.5, 0.0};
    c.resolution = {180, 180};
    return c;
}

// The exact world point under screen point xs on the plane of triangle t.
glm::dvec3 OnTrianglePlane(const TriangleMesh& mesh, std::int32_t t, const Camera& camera,
                           glm::dvec2 xs) {
    const glm::dvec3 n = mesh.FaceNormal(t);
    const glm::dvec3 v0(mesh.positions[mesh.triangles[t][0]]);
    const glm::dvec3 d = camera.RayDirection(xs, camera.resolution);
    return camera.position + (glm::dot(n, v0 - camera.position) / glm::dot(n, d)) * d;
}

TEST(Readback, DepthDerivativesAreExactOnPlanesAndDiscontinuitiesAreRejected) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = ReadbackCamera();
    const Readback rb = MakeReadback(*renderer, camera, camera.resolution);
    int smooth = 0, covered = 0, rejectedAtEdges = 0;
    const int w = 180;
    for (int y = 1; y < 179; ++y)
        for (int x = 1; x < 179; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (!rb.buffer.Covered(i)) continue;
            ++covered;
            // A pixel whose 4-neighbours see another plane must be rejected when the depth jumps.
            const glm::dvec3 n = scene.FaceNormal(rb.buffer.triangle[i]);
            bool otherPlane = false;
            for (std::size_t j : {i - 1, i + 1, i - w, i + w})
                otherPlane = otherPlane || !rb.buffer.Covered(j) ||
                             glm::dot(scene.FaceNormal(rb.buffer.triangle[j]), n) < 0.5;
            if (!rb.smooth[i]) {
                rejectedAtEdges += otherPlane;
                continue;
            }
            ++smooth;
            ASSERT_FALSE(otherPlane) << "pixel " << x << "," << y << " straddles an edge";
            const double eps = 1e-3;
            const glm::dvec2 c(x + 0.5, y + 0.5);
            const std::int32_t t = rb.buffer.triangle[i];
            const glm::dvec3 exact1 = (OnTrianglePlane(scene, t, camera, c + glm::dvec2(eps, 0)) -
                                       OnTrianglePlane(scene, t, camera, c - glm::dvec2(eps, 0))) /
                                      (2 * eps);
            const glm::dvec3 exact2 = (OnTrianglePlane(scene, t, camera, c + glm::dvec2(0, eps)) -
                                       OnTrianglePlane(scene, t, camera, c - glm::dvec2(0, eps))) /
                                      (2 * eps);
            ASSERT_NEAR(glm::length(rb.dWdx1[i] - exact1), 0.0, 1e-5 * glm::length(exact1))
                << "pixel " << x << "," << y;
            ASSERT_NEAR(glm::length(rb.dWdx2[i] - exact2), 0.0, 1e-5 * glm::length(exact2))
                << "pixel " << x << "," << y;
        }
    EXPECT_GT(smooth, covered * 9 / 10);
    EXPECT_GT(rejectedAtEdges, 100);
    EXPECT_EQ(rb.wsRelevant.size(), static_cast<std::size_t>(std::count_if(
                                        rb.buffer.triangle.begin(), rb.buffer.triangle.end(),
                                        [](std::int32_t t) { return t >= 0; })));
}

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
    const Camera camera = ReadbackCamera();
    const Readback rb = MakeReadback(*renderer, camera, camera.resolution);
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

// Every point lies in the hull of `vertices` up to `tolerance` (support functions along random
// directions: conv(V) ⊇ P iff max over V of d·v ≥ max over P of d·p for every d).
void ExpectHullContains(const std::vector<glm::dvec3>& vertices,
                        const std::vector<glm::dvec3>& points, double tolerance) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 1000; ++trial) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
        double hullMax = -std::numeric_limits<double>::infinity();
        for (const glm::dvec3& v : vertices) hullMax = std::max(hullMax, glm::dot(d, v));
        double allMax = -std::numeric_limits<double>::infinity();
        for (const glm::dvec3& p : points) allMax = std::max(allMax, glm::dot(d, p));
        ASSERT_GE(hullMax, allMax - tolerance) << "trial " << trial;
    }
}

std::set<std::vector<double>> AsSet(const std::vector<glm::dvec3>& points) {
    std::set<std::vector<double>> out;
    for (const glm::dvec3& p : points) out.insert({p.x, p.y, p.z});
    return out;
}

TEST(RelevantHullVertices, ImagePrefilterKeepsTheHullOfAllRelevantPoints) {
    // The walkthrough (report §3): 36 objects on a floor, 17,244 relevant points at 180².
    const Scene scene = cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
    const auto renderer = MakeCpuRenderer(scene.geometry);
    const Readback rb = MakeReadback(*renderer, scene.camera, scene.readback);
    ASSERT_GT(rb.wsRelevant.size(), 15000u);
    // The readback's hull equals Qhull's hull of every relevant point (no image pre-filter).
    std::vector<Eigen::Vector3d> all;
    for (const glm::dvec3& p : rb.wsRelevant) all.emplace_back(p.x, p.y, p.z);
    std::vector<glm::dvec3> reference;
    for (std::size_t i : ConvexHullVertices3D(all)) reference.push_back(rb.wsRelevant[i]);
    EXPECT_EQ(AsSet(rb.wsRelevantHull), AsSet(reference));
    EXPECT_GE(rb.wsRelevantHull.size(), 8u);
    EXPECT_LT(rb.wsRelevantHull.size(), 200u);
    EXPECT_GE(rb.relevantHullMs, 0.0);
    // Its vertices are relevant points, and it contains all of them.
    const std::set<std::vector<double>> relevant = AsSet(rb.wsRelevant);
    for (const glm::dvec3& v : rb.wsRelevantHull)
        EXPECT_TRUE(relevant.count({v.x, v.y, v.z})) << v.x << " " << v.y << " " << v.z;
    ExpectHullContains(rb.wsRelevantHull, rb.wsRelevant,
                       1e-12 * scene.geometry.ComputeBounds().Radius());
}

TEST(RelevantHullVertices, FloorOnlyViewGivesTheCornersOfTheVisibleFloor) {
    // A camera that sees nothing but the floor: every relevant point is coplanar, where Qhull
    // alone would fail ("initial simplex is flat").
    const TriangleMesh scene = testing::FloorQuad(100.0);
    const auto renderer = MakeCpuRenderer(scene);
    Camera camera;
    camera.position = {3.0, 4.0, 5.0};
    camera.target = {2.0, 0.0, -1.0};
    camera.resolution = {180, 180};
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    const Readback rb = MakeReadback(*renderer, camera, camera.resolution);
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    ASSERT_EQ(rb.wsRelevant.size(), 180u * 180u);
    for (const glm::dvec3& p : rb.wsRelevant) ASSERT_EQ(p.y, 0.0);
    // The visible floor is the trapezoid of the image's four corner pixels; points along its
    // straight sides are collinear up to rounding, so a few of them may stay as vertices.
    const std::set<std::vector<double>> hull = AsSet(rb.wsRelevantHull),
                                        relevant = AsSet(rb.wsRelevant);
    for (const std::size_t corner :
         {std::size_t{0}, std::size_t{179}, std::size_t{180 * 179}, std::size_t{180 * 180 - 1}}) {
        const glm::dvec3& p = rb.buffer.wsPosition[corner];
        EXPECT_TRUE(hull.count({p.x, p.y, p.z})) << "corner pixel " << corner;
    }
    EXPECT_LE(hull.size(), 8u);
    for (const std::vector<double>& v : hull) EXPECT_TRUE(relevant.count(v));
    ExpectHullContains(rb.wsRelevantHull, rb.wsRelevant, 1e-12 * 100.0);
}

TEST(BoundedEnergy, EqualsEnergyBitForBitBelowTheBound) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = ReadbackCamera();
    const Readback rb = MakeReadback(*renderer, camera, camera.resolution);
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
