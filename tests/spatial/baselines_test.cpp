// Tests of the shadow-map baselines (spatial/baselines.h): a 40 × 40 floor with objects up to 3
// units high, the camera 1.7 above it looking across, relevant points = camera rays that hit the
// floor (computed analytically: there is no renderer yet).
#include "lexel/spatial/baselines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial {
namespace {

// How far outside [0, W] × [0, H] a relevant point may map (texels): the baselines' contract
// (baselines.h).
constexpr double kMapTolTexels = 1e-6;

Bounds FloorBounds() {
    Bounds b;
    b.Add({-20.0, 0.0, -20.0});
    b.Add({20.0, 3.0, 20.0});
    return b;
}

// Camera 1.7 above the floor, looking across it and slightly down.
Scene MakeScene() {
    Scene scene;
    scene.name = "baselines";
    scene.camera.position = {0.0, 1.7, 15.0};
    scene.camera.target = {0.0, 0.2, -10.0};
    scene.camera.fovYDeg = 60.0;
    scene.camera.nearPlane = 0.1;
    scene.camera.farPlane = 100.0;
    scene.camera.resolution = {750, 750};
    scene.shadowMap = {400, 400};
    scene.floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    return scene;
}

// Camera looking horizontally along -z from (0, 1.7, 10): the view direction is exactly (0, 0, -1).
Scene MakeLevelScene() {
    Scene scene = MakeScene();
    scene.camera.position = {0.0, 1.7, 10.0};
    scene.camera.target = {0.0, 1.7, -10.0};
    return scene;
}

// Where the camera ray through screen point xs (pixels of the camera resolution) meets y = 0.
glm::dvec3 FloorHit(const Camera& camera, glm::dvec2 xs) {
    const glm::dvec3 d = camera.RayDirection(xs, camera.resolution);
    return camera.position + (-camera.position.y / d.y) * d;
}

// Floor points seen through a grid × grid lattice of pixels: in front of the floor, within the
// 40 × 40 square, at view depth in [near, far] (RayDirection has unit length along the view axis,
// so the ray parameter is the view depth).
std::vector<glm::dvec3> RelevantFloorPoints(const Camera& camera, int grid = 40) {
    std::vector<glm::dvec3> out;
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            const glm::dvec2 xs((i + 0.5) * camera.resolution.width / grid,
                                (j + 0.5) * camera.resolution.height / grid);
            const glm::dvec3 d = camera.RayDirection(xs, camera.resolution);
            if (!(d.y < 0.0)) continue;
            const double t = -camera.position.y / d.y;
            if (t < camera.nearPlane || t > camera.farPlane) continue;
            glm::dvec3 x = camera.position + t * d;
            x.y = 0.0;  // exactly on the floor plane
            if (std::abs(x.x) <= 20.0 && std::abs(x.z) <= 20.0) out.push_back(x);
        }
    return out;
}

std::string Describe(const Light& light) {
    std::ostringstream s;
    const glm::dvec3 v = light.type == Light::Type::kPoint ? light.position : light.direction;
    s << (light.type == Light::Type::kPoint ? "point " : "directional ") << "(" << v.x << ", "
      << v.y << ", " << v.z << ")";
    return s.str();
}

// Independent of the library's own check: every relevant point in front and inside the map.
::testing::AssertionResult Valid(const LightMatrix& m, const LightSpace& ls,
                                 const std::vector<glm::dvec3>& wsRelevant, Resolution map) {
    for (const glm::dvec3& p : {m.p1, m.p2, m.p4})
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return ::testing::AssertionFailure() << "non-finite matrix";
    for (const glm::dvec3& x : wsRelevant) {
        const glm::dvec3 X = ls.ToLight(x);
        if (!InFront(m.p4, X))
            return ::testing::AssertionFailure()
                   << "point (" << x.x << ", " << x.y << ", " << x.z << ") behind p4";
        const glm::dvec2 u = m.Map(X);
        if (!(u.x >= -kMapTolTexels && u.x <= map.width + kMapTolTexels && u.y >= -kMapTolTexels &&
              u.y <= map.height + kMapTolTexels))
            return ::testing::AssertionFailure() << "point maps to (" << u.x << ", " << u.y << ")";
    }
    return ::testing::AssertionSuccess();
}

// Area of the map rectangle [0, W] × [0, H] on the plane p4·X = 1 (light-space units²).
double PlaneArea(const LightMatrix& m, Resolution map) {
    const glm::dvec3 a = m.Unmap({0.0, 0.0});
    const glm::dvec3 b = m.Unmap({double(map.width), 0.0});
    const glm::dvec3 c = m.Unmap({0.0, double(map.height)});
    return glm::length(glm::cross(b - a, c - a));
}

// Point lights uniformly on the upper hemisphere of radius 100 around the floor centre, then
// directional lights shining down from uniform upper-hemisphere directions.
std::vector<Light> SweepLights(std::uint64_t seed, int points, int directionals) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto hemisphere = [&]() {
        const double y = unit(rng), phi = 2.0 * std::numbers::pi * unit(rng);
        const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
        return glm::dvec3(r * std::cos(phi), y, r * std::sin(phi));
    };
    std::vector<Light> lights;
    for (int i = 0; i < points; ++i) {
        Light l;
        l.type = Light::Type::kPoint;
        l.position = 100.0 * hemisphere();
        lights.push_back(l);
    }
    for (int i = 0; i < directionals; ++i) {
        Light l;
        l.type = Light::Type::kDirectional;
        l.direction = -hemisphere();
        lights.push_back(l);
    }
    return lights;
}

using Method = LightMatrix (*)(const BaselineContext&, BaselineDiagnostics*);
const std::vector<std::pair<std::string, Method>> kMethods = {
    {"normal", &NormalLightMatrix},
    {"focused", &FocusedLightMatrix},
    {"lispsm", &LispsmLightMatrix},
    {"psm", &PsmLightMatrix},
    {"plane-optimal", &PlaneOptimalLightMatrix},
    {"lispsm-tight", &LispsmTightLightMatrix},
    {"lispsm-engine", &LispsmEngineLightMatrix}};

