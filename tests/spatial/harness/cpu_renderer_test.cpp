// The CPU backend against closed forms: exact world points, projective round trips, no acne on a
// lit plane, and shadows that agree with an analytic box occluder.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/light_matrix.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

Camera TestCamera(Resolution res) {
    Camera c;
    c.position = {0.0, 1.7, 12.0};
    c.target = {0.0, 0.0, 0.0};
    c.resolution = res;
    c.nearPlane = 0.1;
    c.farPlane = 100.0;
    return c;
}

LightMatrix FitToCorners(const LightSpace& ls, const Bounds& b, Resolution map) {
    std::vector<glm::dvec3> pts;
    for (const auto& c : b.Corners()) pts.push_back(ls.ToLight(c));
    return *FitMapToPoints({0, 0, 1}, pts, map);
}

TEST(TriangleMesh, BoxIsClosedAndOutward) {
    const TriangleMesh box = testing::BoxMesh({-1, -2, -3}, {1, 2, 3});
    double volume = 0.0;  // divergence theorem: Σ a·(b×c)/6 over outward triangles
    for (const auto& t : box.triangles)
        volume +=
            glm::dot(glm::dvec3(box.positions[t[0]]),
                     glm::cross(glm::dvec3(box.positions[t[1]]), glm::dvec3(box.positions[t[2]]))) /
            6.0;
    EXPECT_NEAR(volume, 2.0 * 4.0 * 6.0, 1e-12);
}

TEST(CpuRenderer, CameraPointsLieOnTheFloorAndProjectBackToTheirPixel) {
    const TriangleMesh floor = testing::FloorQuad(50.0);
    const auto renderer = MakeCpuRenderer(floor);
    const Camera camera = TestCamera({160, 120});
    const CameraBuffer frame = renderer->RenderCamera(camera, camera.resolution);
    const glm::dmat4 q = camera.ScreenFromWorld(camera.resolution);
    int covered = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * 160 + x;
            if (!frame.Covered(i)) continue;
            ++covered;
            const glm::dvec3& ws = frame.wsPosition[i];
            ASSERT_NEAR(ws.y, 0.0, 1e-9) << "pixel " << x << "," << y;
            const glm::dvec4 h = q * glm::dvec4(ws, 1.0);
            ASSERT_NEAR(h.x / h.w, x + 0.5, 1e-7);
            ASSERT_NEAR(h.y / h.w, y + 0.5, 1e-7);
            ASSERT_NEAR(frame.wsNormal[i].y, 1.0, 1e-12);
        }
    // The floor's far edge z = -50 is parallel to the image rows; everything below it is floor.
    const glm::dvec4 farEdge = q * glm::dvec4(0.0, 0.0, -50.0, 1.0);
    EXPECT_NEAR(covered, 160.0 * (120.0 - farEdge.y / farEdge.w), 160.0);
}

TEST(CpuRenderer, SharedEdgesLeaveNoHoles) {
    // A camera looking straight down on a quad larger than the view: every pixel covered once.
    const TriangleMesh floor = testing::FloorQuad(10.0);
    const auto renderer = MakeCpuRenderer(floor);
    Camera camera = TestCamera({101, 77});
    camera.position = {0.3, 5.0, 0.2};
    camera.target = {0.3, 0.0, 0.2};
    camera.up = {0.0, 0.0, -1.0};
    const CameraBuffer frame = renderer->RenderCamera(camera, camera.resolution);
    for (std::size_t i = 0; i < frame.triangle.size(); ++i) ASSERT_TRUE(frame.Covered(i)) << i;
}

