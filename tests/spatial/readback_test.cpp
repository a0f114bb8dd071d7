// The readback of Appendix A: derivatives against the exact screen → surface map, the
// discontinuity rejection, the per-frame hull, and a readback built from a depth buffer alone.
#include "lexel/spatial/readback.h"

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
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
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
    // The walkthrough (report §3): 36 objects on a floor, at the case's 720² readback (17,244
    // relevant points at the report's 180²).
    const Scene scene = cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
    const auto renderer = MakeCpuRenderer(scene.geometry);
    const Readback rb = RenderReadback(*renderer, scene.camera, scene.readback);
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
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
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

// A renderer with only a depth buffer: its float window depths and Q give the world points to
// float precision, and the readback built from them matches the exact one's derivatives.
TEST(Readback, FromADepthBufferAloneMatchesTheExactPass) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(camera.resolution);
    const Readback exact = RenderReadback(*renderer, camera, camera.resolution);
    std::vector<float> depth(exact.buffer.windowDepth.begin(), exact.buffer.windowDepth.end());
    const Readback fromDepth = MakeReadback(
        CameraBufferFromDepth(camera.resolution, depth, screenFromWorld), screenFromWorld);

    ASSERT_EQ(fromDepth.wsRelevant.size(), exact.wsRelevant.size());
    double worstPoint = 0.0, worstDerivative = 0.0;
    int bothSmooth = 0, exactSmooth = 0;
    for (std::size_t i = 0; i < camera.resolution.Count(); ++i) {
        ASSERT_EQ(fromDepth.buffer.Covered(i), exact.buffer.Covered(i)) << "pixel " << i;
        if (!exact.buffer.Covered(i)) continue;
        const double scale = glm::length(exact.buffer.wsPosition[i] - camera.position);
        worstPoint = std::max(
            worstPoint,
            glm::length(fromDepth.buffer.wsPosition[i] - exact.buffer.wsPosition[i]) / scale);
        exactSmooth += exact.smooth[i];
        if (!exact.smooth[i] || !fromDepth.smooth[i]) continue;
        ++bothSmooth;
        worstDerivative =
            std::max(worstDerivative, glm::length(fromDepth.dWdx1[i] - exact.dWdx1[i]) /
                                          glm::length(exact.dWdx1[i]));
    }
    // Float window depth carries ~6e-8 relative error, amplified by 1/(1 - x³) near the far end
    // of the depth range; the central differences divide it by the per-pixel depth step.
    EXPECT_LT(worstPoint, 5e-5);  // observed 6.6e-6
    // Float depth noise could fail the smoothness test on far, nearly flat pixels (none here).
    EXPECT_GT(bothSmooth, 0.95 * exactSmooth) << bothSmooth << " of " << exactSmooth;
    EXPECT_LT(worstDerivative, 5e-3);  // observed 2.6e-4
    std::cout << "worst point " << worstPoint << ", derivative " << worstDerivative << ", smooth "
              << bothSmooth << "/" << exactSmooth << "\n";
    // The depth-only hull (no prefilter: every covered pixel has its own id) has the support
    // function of the exact points, up to the float error of the points themselves.
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    for (int k = 0; k < 200; ++k) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
        double exactMax = -1e300, hullMax = -1e300;
        for (const glm::dvec3& x : exact.wsRelevant) exactMax = std::max(exactMax, glm::dot(d, x));
        for (const glm::dvec3& v : fromDepth.wsRelevantHull)
            hullMax = std::max(hullMax, glm::dot(d, v));
        EXPECT_NEAR(hullMax, exactMax, 1e-3) << "direction " << k;
    }
}

TEST(Readback, DepthBufferOfTheWrongSizeIsRefused) {
    const Camera camera = testing::ReadbackCamera();
    const std::vector<float> depth(10, 0.5f);
    EXPECT_THROW(
        CameraBufferFromDepth(camera.resolution, depth, camera.ScreenFromWorld(camera.resolution)),
        std::invalid_argument);
}

}  // namespace
}  // namespace lexel::spatial