Light Directional(glm::dvec3 direction) {
    Light l;
    l.type = Light::Type::kDirectional;
    l.direction = glm::normalize(direction);
    return l;
}

Light Point(glm::dvec3 position) {
    Light l;
    l.type = Light::Type::kPoint;
    l.position = position;
    return l;
}

TEST(Baselines, EveryMethodIsValidOverTheHemisphereSweep) {
    const std::uint64_t seed = 7;
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    ASSERT_GT(relevant.size(), 300u);
    std::map<std::string, int> fallbacks;
    std::map<std::string, std::string> firstReason;
    for (const Light& light : SweepLights(seed, 300, 20)) {
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        for (const auto& [name, method] : kMethods) {
            BaselineDiagnostics diagnostics;
            const LightMatrix m = method(context, &diagnostics);
            EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap))
                << name << ", seed " << seed << ", light " << Describe(light);
            if (!diagnostics.fallback.empty()) {
                ++fallbacks[name];
                if (firstReason[name].empty()) firstReason[name] = diagnostics.fallback;
            }
        }
    }
    // The counts the report quotes; printed so a change in behaviour shows in the log.
    for (const auto& [name, method] : kMethods)
        std::cout << "[ fallbacks ] " << name << ": " << fallbacks[name] << " of 320"
                  << (firstReason[name].empty() ? "" : " (first: " + firstReason[name] + ")")
                  << "\n";
}

TEST(NormalBaseline, BoundsCornersTouchAllFourMapSides) {
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    for (const Light& light : SweepLights(11, 20, 5)) {
        const LightSpace ls(light, bounds);
        BaselineDiagnostics diagnostics;
        const LightMatrix m =
            NormalLightMatrix(MakeBaselineContext(scene, ls, bounds, relevant), &diagnostics);
        ASSERT_TRUE(diagnostics.fallback.empty()) << diagnostics.fallback;
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::dvec3& x : bounds.Corners()) {
            const glm::dvec2 u = m.Map(ls.ToLight(x));
            lo = glm::min(lo, u);
            hi = glm::max(hi, u);
        }
        // The min-area rectangle touches the hull on all four sides (texels).
        EXPECT_NEAR(lo.x, 0.0, 1e-6) << Describe(light);
        EXPECT_NEAR(hi.x, scene.shadowMap.width, 1e-6) << Describe(light);
        EXPECT_NEAR(lo.y, 0.0, 1e-6) << Describe(light);
        EXPECT_NEAR(hi.y, scene.shadowMap.height, 1e-6) << Describe(light);
    }
}

TEST(FocusedBaseline, SmallerThanNormalAndCoversEveryRelevantPoint) {
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    int strictlySmaller = 0;
    for (const Light& light : SweepLights(13, 60, 10)) {
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        const LightMatrix normal = NormalLightMatrix(context);
        BaselineDiagnostics diagnostics;
        const LightMatrix focused = FocusedLightMatrix(context, &diagnostics);
        EXPECT_TRUE(diagnostics.fallback.empty()) << diagnostics.fallback;
        EXPECT_NEAR(glm::length(focused.p4 - normal.p4), 0.0, 1e-15);
        const double focusedArea = PlaneArea(focused, scene.shadowMap);
        const double normalArea = PlaneArea(normal, scene.shadowMap);
        EXPECT_LE(focusedArea, normalArea * (1.0 + 1e-9)) << Describe(light);
        if (focusedArea < 0.99 * normalArea) ++strictlySmaller;
        EXPECT_TRUE(Valid(focused, ls, relevant, scene.shadowMap)) << Describe(light);
    }
    // The camera sees only part of the floor, so focusing must pay off for most lights.
    EXPECT_GT(strictlySmaller, 50);
}

TEST(FocusedBaseline, FrustumInsideBoundsGivesTheFrustumRectangle) {
    const Scene scene = MakeScene();
    Bounds huge;  // contains the whole view frustum (far plane 100 from z = 15)
    huge.Add({-300.0, -300.0, -300.0});
    huge.Add({300.0, 300.0, 300.0});
    for (const Light& light :
         {Directional({0.3, -1.0, 0.2}), Point({0.0, 2000.0, 100.0}), Point({900.0, 800.0, 0.0})}) {
        const LightSpace ls(light, huge);
        BaselineDiagnostics diagnostics;
        const LightMatrix focused =
            FocusedLightMatrix(MakeBaselineContext(scene, ls, huge, {}), &diagnostics);
        EXPECT_TRUE(diagnostics.fallback.empty()) << diagnostics.fallback;
        std::vector<glm::dvec3> lsCorners;
        for (const glm::dvec3& x : scene.camera.FrustumCorners())
            lsCorners.push_back(ls.ToLight(x));
        const auto expected = FitMapToPoints(focused.p4, lsCorners, scene.shadowMap);
        ASSERT_TRUE(expected.has_value());
        EXPECT_NEAR(PlaneArea(focused, scene.shadowMap) / PlaneArea(*expected, scene.shadowMap),
                    1.0, 1e-9)
            << Describe(light);
        // Same rectangle: the frustum corners touch all four sides of the focused map.
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::dvec3& X : lsCorners) {
            lo = glm::min(lo, focused.Map(X));
            hi = glm::max(hi, focused.Map(X));
        }
        EXPECT_NEAR(lo.x, 0.0, 1e-6);
        EXPECT_NEAR(lo.y, 0.0, 1e-6);
        EXPECT_NEAR(hi.x, scene.shadowMap.width, 1e-6);
        EXPECT_NEAR(hi.y, scene.shadowMap.height, 1e-6);
    }
}

TEST(LispsmBaseline, OptimalNearMatchesClosedForms) {
    // γ = 90°: n + √(fn) (Lloyd 2006 §4.1).
    EXPECT_DOUBLE_EQ(LispsmOptimalNear(0.1, 100.0, 1.0), 0.1 + std::sqrt(10.0));
    // γ = 45°, n = 1, f = 100: (1 + 10) / (√2 / 2) = 11 √2 = 15.556349186104045.
    EXPECT_NEAR(LispsmOptimalNear(1.0, 100.0, std::sin(std::numbers::pi / 4.0)), 15.556349186104045,
                1e-12);
}

