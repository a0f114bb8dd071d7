// The warped methods (warped_methods.h) in the evaluation: LogPSM's measured storage factor on a
// box scene lit from overhead is within 10% of its analytic value (Lloyd et al. 2008; at γ = 90°
// the analytic S̄_opt of Lloyd 2006 Appendix C) and its texels split as that analysis says; every
// warped method gets the other single maps' texels and covers what focused-tight covers.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/logpsm.h"
#include "lexel/spatial/methods/registry.h"
#include "lexel/spatial/perspective_aliasing.h"
#include "lexel/spatial/rtw.h"
#include "lexel/spatial/studies/storage_factor.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

// A floor 400 across with a box on it, seen by a level camera 2 above it (60°, near 0.1, far
// 100): the floor fills the lower half of the view from depth 2 / tan 30° = 3.46 to the far plane.
Scene BoxScene(const Light& light) {
    Scene scene;
    scene.name = "box";
    scene.camera.position = {0.0, 2.0, 0.0};
    scene.camera.target = {0.0, 2.0, -1.0};
    scene.camera.fovYDeg = 60.0;
    scene.camera.nearPlane = 0.1;
    scene.camera.farPlane = 100.0;
    scene.camera.resolution = {320, 320};
    scene.readback = {160, 160};
    scene.shadowMap = {256, 256};
    scene.geometry = testing::FloorQuad(200.0);
    scene.geometry.Append(testing::BoxMesh({-1.0, 0.0, -12.0}, {1.0, 1.5, -10.0}));
    scene.floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    scene.lights = {light};
    return scene;
}

// The box scene under `light` with its readback, light space and the baselines' context (which
// points into the light space: built in place, never copied).
struct BoxReadback {
    explicit BoxReadback(const Light& light)
        : scene(BoxScene(light)),
          backend(MakeCpuRenderer(scene.geometry)),
          readback(RenderReadback(*backend, scene.camera, scene.readback)),
          bounds(scene.geometry.ComputeBounds()),
          lightSpace(scene.lights.front(), bounds),
          context(MakeBaselineContext(scene, lightSpace, bounds, readback.wsRelevant,
                                      readback.wsRelevantHull)) {}
    BoxReadback(const BoxReadback&) = delete;
    BoxReadback& operator=(const BoxReadback&) = delete;
    Scene scene;
    std::unique_ptr<RenderBackend> backend;
    Readback readback;
    Bounds bounds;
    LightSpace lightSpace;
    BaselineContext context;
};

// The frame's visible planar depth range, as `lexel storage --case` takes it.
ViewFrustum VisibleFrustum(const Evaluator& evaluator) {
    const Camera& camera = evaluator.scene().camera;
    ViewFrustum f;
    f.fovYDeg = camera.fovYDeg;
    f.aspect = static_cast<double>(camera.resolution.width) / camera.resolution.height;
    f.nearPlane = std::numeric_limits<double>::infinity();
    f.farPlane = 0.0;
    const CameraBuffer& frame = evaluator.frame();
    for (std::size_t i = 0; i < frame.wsPosition.size(); ++i) {
        if (!frame.Covered(i)) continue;
        const double z = PlanarEyeDepth(camera, frame.wsPosition[i]);
        f.nearPlane = std::min(f.nearPlane, z);
        f.farPlane = std::max(f.farPlane, z);
    }
    return f;
}

// LogPSM's effective storage factor with the light overhead, in closed form. Per texel of an
// M_x × M_z map the beam's cross-section (the plane ⊥ the light: the floor's x, z) has the
// columns J⁻¹ e_s = (p, 0) and J⁻¹ e_t = (−r q, q): p = 2 a tanθ z (1+m) / M_x the lateral step,
// q = z ln(ρ) (1+m) / M_z the step along the view (ρ the fitted depth ratio; 1+m the margin on
// each axis), and r = x/z the slope of the warp's rays (the perspective's t-lines are rays from
// the eye), |r| ≤ a tanθ = tan φ, φ the horizontal half angle. LogPsmLightMap balances the
// column lengths, p = q √(1 + r²) at |r| = tan φ (logpsm.h), and then σ₁² of [[p, −rq], [0, q]]
// is q² (λ² + λ r), λ = √(1 + r²). With the pixel 2 tanθ z / H wide, texels · σ₁² / pixels is
//     S = S̄_opt · (1+m)² · (sec φ + tan φ),        S̄_opt = ln(ρ) / (2 tanθ),
// largest at the frustum's side faces: the lexel measure (the widest cross-section) exceeds
// Lloyd's S̄ (the texel's extents along x and z, which leave the shear out) by sec φ + tan φ,
// √3 for a 60° square frame.
double OverheadLogPsmEffectiveStorage(const ViewFrustum& visible, double margin) {
    const double tanPhi = visible.aspect * visible.TanHalfFovY();
    return OptimalStorageFactor(visible) * (1.0 + margin) * (1.0 + margin) *
           (std::sqrt(1.0 + tanPhi * tanPhi) + tanPhi);
}