TEST(LightMatrix, WorldToMapToWorldRoundTrip) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    Bounds bounds;
    bounds.Add({-5, 0, -5});
    bounds.Add({5, 3, 5});
    for (int trial = 0; trial < 200; ++trial) {
        Light light;
        if (trial % 2) {
            light.type = Light::Type::kDirectional;
            light.direction = {uni(rng), -1.0, uni(rng)};
        } else {
            light.position = {20 * uni(rng), 10 + 20 * std::abs(uni(rng)), 20 * uni(rng)};
        }
        const LightSpace ls(light, bounds);
        LightMatrix m = FitToCorners(ls, bounds, {400, 300});
        // Tilt the optical axis a little and re-fit, so the test covers projective warps.
        const glm::dvec3 p4 = glm::normalize(glm::dvec3(0.1 * uni(rng), 0.1 * uni(rng), 1.0));
        std::vector<glm::dvec3> pts;
        for (const auto& c : bounds.Corners()) pts.push_back(ls.ToLight(c));
        if (auto tilted = FitMapToPoints(p4, pts, {400, 300})) m = *tilted;
        for (int k = 0; k < 20; ++k) {
            const glm::dvec3 ws(5 * uni(rng), 1.5 + 1.5 * uni(rng), 5 * uni(rng));
            const glm::dvec3 lsX = ls.ToLight(ws);
            ASSERT_TRUE(InFront(m.p4, lsX));
            const glm::dvec2 u = m.Map(lsX);
            EXPECT_GE(u.x, -1e-6);
            EXPECT_LE(u.x, 400 + 1e-6);
            const glm::dvec3 back = ls.PointAtDepth(m.Unmap(u), ls.Depth(ws));
            ASSERT_NEAR(glm::length(back - ws), 0.0, 1e-9 * (1.0 + ls.Depth(ws)))
                << "trial " << trial << " point " << k;
        }
    }
}

TEST(CpuRenderer, LitPlaneHasNoAcneAtAnyAngle) {
    const TriangleMesh floor = testing::FloorQuad(20.0);
    const auto renderer = MakeCpuRenderer(floor);
    const Camera camera = TestCamera({200, 150});
    const CameraBuffer frame = renderer->RenderCamera(camera, camera.resolution);
    const Bounds bounds = floor.ComputeBounds();
    for (double elevationDeg : {89.0, 60.0, 30.0, 10.0, 3.0}) {
        for (int kind = 0; kind < 2; ++kind) {
            Light light;
            const double e = glm::radians(elevationDeg);
            const glm::dvec3 toLight(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
            if (kind == 0) {
                light.position = 100.0 * toLight;
            } else {
                light.type = Light::Type::kDirectional;
                light.direction = -toLight;
            }
            const LightSpace ls(light, bounds);
            for (Resolution mapRes : {Resolution{16, 16}, Resolution{400, 400}}) {
                const ShadowMap map =
                    renderer->RenderShadowMap(ls, FitToCorners(ls, bounds, mapRes), mapRes);
                const std::vector<Shade> shades = renderer->ShadePixels(frame, ls, map);
                int shadowed = 0, lit = 0;
                for (Shade s : shades) {
                    shadowed += s == Shade::kShadowed;
                    lit += s == Shade::kLit;
                }
                EXPECT_EQ(shadowed, 0)
                    << "elevation " << elevationDeg << " kind " << kind << " map " << mapRes.width;
                EXPECT_GT(lit, 10000);
            }
        }
    }
}

TEST(CpuRenderer, BoxShadowMatchesTheAnalyticOccluder) {
    TriangleMesh scene = testing::FloorQuad(20.0);
    const glm::dvec3 boxLo(-1.0, 0.0, -1.0), boxHi(1.0, 2.0, 1.0);
    scene.Append(testing::BoxMesh(boxLo, boxHi));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = TestCamera({300, 225});
    const CameraBuffer frame = renderer->RenderCamera(camera, camera.resolution);
    Light light;
    light.position = {-30.0, 20.0, -25.0};
    const Bounds bounds = scene.ComputeBounds();
    const LightSpace ls(light, bounds);
    const Resolution mapRes{2048, 2048};
    const ShadowMap map = renderer->RenderShadowMap(ls, FitToCorners(ls, bounds, mapRes), mapRes);
    const std::vector<Shade> shades = renderer->ShadePixels(frame, ls, map);
    int floorPixels = 0, truthShadowed = 0, wrong = 0;
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!frame.Covered(i) || std::abs(frame.wsPosition[i].y) > 1e-9) continue;
        ++floorPixels;
        const bool truth =
            testing::SegmentHitsBox(frame.wsPosition[i], light.position, boxLo, boxHi);
        truthShadowed += truth;
        wrong += truth != (shades[i] == Shade::kShadowed);
    }
    EXPECT_GT(truthShadowed, 500);
    std::cout << "box shadow: " << wrong << " of " << truthShadowed << " shadowed pixels differ\n";
    // Only pixels within a texel of the shadow's edge may differ.
    EXPECT_LE(wrong, truthShadowed / 50) << "of " << floorPixels << " floor pixels";
}

}  // namespace
}  // namespace lexel::spatial