TEST(LispsmBaseline, BodyDepthsAndOptimalNearForLevelCamera) {
    // The level camera at z = 10 looks along -z: its body (frustum ∩ bounds) starts at the near
    // plane (0.1, inside the bounds) and ends at the far wall z = -20, 30 units away.
    const Scene scene = MakeLevelScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    struct Case {
        Light light;
        double sinGamma;
    };
    for (const Case& c : {Case{Directional({0.0, -1.0, 0.0}), 1.0},
                          Case{Directional({0.0, -1.0, -1.0}), std::sqrt(0.5)}}) {
        const LightSpace ls(c.light, bounds);
        BaselineDiagnostics d;
        const LightMatrix m =
            LispsmLightMatrix(MakeBaselineContext(scene, ls, bounds, relevant), &d);
        EXPECT_TRUE(d.fallback.empty()) << d.fallback;
        EXPECT_NEAR(d.sinGamma, c.sinGamma, 1e-12);
        EXPECT_NEAR(d.zNear, 0.1, 1e-9);
        EXPECT_NEAR(d.zFar, 30.0, 1e-9);
        // γ = 90°: 0.1 + √3 = 1.8320508075688772; γ = 45°: that × √2 = 2.5909246...
        EXPECT_NEAR(d.nOpt, (0.1 + std::sqrt(3.0)) / c.sinGamma, 1e-9);
        EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap));
        // A real warp: p4 is not the orthographic (0, 0, 1).
        EXPECT_GT(glm::length(m.p4 - glm::dvec3(0.0, 0.0, 1.0)), 1e-3);
    }
}

TEST(LispsmBaseline, LightAlongViewDirectionReducesToFocused) {
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    const glm::dvec3 view = glm::normalize(scene.camera.target - scene.camera.position);
    for (const Light& light : {Directional(view), Directional(-view)}) {
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        BaselineDiagnostics d;
        const LightMatrix lispsm = LispsmLightMatrix(context, &d);
        const LightMatrix focused = FocusedLightMatrix(context);
        EXPECT_FALSE(d.fallback.empty());
        EXPECT_NEAR(glm::length(lispsm.p4 - focused.p4), 0.0, 1e-9);
        EXPECT_TRUE(Valid(lispsm, ls, relevant, scene.shadowMap));
    }
}

TEST(LispsmBaseline, DistantPointLightApproachesTheDirectionalMap) {
    // "Through the light's perspective first": H is rigid to first order at the eye, so as a
    // point light recedes along -l its warp tends to the directional light's. Compared through the
    // denominators p4·X over the relevant points (equal up to scale when the warps agree): their
    // ratio's relative spread shrinks like 1 / distance. The maps themselves agree to < 1 texel;
    // not closer, because the min-area rectangle may settle on the other of two nearly parallel
    // hull edges (a 0.2-texel difference here).
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    const glm::dvec3 l = glm::normalize(glm::dvec3(0.3, -1.0, 0.5));
    const LightSpace lsDir(Directional(l), bounds);
    const LightMatrix mDir = LispsmLightMatrix(MakeBaselineContext(scene, lsDir, bounds, relevant));
    for (double distance : {1e4, 1e6}) {
        const LightSpace lsPoint(Point(bounds.Center() - distance * l), bounds);
        BaselineDiagnostics d;
        const LightMatrix mPoint =
            LispsmLightMatrix(MakeBaselineContext(scene, lsPoint, bounds, relevant), &d);
        EXPECT_TRUE(d.fallback.empty()) << d.fallback;
        double ratioMin = 1e300, ratioMax = -1e300, worstTexels = 0.0;
        for (const glm::dvec3& x : relevant) {
            const double ratio =
                glm::dot(mPoint.p4, lsPoint.ToLight(x)) / glm::dot(mDir.p4, lsDir.ToLight(x));
            ratioMin = std::min(ratioMin, ratio);
            ratioMax = std::max(ratioMax, ratio);
            worstTexels = std::max(worstTexels, glm::length(mPoint.Map(lsPoint.ToLight(x)) -
                                                            mDir.Map(lsDir.ToLight(x))));
        }
        // Measured: 1.08e-3 at 1e4, 1.08e-5 at 1e6 (the scene is ~40 units across).
        EXPECT_LT(ratioMax / ratioMin - 1.0, 20.0 / distance) << distance;
        EXPECT_LT(worstTexels, 1.0) << distance;
    }
}

// --- LiSPSM's n rules: Wimmer's and the engines' (LispsmNearRule) ----------------------------

// The camera of the n-rule tests: at height 2 looking level along -z, 60° field of view, square
// frame, near 0.1, far 100, so that view depth is -z and the warp axis of a light in the y-z plane
// lies in that plane.
Camera LevelCamera() {
    Camera camera;
    camera.position = {0.0, 2.0, 0.0};
    camera.target = {0.0, 2.0, -1.0};
    camera.fovYDeg = 60.0;
    camera.resolution = {400, 400};
    camera.nearPlane = 0.1;
    camera.farPlane = 100.0;
    return camera;
}

// A body's vertices, written out by hand from the camera's geometry: eye-relative points
// (x, y, -depth) with |x|, |y| ≤ depth·tan 30° inside the frustum.
//   frustum  the whole view frustum (depths 0.1 and 100).
//   slab     the frustum ∩ the ground slab -1 ≤ y ≤ 0 (eye-relative -3 ≤ y ≤ -2): its top face
//            enters the view at depth 2 / tan 30° = 2√3 = 3.4641, its bottom at 3√3.
std::vector<glm::dvec3> BodyVertices(const Camera& camera, bool slab) {
    const double t = std::tan(std::numbers::pi / 6.0);
    std::vector<glm::dvec3> out;
    auto add = [&](double x, double y, double depth) {
        out.push_back(camera.position + glm::dvec3(x, y, -depth));
    };
    for (double sx : {-1.0, 1.0}) {
        if (!slab) {
            for (double depth : {camera.nearPlane, camera.farPlane})
                for (double sy : {-1.0, 1.0}) add(sx * t * depth, sy * t * depth, depth);
            continue;
        }
        for (double y : {-2.0, -3.0})
            for (double depth : {-y / t, camera.farPlane}) add(sx * t * depth, y, depth);
    }
    return out;
}

