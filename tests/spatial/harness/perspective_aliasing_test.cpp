// Lloyd 2006's perspective aliasing w_l/w_i per pixel (evaluation.h, PerspectiveAliasing) against
// a closed form (orthographic map, light overhead) and against central differences of the map
// with an SVD (Eigen) for warped maps and point lights; the effective storage factor's scaling.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <random>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"

namespace lexel::spatial {
namespace {

Camera TestCamera() {
    Camera camera;
    camera.position = {0.0, 2.0, 10.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.fovYDeg = 60.0;
    camera.resolution = {640, 480};
    return camera;
}

Bounds UnitBox(double halfExtent) {
    Bounds bounds;
    bounds.Add(glm::dvec3(-halfExtent));
    bounds.Add(glm::dvec3(halfExtent));
    return bounds;
}

// w_l/w_i from 5-point central differences of u along an orthonormal basis ⊥ the light's ray,
// with σ₁ of the 2×2 inverse from Eigen's SVD.
double FiniteDifferenceAliasing(const Camera& camera, const LightSpace& lightSpace,
                                const LightMatrix& matrix, const glm::dvec3& wsPoint,
                                double wsStep) {
    const glm::dvec3 wsRay = -lightSpace.DirectionToLight(wsPoint);
    const glm::dvec3 wsE1 = glm::normalize(glm::cross(wsRay, glm::dvec3(0.3, 0.5, 0.8)));
    const glm::dvec3 wsE2 = glm::cross(wsRay, wsE1);
    Eigen::Matrix2d jacobian;
    const glm::dvec3 axes[2] = {wsE1, wsE2};
    for (int c = 0; c < 2; ++c) {
        const auto u = [&](double t) {
            return matrix.Map(lightSpace.ToLight(wsPoint + t * wsStep * axes[c]));
        };
        const glm::dvec2 du = (-u(2) + 8.0 * u(1) - 8.0 * u(-1) + u(-2)) / (12.0 * wsStep);
        jacobian(0, c) = du.x;
        jacobian(1, c) = du.y;
    }
    const double wsTexel =
        Eigen::JacobiSVD<Eigen::Matrix2d>(jacobian.inverse()).singularValues()(0);
    const glm::dvec3 esPoint = glm::dvec3(camera.ViewFromWorld() * glm::dvec4(wsPoint, 1.0));
    const double wsPixel =
        2.0 * std::tan(glm::radians(30.0)) * (-esPoint.z) / camera.resolution.height;
    return wsTexel / wsPixel;
}

TEST(PerspectiveAliasing, OrthographicMapWithTheLightOverheadIsTexelOverPixelWidth) {
    // Light straight down, p4 = (0, 0, 1): u = (a X1, b X2) / s, so a texel is s/a × s/b world
    // units across the beam and w_l = s / min(a, b); the pixel is 2 tan30° z / 480 wide.
    const Camera camera = TestCamera();
    const LightSpace lightSpace({Light::Type::kDirectional, {}, {0.0, -1.0, 0.0}}, UnitBox(5.0));
    LightMatrix matrix;
    matrix.p1 = {300.0, 0.0, 0.0};
    matrix.p2 = {0.0, 200.0, 0.0};
    matrix.p4 = {0.0, 0.0, 1.0};
    for (const glm::dvec3 wsPoint : {glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(1.0, 0.5, -3.0)}) {
        const double s = lightSpace.ToLight(wsPoint).z;
        const double z =
            glm::dot(wsPoint - camera.position, glm::normalize(camera.target - camera.position));
        const double expected = (s / 200.0) / (2.0 * std::tan(glm::radians(30.0)) * z / 480.0);
        EXPECT_NEAR(PerspectiveAliasing(camera, lightSpace, matrix, wsPoint), expected,
                    1e-12 * expected);
    }
}

TEST(PerspectiveAliasing, MatchesCentralDifferencesForWarpedMapsAndPointLights) {
    const Camera camera = TestCamera();
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const bool point = trial % 2 == 0;
        const glm::dvec3 wsLight(8.0 * unit(rng), 20.0 + 5.0 * unit(rng), 8.0 * unit(rng));
        const Light light = point ? Light{Light::Type::kPoint, wsLight, {}}
                                  : Light{Light::Type::kDirectional, {}, -wsLight};
        const LightSpace lightSpace(light, UnitBox(4.0));
        LightMatrix matrix;
        matrix.p1 = {100.0 + 50.0 * unit(rng), 30.0 * unit(rng), 30.0 * unit(rng)};
        matrix.p2 = {30.0 * unit(rng), 100.0 + 50.0 * unit(rng), 30.0 * unit(rng)};
        matrix.p4 = glm::normalize(glm::dvec3(0.2 * unit(rng), 0.2 * unit(rng), 1.0));
        const glm::dvec3 wsPoint(3.0 * unit(rng), 3.0 * unit(rng), 3.0 * unit(rng));
        const double measured = PerspectiveAliasing(camera, lightSpace, matrix, wsPoint);
        const double reference =
            FiniteDifferenceAliasing(camera, lightSpace, matrix, wsPoint, 1e-3);
        EXPECT_NEAR(measured, reference, 1e-7 * reference)
            << "trial " << trial << (point ? " point" : " directional") << " light (" << wsLight.x
            << ", " << wsLight.y << ", " << wsLight.z << "), point (" << wsPoint.x << ", "
            << wsPoint.y << ", " << wsPoint.z << ")";
    }
}

TEST(PerspectiveAliasing, BehindTheMapIsInfinite) {
    const Camera camera = TestCamera();
    const LightSpace lightSpace({Light::Type::kPoint, {0.0, 20.0, 0.0}, {}}, UnitBox(4.0));
    LightMatrix matrix;
    matrix.p4 = -lightSpace.ToLight(glm::dvec3(0.0));  // the point is behind p4·X = 0
    EXPECT_TRUE(std::isinf(PerspectiveAliasing(camera, lightSpace, matrix, glm::dvec3(0.0))));
}

TEST(EffectiveStorageFactor, IsTexelsTimesAliasingSquaredOverPixels) {
    // A 400² map whose worst texel is 3 pixels wide needs 1200² texels; over a 750² frame that is
    // S̄ = 1200² / 750² = 2.56.
    EXPECT_DOUBLE_EQ(EffectiveStorageFactor(400 * 400, 3.0, 750 * 750), 2.56);
    EXPECT_EQ(EffectiveStorageFactor(400 * 400, 3.0, 0), 0.0);
}

TEST(Evaluation, StorageFactorIsTheWorstPerspectiveAliasingOfTheShadedPixels) {
    // The CLI's small case: its focused map covers every counted pixel, so the evaluation's
    // maximum is the maximum of PerspectiveAliasing over the lit and shadowed pixels.
    const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / ".." /
                                                "tests/cases/data/spatial_small.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"focused", "pssm"};
    options.keepBuffers = true;
    const LightOutcome o = evaluator.Evaluate(scene.lights.front(), options);
    const LightSpace lightSpace(o.light, evaluator.bounds());
    const std::int64_t framePixels =
        static_cast<std::int64_t>(scene.camera.resolution.width) * scene.camera.resolution.height;
    const MethodOutcome& focused = o.methods[0];
    ASSERT_EQ(focused.metrics.uncovered, 0);
    double worst = 0.0;
    for (std::size_t i = 0; i < focused.buffers.shades.size(); ++i)
        if (focused.buffers.shades[i] == Shade::kLit ||
            focused.buffers.shades[i] == Shade::kShadowed)
            worst = std::max(
                worst, PerspectiveAliasing(scene.camera, lightSpace, focused.buffers.map.matrix,
                                           evaluator.frame().wsPosition[i]));
    EXPECT_EQ(focused.metrics.perspectiveMax, worst);
    for (const MethodOutcome& m : o.methods) {
        EXPECT_EQ(m.metrics.texels, scene.shadowMap.width * scene.shadowMap.height) << m.method;
        EXPECT_GT(m.metrics.perspectiveMax, 0.0) << m.method;
        EXPECT_LE(m.metrics.perspectiveP99, m.metrics.perspectiveMax) << m.method;
        EXPECT_DOUBLE_EQ(m.metrics.storageFactor,
                         static_cast<double>(m.metrics.texels) * m.metrics.perspectiveMax *
                             m.metrics.perspectiveMax / static_cast<double>(framePixels))
            << m.method;
    }
}

}  // namespace
}  // namespace lexel::spatial