TEST(LogPsm, MeasuredStorageFactorOnABoxSceneIsWithinTenPercentOfItsAnalyticValue) {
    const Scene scene = BoxScene({Light::Type::kDirectional, {}, {0.0, -1.0, 0.0}});
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"logpsm", "lispsm-tight", "focused-tight"};
    const LightOutcome o = evaluator.Evaluate(scene.lights.front(), options);
    const ViewFrustum visible = VisibleFrustum(evaluator);
    // The light overhead (γ = 90°): LogPSM's S̄ (Lloyd's measure) is S̄_opt for the visible depths.
    const glm::dvec3 esToLight(0.0, 1.0, 0.0);
    EXPECT_NEAR(LogPsmStorageFactor(visible, esToLight), OptimalStorageFactor(visible),
                1e-12 * OptimalStorageFactor(visible));
    const double analytic = OverheadLogPsmEffectiveStorage(visible, BaselineContext{}.margin);
    const MethodOutcome& log = o.methods[0];
    EXPECT_LE(log.metrics.texels, scene.shadowMap.width * scene.shadowMap.height);
    EXPECT_GE(log.metrics.texels, scene.shadowMap.width * scene.shadowMap.height - 256);
    EXPECT_NEAR(log.metrics.storageFactor, analytic, 0.10 * analytic)
        << "visible depths " << visible.nearPlane << " to " << visible.farPlane;
    // Both other single maps need more: LiSPSM's η = 0 warp, and no warp.
    EXPECT_GT(o.methods[1].metrics.storageFactor, 2.0 * log.metrics.storageFactor);
    EXPECT_GT(o.methods[2].metrics.storageFactor, 20.0 * log.metrics.storageFactor);
    std::cout << "[ logpsm   ] box, overhead: measured " << log.metrics.storageFactor
              << ", analytic " << analytic << " (S̄_opt " << OptimalStorageFactor(visible)
              << ", visible depths " << visible.nearPlane << " to " << visible.farPlane
              << "); lispsm-tight " << o.methods[1].metrics.storageFactor << ", focused-tight "
              << o.methods[2].metrics.storageFactor << "\n";
}

TEST(LogPsm, OverheadLightSplitsTheTexelsAsTheOptimalParameterization) {
    // Appendix C: M_x / M_z = a / (ln(f/n) / (2 tanθ)) at one texel per pixel.
    const BoxReadback box({Light::Type::kDirectional, {}, {0.0, -1.0, 0.0}});
    const Scene& scene = box.scene;
    const Readback& readback = box.readback;
    const LightSpace& lightSpace = box.lightSpace;
    const BaselineContext& context = box.context;
    BaselineDiagnostics diagnostics;
    const LogPsmMap map = LogPsmLightMap(context, &diagnostics);
    EXPECT_TRUE(map.logarithmic) << diagnostics.fallback;
    double zLo = std::numeric_limits<double>::infinity(), zHi = 0.0;
    for (const glm::dvec3& x : readback.wsRelevant) {
        zLo = std::min(zLo, PlanarEyeDepth(scene.camera, x));
        zHi = std::max(zHi, PlanarEyeDepth(scene.camera, x));
    }
    // The columns' lengths (OverheadLogPsmEffectiveStorage above): A_x / A_z = 2 tanθ / ln ρ over
    // √(1 + tan²φ), the t-column's shear at the side faces; ρ the visible depth ratio (the margin
    // grows both axes alike).
    const double tanPhi = std::tan(glm::radians(30.0));
    const double expected =
        2.0 * std::tan(glm::radians(30.0)) / std::log(zHi / zLo) / std::sqrt(1.0 + tanPhi * tanPhi);
    EXPECT_NEAR(map.aliasingRatio, expected, 0.01 * expected);
    // Every visible point lands in the map.
    for (const glm::dvec3& x : readback.wsRelevant) {
        const auto u = map.warp.Forward(lightSpace.ToLight(x));
        ASSERT_TRUE(u);
        EXPECT_GE(u->x, 0.0);
        EXPECT_GE(u->y, 0.0);
        EXPECT_LE(u->x, map.resolution.width);
        EXPECT_LE(u->y, map.resolution.height);
    }
}