// A directional light at angle γ to the view direction (0, 0, -1), travelling forward and down:
// l = (0, -sin γ, -cos γ). The warp axis (v projected ⊥ l) is then f = (0, cos γ, -sin γ).
Light LightAtGamma(double gammaDeg) {
    const double g = gammaDeg * std::numbers::pi / 180.0;
    return Directional({0.0, -std::sin(g), -std::cos(g)});
}

// The tight LiSPSM of `rule` for a body given as the visible points.
struct RuleRun {
    LightMatrix matrix;
    BaselineDiagnostics diagnostics;
    std::vector<glm::dvec2> images;  // the body's points on the map (texels)
};
RuleRun RunRule(const Camera& camera, const std::vector<glm::dvec3>& body, const Light& light,
                const LispsmNearRule& rule, const Bounds& bounds) {
    const LightSpace ls(light, bounds);
    BaselineContext context;
    context.lightSpace = &ls;
    context.camera = camera;
    context.map = {400, 400};
    context.wsBounds = bounds;
    context.wsRelevant = body;
    RuleRun run;
    run.matrix = LispsmRuleLightMatrix(context, rule, &run.diagnostics);
    EXPECT_TRUE(Valid(run.matrix, ls, body, context.map));
    for (const glm::dvec3& x : body) run.images.push_back(run.matrix.Map(ls.ToLight(x)));
    return run;
}

Bounds BoxAround(const std::vector<glm::dvec3>& points) {
    Bounds b;
    for (const glm::dvec3& p : points) b.Add(p);
    return b;
}

// The n the rules give for a body at γ, computed here from the vertices: z_n, z_f their view
// depths, d their extent along f (the tight body's sweep toward the light runs along l ⊥ f).
double ExpectedNear(const Camera& camera, const std::vector<glm::dvec3>& body, double gammaDeg,
                    bool engine, double* warpDepth) {
    const double g = gammaDeg * std::numbers::pi / 180.0, s = std::sin(g);
    const glm::dvec3 f(0.0, std::cos(g), -std::sin(g));
    double zn = 1e300, zf = -1e300, fMin = 1e300, fMax = -1e300;
    for (const glm::dvec3& p : body) {
        const double z = camera.position.z - p.z, fp = glm::dot(f, p - camera.position);
        zn = std::min(zn, z), zf = std::max(zf, z);
        fMin = std::min(fMin, fp), fMax = std::max(fMax, fp);
    }
    *warpDepth = fMax - fMin;
    const double z1 = engine ? std::min(zn + *warpDepth * s, zf) : zf;
    return (zn + std::sqrt(zn * z1)) / s;
}

// Whether x, rounded to the digits `printed` shows (`unit`: its last digit's place), is printed.
::testing::AssertionResult RoundsTo(double x, double printed, double unit) {
    if (std::abs(x - printed) <= 0.5 * unit) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << x << " does not round to " << printed;
}

TEST(LispsmNearRule, FrustumAndSlabBodiesGiveThePublishedNumbers) {
    // The table, from Filament's applyLISPSM and Wimmer's formula, to the digits printed:
    // frustum body n = 3.26 both at 90°, 4.61 / 4.11 at 45°, 18.8 / 8.69 at 10°, 93.5 / 21.3 at
    // 2°; slab body (z_n = 2√3) 22.08 both at 90°, 31.2 / 23.8, 127 / 47.3, 633 / 201. The
    // library's n (through the whole tight construction) must equal the closed form to 1e-9.
    struct Row {
        bool slab;
        double gammaDeg, wimmer, engine, unit;
    };
    const Row rows[] = {
        {false, 90.0, 3.26, 3.26, 0.01},  {false, 45.0, 4.61, 4.11, 0.01},
        {false, 10.0, 18.8, 8.69, 0.1},   {false, 2.0, 93.5, 21.3, 0.1},
        {true, 90.0, 22.08, 22.08, 0.01}, {true, 45.0, 31.2, 23.8, 0.1},
        {true, 10.0, 127.0, 47.3, 1.0},   {true, 2.0, 633.0, 201.0, 1.0},
    };
    const Camera camera = LevelCamera();
    for (const Row& row : rows) {
        const std::vector<glm::dvec3> body = BodyVertices(camera, row.slab);
        Bounds bounds = BoxAround(body);  // the scene: the body, and for the frustum room above
        if (!row.slab) bounds.Add(camera.position + glm::dvec3(0.0, 60.0, 0.0));
        const std::string what = std::string(row.slab ? "slab" : "frustum") + " at " +
                                 std::to_string(row.gammaDeg) + "°";
        for (bool engine : {false, true}) {
            LispsmNearRule rule;
            if (engine) rule.kind = LispsmNearRule::Kind::kEngine;
            const RuleRun run = RunRule(camera, body, LightAtGamma(row.gammaDeg), rule, bounds);
            const BaselineDiagnostics& d = run.diagnostics;
            EXPECT_TRUE(d.fallback.empty()) << what << ": " << d.fallback;
            double warpDepth = 0.0;
            const double expected = ExpectedNear(camera, body, row.gammaDeg, engine, &warpDepth);
            EXPECT_NEAR(d.sinGamma, std::sin(row.gammaDeg * std::numbers::pi / 180.0), 1e-12);
            EXPECT_NEAR(d.zNear, row.slab ? 2.0 * std::sqrt(3.0) : 0.1, 1e-9) << what;
            EXPECT_NEAR(d.zFar, 100.0, 1e-9) << what;
            EXPECT_NEAR(d.warpDepth, warpDepth, 1e-9 * warpDepth) << what;
            EXPECT_NEAR(d.nOpt, expected, 1e-9 * expected) << what << (engine ? " engine" : "");
            EXPECT_TRUE(RoundsTo(d.nOpt, engine ? row.engine : row.wimmer, row.unit))
                << what << (engine ? " engine" : " wimmer");
        }
    }
}

TEST(LispsmNearRule, ClosedFormsAndFilamentsVirtualPlanes) {
    const LispsmNearRule wimmer, engine{LispsmNearRule::Kind::kEngine};
    // γ = 90° on the frustum body: d = z_f - z_n, so z₁ = z_f and both are 0.1 + √10.
    const LispsmDepths frustum{0.1, 100.0, 99.9};
    EXPECT_DOUBLE_EQ(*LispsmNear(wimmer, frustum, 1.0, 0.1), 0.1 + std::sqrt(10.0));
    EXPECT_NEAR(*LispsmNear(engine, frustum, 1.0, 0.1), 0.1 + std::sqrt(10.0), 1e-14);
    // z₁ = z₀ + d sin γ: z_n = 1, d = 48, sin γ = 1/2 → z₁ = 25, n = (1 + 5) / (1/2) = 12.
    EXPECT_NEAR(*LispsmNear(engine, {1.0, 100.0, 48.0}, 0.5, 0.1), 12.0, 1e-13);
    // ... capped at z_f: d = 400 would put z₁ at 201; it stays 100: n = (1 + 10) / (1/2) = 22.
    EXPECT_NEAR(*LispsmNear(engine, {1.0, 100.0, 400.0}, 0.5, 0.1), 22.0, 1e-13);
    // Filament's defaults (near hint 1 m, far hint 100 m) at γ = 90° on the frustum body: vz₀ = 1,
    // vz₁ = 100, n = 0.1 + √100 = 10.1; its floor dzn / (2 - 3 dzn / 99.9) = 0.456.
    LispsmNearRule filament = engine;
    filament.virtualNear = 1.0;
    filament.virtualFar = 100.0;
    EXPECT_NEAR(*LispsmNear(filament, frustum, 1.0, 0.1), 10.1, 1e-13);
    // A far hint below z₁ caps the root: vz₁ = 25 → n = 0.1 + √(0.1 · 25) (no near hint).
    LispsmNearRule farOnly = engine;
    farOnly.virtualFar = 25.0;
    EXPECT_NEAR(*LispsmNear(farOnly, frustum, 1.0, 0.1), 0.1 + std::sqrt(2.5), 1e-14);
    // The floor wins when the near hint nears 2/3 of the range: z 1..10, hint 6.5 (dzn 5.5):
    // n ≥ 5.5 / (2 - 16.5 / 9) = 33.0 > (1 + √(6.5 · 10)) = 9.06; past 2/3 there is no warp.
    LispsmNearRule deep = engine;
    deep.virtualNear = 6.5;
    EXPECT_NEAR(*LispsmNear(deep, {1.0, 10.0, 9.0}, 1.0, 1.0), 5.5 / (2.0 - 16.5 / 9.0), 1e-12);
    deep.virtualNear = 7.0;  // dzn = 6 = 2/3 of 9
    EXPECT_FALSE(LispsmNear(deep, {1.0, 10.0, 9.0}, 1.0, 1.0).has_value());
    // Degenerate input is refused by value, never NaN.
    EXPECT_FALSE(LispsmNear(engine, {0.0, 10.0, 9.0}, 1.0, 0.1).has_value());
    EXPECT_FALSE(LispsmNear(engine, {1.0, 0.5, 9.0}, 1.0, 0.1).has_value());
    EXPECT_FALSE(LispsmNear(engine, {1.0, 10.0, -1.0}, 1.0, 0.1).has_value());
    EXPECT_FALSE(LispsmNear(wimmer, {1.0, 10.0, 9.0}, 0.0, 0.1).has_value());
}

TEST(LispsmNearRule, WarpFrustumIdentityHoldsForBothRules) {
    // The warp is a frustum along f with its centre n before the body's near face: the map's
    // denominator p4·X is proportional to f·(x - eye) - (z_min - n), z_min = min over the body of
    // f·(x - eye) (for a directional light the tight body's sweep runs along l ⊥ f, so the
    // visible points give z_min). Checked over the visible points and a grid through the bounds.
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    const glm::dvec3 v = glm::normalize(scene.camera.target - scene.camera.position);
    std::vector<glm::dvec3> grid = relevant;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j)
            for (int k = 0; k <= 4; ++k)
                grid.push_back(bounds.lo + (bounds.hi - bounds.lo) * glm::dvec3(i, j, k) / 4.0);
    for (const glm::dvec3& direction : {glm::dvec3(0.3, -1.0, 0.5), glm::dvec3(0.0, -1.0, -1.0),
                                        glm::dvec3(1.0, -0.3, 0.2), glm::dvec3(0.0, -0.2, -1.0)}) {
        const Light light = Directional(direction);
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        const glm::dvec3 l = light.direction;
        const glm::dvec3 f = glm::normalize(v - glm::dot(v, l) * l);
        double zMin = 1e300;
        for (const glm::dvec3& x : relevant)
            zMin = std::min(zMin, glm::dot(f, x - scene.camera.position));
        for (bool engine : {false, true}) {
            LispsmNearRule rule;
            if (engine) rule.kind = LispsmNearRule::Kind::kEngine;
            BaselineDiagnostics d;
            const LightMatrix m = LispsmRuleLightMatrix(context, rule, &d);
            ASSERT_TRUE(d.fallback.empty()) << d.fallback;
            // p4·X = k·w with k from the first visible point; the residual relative to the
            // largest |p4·X| (a ratio would lose digits where w crosses 0 in the grid).
            auto w = [&](const glm::dvec3& x) {
                return glm::dot(f, x - scene.camera.position) - (zMin - d.nOpt);
            };
            const double k = glm::dot(m.p4, ls.ToLight(relevant[0])) / w(relevant[0]);
            double residual = 0.0, scale = 0.0;
            for (const glm::dvec3& x : grid) {
                const double denominator = glm::dot(m.p4, ls.ToLight(x));
                residual = std::max(residual, std::abs(denominator - k * w(x)));
                scale = std::max(scale, std::abs(denominator));
            }
            // Measured: ≤ 6e-16 (rounding).
            EXPECT_LT(residual / scale, 1e-13)
                << Describe(light) << (engine ? " engine" : " wimmer");
        }
    }
}