// RTW's importance (rtw.h, step 1): each readback pixel's perspective aliasing w_l/w_i under the
// base map, max-splatted over where the pixel lands, so a receiver nearly parallel to the light
// (the floor under a low sun), whose footprint σ₁(J⁻¹) grows without bound, asks only for what
// its depth asks. Brute force: the map's maximum is the pixels' largest w_l/w_i, and the texel a
// pixel lands in holds at least its own.
TEST(Rtw, ImportanceIsEachPixelsPerspectiveAliasingUnderTheBaseMap) {
    const BoxReadback box(
        {Light::Type::kDirectional, {}, glm::normalize(glm::dvec3(1.0, -0.05, -0.3))});
    const Scene& scene = box.scene;
    const Readback& readback = box.readback;
    const LightSpace& lightSpace = box.lightSpace;
    const BaselineContext& context = box.context;
    const LightMatrix base = FocusedTightLightMatrix(context);
    const ImportanceMap importance =
        RtwImportance(readback, scene.camera, lightSpace, base, scene.shadowMap,
                      scene.camera.resolution, {}, RtwOptions{.edgeWeight = 0.0});
    const CameraBuffer& buffer = readback.buffer;
    double largest = 0.0;
    std::size_t counted = 0;
    for (std::size_t i = 0; i < buffer.triangle.size(); ++i) {
        if (!buffer.Covered(i)) continue;
        const glm::dvec3 lsX = lightSpace.ToLight(buffer.wsPosition[i]);
        const double rate =
            PerspectiveAliasing(scene.camera, lightSpace, base, buffer.wsPosition[i]);
        if (!InFront(base.p4, lsX) || !std::isfinite(rate)) continue;
        const glm::dvec2 b = base.Map(lsX);
        const int x = static_cast<int>(std::floor(b.x)), y = static_cast<int>(std::floor(b.y));
        if (x < 0 || y < 0 || x >= scene.shadowMap.width || y >= scene.shadowMap.height) continue;
        ++counted;
        largest = std::max(largest, rate);
        EXPECT_GE(importance.value[static_cast<std::size_t>(y) * scene.shadowMap.width + x], rate)
            << "readback pixel " << i;
    }
    ASSERT_GT(counted, 1000u);
    const double mapMax = *std::max_element(importance.value.begin(), importance.value.end());
    EXPECT_NEAR(mapMax, largest, 1e-12 * largest);
    // A texel width against the nearest floor pixel's, not the grazing floor's unbounded σ₁.
    EXPECT_LT(mapMax, 100.0);
}

TEST(WarpedMethods, GetTheSingleMapsTexelsAndCoverWhatTheirBaseCovers) {
    const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / ".." /
                                                "tests/cases/data/spatial_small.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"focused-tight", "lispsm-tight", "rtw", "rtw-lagrange", "logpsm"};
    options.keepBuffers = true;
    const std::int64_t texels =
        static_cast<std::int64_t>(scene.shadowMap.width) * scene.shadowMap.height;
    for (const Light& light : scene.lights) {
        const LightOutcome o = evaluator.Evaluate(light, options);
        const MethodOutcome& focused = o.methods[0];
        const MethodOutcome& lispsm = o.methods[1];
        for (std::size_t m = 2; m < o.methods.size(); ++m) {
            const MethodOutcome& w = o.methods[m];
            SCOPED_TRACE(w.method);
            ASSERT_TRUE(w.buffers.map.warp);
            EXPECT_FALSE(w.buffers.map.warp->IsLinear());
            if (w.method == "logpsm") {
                EXPECT_LE(w.metrics.texels, texels);
                EXPECT_GE(w.metrics.texels, texels - std::max(w.buffers.map.resolution.width,
                                                              w.buffers.map.resolution.height));
                // The same warp frame fitted to the same visible points (in log coordinates).
                EXPECT_LE(w.metrics.uncovered, std::max<std::int64_t>(2 * lispsm.metrics.uncovered,
                                                                      o.receiverPixels / 1000));
            } else {
                EXPECT_EQ(w.metrics.texels, texels);
                EXPECT_EQ(w.metrics.uncovered,
                          focused.metrics.uncovered);  // [0, W] onto [0, W]: the same cover
                EXPECT_EQ(w.matrix.p4, focused.matrix.p4);
            }
            EXPECT_TRUE(std::isfinite(w.metrics.h));
            EXPECT_GT(w.metrics.perspectiveMax, 0.0);
            EXPECT_EQ(w.buffers.shades.size(), focused.buffers.shades.size());
        }
    }
}

}  // namespace
}  // namespace lexel::spatial