TEST(LispsmNearRule, ContinuousDownToTheCutoffThenFocusedTight) {
    // n(γ) = g(sin γ) / sin γ with g non-decreasing (Wimmer: constant; engine: z₁ grows with
    // sin γ), so on a grid of sin γ with ratio q from 1 down to the cutoff 1e-3 consecutive n
    // differ by a factor in [1, q]: no jump, and no switch to the orthographic map at Filament's
    // sin γ = 0.02.
    const double q = 1.01;
    for (const LispsmDepths& depths :
         {LispsmDepths{0.1, 100.0, 115.0}, LispsmDepths{2.0 * std::sqrt(3.0), 100.0, 97.0}})
        for (const auto kind : {LispsmNearRule::Kind::kWimmer, LispsmNearRule::Kind::kEngine}) {
            const LispsmNearRule rule{kind};
            double previous = *LispsmNear(rule, depths, 1.0, 0.1);
            for (double s = 1.0 / q; s >= 1e-3; s /= q) {
                const double n = *LispsmNear(rule, depths, s, 0.1);
                EXPECT_GE(n / previous, 1.0 - 1e-12) << s;
                EXPECT_LE(n / previous, q * (1.0 + 1e-12)) << s;
                previous = n;
            }
        }
    // Through the whole construction on the frustum body: lights at sin γ = 1e-3·(1 + ε) just
    // above the cutoff warp, with n the closed form, and the maps converge as ε → 0 (the visible
    // points move 100× less from ε = 1e-4 to 1e-6 than from 1e-2 to 1e-4); just below the cutoff
    // both rules are focused-tight.
    const Camera camera = LevelCamera();
    const std::vector<glm::dvec3> body = BodyVertices(camera, false);
    Bounds bounds = BoxAround(body);
    bounds.Add(camera.position + glm::dvec3(0.0, 60.0, 0.0));
    for (const auto kind : {LispsmNearRule::Kind::kWimmer, LispsmNearRule::Kind::kEngine}) {
        const LispsmNearRule rule{kind};
        std::vector<std::vector<glm::dvec2>> images;
        for (double eps : {1e-2, 1e-4, 1e-6}) {
            const double gammaDeg = std::asin(1e-3 * (1.0 + eps)) * 180.0 / std::numbers::pi;
            const RuleRun run = RunRule(camera, body, LightAtGamma(gammaDeg), rule, bounds);
            const BaselineDiagnostics& d = run.diagnostics;
            EXPECT_TRUE(d.fallback.empty()) << d.fallback;
            double warpDepth = 0.0;
            const double expected = ExpectedNear(camera, body, gammaDeg,
                                                 kind == LispsmNearRule::Kind::kEngine, &warpDepth);
            EXPECT_NEAR(d.nOpt, expected, 1e-8 * expected) << eps;
            images.push_back(run.images);
        }
        auto moved = [&](int a, int b) {
            double most = 0.0;
            for (std::size_t i = 0; i < body.size(); ++i)
                most = std::max(most, glm::length(images[a][i] - images[b][i]));
            return most;
        };
        // Measured: 0.064 / 6.4e-4 texel (Wimmer), 0.35 / 3.5e-3 (engine).
        EXPECT_LT(moved(1, 2), 0.02 * moved(0, 1));
        EXPECT_LT(moved(1, 2), 0.1);
        const double below = std::asin(0.99e-3) * 180.0 / std::numbers::pi;
        const RuleRun run = RunRule(camera, body, LightAtGamma(below), rule, bounds);
        EXPECT_NE(run.diagnostics.fallback.find("focused-tight"), std::string::npos);
    }
}

TEST(LispsmNearRule, OptimalNeverHasALargerHThanLispsmEngineOverASweep) {
    // The multi-start guarantee (multi_start.h) through the registry `lexel sweep` uses: on every
    // light of a shipped scene's sweep, h (eq. 6) of `optimal` is at most that of `lispsm-engine`,
    // which is among its starts. (Street and walkthrough: `optimal` loses to lispsm-tight on
    // misclassified pixels there.)
    int total = 0;
    for (const char* file : {"street.json", "walkthrough.json"}) {
        const Scene scene =
            cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial" / file);
        const std::unique_ptr<RenderBackend> backend = MakeCpuRenderer(scene.geometry);
        const Evaluator evaluator(scene, *backend);
        std::vector<Light> lights = cases::SweepLightsOf(scene, 25, Light::Type::kPoint);
        for (const Light& l : cases::SweepLightsOf(scene, 25, Light::Type::kDirectional))
            lights.push_back(l);
        int engineStarts = 0;
        for (const Light& light : lights) {
            const LightOutcome o = evaluator.Evaluate(light, {});
            const LightSpace ls(light, evaluator.bounds());
            MethodContext context;
            context.baseline =
                MakeBaselineContext(scene, ls, evaluator.bounds(), evaluator.readback().wsRelevant,
                                    evaluator.readback().wsRelevantHull);
            context.baseline.samples = &o.samples;
            context.samples = &o.samples;
            const MethodMatrix optimal = ComputeLightMatrix("optimal-h", context);
            const MethodMatrix engine = ComputeLightMatrix("lispsm-engine", context);
            const double hOptimal = Energy(optimal.matrix, o.samples);
            EXPECT_EQ(hOptimal, optimal.optimizer->h);
            EXPECT_LE(hOptimal, Energy(engine.matrix, o.samples))
                << file << " " << cases::LightLabel(light);
            if (optimal.winner == "lispsm-engine") ++engineStarts;
            // `optimal` holds the same promise on its own energy e.
            const MethodMatrix onE = ComputeLightMatrix("optimal", context);
            const double eOptimal = Energy(onE.matrix, o.samples, kEdgeEnergy);
            EXPECT_EQ(eOptimal, onE.optimizer->h);
            EXPECT_LE(eOptimal, Energy(engine.matrix, o.samples, kEdgeEnergy))
                << file << " " << cases::LightLabel(light);
        }
        total += engineStarts;
    }
    // The start matters: its map or its search wins on some lights (measured: 5 of 50 on the
    // street, 2 of 50 on the walkthrough); without it h(optimal-h) > h(lispsm-engine) on one.
    EXPECT_GT(total, 0);
}

TEST(PsmBaseline, LightPerpendicularToViewIsOrthographicInPostPerspectiveSpace) {
    // A directional light ⊥ the view direction lies on the camera plane: in NDC it is a direction,
    // so the PSM map is orthographic there and its denominator p4·X is proportional to the virtual
    // camera's view depth v·(x - eye').
    const Scene scene = MakeLevelScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    const LightSpace ls(Directional({0.0, -1.0, 0.0}), bounds);
    BaselineDiagnostics d;
    const LightMatrix m = PsmLightMatrix(MakeBaselineContext(scene, ls, bounds, relevant), &d);
    EXPECT_TRUE(d.fallback.empty()) << d.fallback;
    EXPECT_NEAR(d.clipLight.w, 0.0, 1e-15);
    EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap));
    const glm::dvec3 view(0.0, 0.0, -1.0);
    const glm::dvec3 virtualEye = scene.camera.position - d.slideBack * view;
    const double ratio0 =
        glm::dot(m.p4, ls.ToLight(relevant[0])) / glm::dot(view, relevant[0] - virtualEye);
    for (const glm::dvec3& x : relevant)
        EXPECT_NEAR(glm::dot(m.p4, ls.ToLight(x)) / glm::dot(view, x - virtualEye) / ratio0, 1.0,
                    1e-9);
}

TEST(PsmBaseline, PointLightOnTheViewAxisLandsOnTheNdcAxis) {
    // A point light 50 units straight ahead of the level camera (outside the bounds): in NDC it is
    // at x = y = 0, z = (f' + n') / (f' - n') - 2 f' n' / ((f' - n') (50 + δ)) with the virtual
    // near n', far f' and slide back δ.
    const Scene scene = MakeLevelScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    const glm::dvec3 wsLight = scene.camera.position + glm::dvec3(0.0, 0.0, -50.0);
    const LightSpace ls(Point(wsLight), bounds);
    BaselineDiagnostics d;
    const LightMatrix m = PsmLightMatrix(MakeBaselineContext(scene, ls, bounds, relevant), &d);
    EXPECT_TRUE(d.fallback.empty()) << d.fallback;
    EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap));
    const double n = d.zNear + d.slideBack, f = d.zFar + d.slideBack;
    EXPECT_NEAR(d.slideBack, PsmSlideBack(d.zNear, d.zFar), 0.0);
    EXPECT_NEAR(n / f, std::max(kPsmMinNearFarRatio, d.zNear / d.zFar), 1e-12);
    const glm::dvec3 ndc = glm::dvec3(d.clipLight) / d.clipLight.w;
    EXPECT_NEAR(d.clipLight.w, 50.0 + d.slideBack, 1e-9);
    EXPECT_NEAR(ndc.x, 0.0, 1e-12);
    EXPECT_NEAR(ndc.y, 0.0, 1e-12);
    EXPECT_NEAR(ndc.z, (f + n) / (f - n) - 2.0 * f * n / ((f - n) * (50.0 + d.slideBack)), 1e-12);
    // And it is what the virtual camera's own matrices give.
    const Camera virtualCamera = PsmVirtualCamera(scene.camera, d.zNear, d.zFar, d.slideBack);
    const glm::dvec4 clip =
        virtualCamera.ClipFromView() * virtualCamera.ViewFromWorld() * glm::dvec4(wsLight, 1.0);
    EXPECT_NEAR(glm::length(clip - d.clipLight), 0.0, 1e-9);
}

TEST(PsmBaseline, LightBehindViewerGivesValidInvertedMap) {
    // The light travels along the view direction (sun behind the viewer): its clip w is negative,
    // Kozlov's inverted case.
    const Scene scene = MakeLevelScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    for (const Light& light : {Directional({0.0, -1.0, -1.0}), Point({0.0, 40.0, 60.0})}) {
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        BaselineDiagnostics d;
        const LightMatrix psm = PsmLightMatrix(context, &d);
        EXPECT_TRUE(d.fallback.empty()) << d.fallback;
        EXPECT_LT(d.clipLight.w, 0.0);
        EXPECT_TRUE(Valid(psm, ls, relevant, scene.shadowMap)) << Describe(light);
        EXPECT_GT(glm::length(psm.p4 - FocusedLightMatrix(context).p4), 1e-3) << Describe(light);
    }
}

// Screen → map Jacobian of m at floor points seen at screen points xs (camera pixels), by
// central differences (h = 0.25 pixel; the map is affine on the floor, so exact up to rounding).
std::vector<glm::dmat2> FloorJacobians(const LightMatrix& m, const LightSpace& ls,
                                       const Camera& camera,
                                       const std::vector<glm::dvec2>& screenPoints) {
    const double h = 0.25;
    auto u = [&](glm::dvec2 xs) { return m.Map(ls.ToLight(FloorHit(camera, xs))); };
    std::vector<glm::dmat2> out;
    for (const glm::dvec2& xs : screenPoints) {
        glm::dmat2 j;
        j[0] = (u(xs + glm::dvec2(h, 0.0)) - u(xs - glm::dvec2(h, 0.0))) / (2.0 * h);
        j[1] = (u(xs + glm::dvec2(0.0, h)) - u(xs - glm::dvec2(0.0, h))) / (2.0 * h);
        out.push_back(j);
    }
    return out;
}

double Norm(const glm::dmat2& a) {
    return std::sqrt(a[0][0] * a[0][0] + a[0][1] * a[0][1] + a[1][0] * a[1][0] + a[1][1] * a[1][1]);
}

TEST(PlaneOptimalBaseline, ScreenToMapIsAffineOnTheFloor) {
    const Scene scene = MakeScene();
    const Bounds bounds = FloorBounds();
    const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    // 50 visible floor points, as screen points (camera pixels).
    const glm::dmat4 q = scene.camera.ScreenFromWorld(scene.camera.resolution);
    std::vector<glm::dvec2> screenPoints;
    for (std::size_t i = 0; screenPoints.size() < 50; i += relevant.size() / 50) {
        const glm::dvec4 h = q * glm::dvec4(relevant[i], 1.0);
        screenPoints.emplace_back(h.x / h.w, h.y / h.w);
    }
    const double scale = double(scene.shadowMap.width) / scene.camera.resolution.width;
    for (const Light& light :
         {Point({30.0, 60.0, -70.0}), Point({-90.0, 20.0, 10.0}), Directional({0.4, -1.0, 0.7})}) {
        const LightSpace ls(light, bounds);
        const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
        const LightMatrix before = *PlaneOptimalProjectiveMatrix(context);
        const auto jBefore = FloorJacobians(before, ls, scene.camera, screenPoints);
        // Before the refit the map is the camera screen at map resolution: u = (400/750) xs.
        const glm::dmat2 expected(scale, 0.0, 0.0, scale);
        for (const glm::dmat2& j : jBefore) {
            EXPECT_LT(Norm(j - jBefore[0]), 1e-6 * Norm(jBefore[0])) << Describe(light);
            EXPECT_LT(Norm(j - expected), 1e-6 * scale) << Describe(light);
        }
        BaselineDiagnostics d;
        const LightMatrix after = PlaneOptimalLightMatrix(context, &d);
        EXPECT_TRUE(d.fallback.empty()) << d.fallback;
        EXPECT_NEAR(glm::length(after.p4 - before.p4), 0.0, 1e-12);
        EXPECT_TRUE(Valid(after, ls, relevant, scene.shadowMap));
        const auto jAfter = FloorJacobians(after, ls, scene.camera, screenPoints);
        for (const glm::dmat2& j : jAfter)
            EXPECT_LT(Norm(j - jAfter[0]), 1e-6 * Norm(jAfter[0])) << Describe(light);
    }
}

TEST(PlaneOptimalBaseline, OffPlanePointBehindP4TurnsTowardFocused) {
    // A low light ahead of the level camera: the top of an object near the camera, (0, 3, 5),
    // casts its floor shadow to z = 155, behind the camera, so the plane-optimal p4 (which sends
    // the shadow's camera plane to infinity) has the point behind it.
    const Scene scene = MakeLevelScene();
    const Bounds bounds = FloorBounds();
    std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
    relevant.push_back({0.0, 3.0, 5.0});
    const LightSpace ls(Point({0.0, 5.0, -95.0}), bounds);
    const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
    const LightMatrix before = *PlaneOptimalProjectiveMatrix(context);
    EXPECT_FALSE(InFront(before.p4, ls.ToLight(relevant.back())));
    BaselineDiagnostics d;
    const LightMatrix m = PlaneOptimalLightMatrix(context, &d);
    EXPECT_FALSE(d.fallback.empty());
    EXPECT_GT(d.rotationFraction, 0.0);
    EXPECT_LT(d.rotationFraction, 1.0);
    EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap));
}

TEST(PlaneOptimalBaseline, NeedsAFloorPlane) {
    Scene scene = MakeScene();
    scene.floorPlane.reset();
    const Bounds bounds = FloorBounds();
    const LightSpace ls(Point({0.0, 100.0, 0.0}), bounds);
    EXPECT_THROW(PlaneOptimalLightMatrix(MakeBaselineContext(scene, ls, bounds, {})), DomainError);
}

TEST(Baselines, ValidForLightsNearTheBoundsAndOtherCameraPoses) {
    // Point lights 22 units from the floor centre sit just outside the 40 × 40 × 3 box, some near
    // the planes of its faces, where normal's p4 = (0, 0, 1) misses corners (its fallbacks run);
    // the poses look steeply down, up over the floor, and diagonally from a corner.
    const Bounds bounds = FloorBounds();
    int normalFallbacks = 0;
    for (int pose = 0; pose < 4; ++pose) {
        Scene scene = MakeScene();
        if (pose == 1) scene.camera.target = {5.0, -20.0, 0.0};
        if (pose == 2) scene.camera.target = {0.0, 5.0, -30.0};
        if (pose == 3) {
            scene.camera.position = {-19.0, 2.9, -19.0};
            scene.camera.target = {20.0, 0.0, 20.0};
        }
        const std::vector<glm::dvec3> relevant = RelevantFloorPoints(scene.camera);
        ASSERT_GT(relevant.size(), 100u);
        for (double radius : {22.0, 30.0}) {
            for (Light light : SweepLights(17 + pose, 40, 5)) {
                if (light.type == Light::Type::kPoint) light.position *= radius / 100.0;
                if (light.type == Light::Type::kPoint && bounds.Contains(light.position)) continue;
                const LightSpace ls(light, bounds);
                const BaselineContext context = MakeBaselineContext(scene, ls, bounds, relevant);
                for (const auto& [name, method] : kMethods) {
                    BaselineDiagnostics d;
                    const LightMatrix m = method(context, &d);
                    EXPECT_TRUE(Valid(m, ls, relevant, scene.shadowMap))
                        << name << ", pose " << pose << ", light " << Describe(light);
                    if (name == "normal" && !d.fallback.empty()) ++normalFallbacks;
                }
            }
        }
    }
    EXPECT_GT(normalFallbacks, 0);  // the fallback paths were exercised
}

}  // namespace
}  // namespace lexel::spatial
