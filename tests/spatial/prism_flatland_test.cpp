// The flatland truth for the 3D optimizer (issue: "a 3D scene that is a prism over a flatland case
// must give the flatland optimum's angle for p4").
//
// The prism. Every flatland segment (a, b) becomes the quad {(a, z), (b, z) : |z| ≤ Z} of world
// space (x, y, z), so the flatland plane is z = 0; the light sits at (L, 0) and the camera at
// (C, 0), looking along (d, 0) with up = (0, 0, -1), which makes its screen x¹ axis the flatland
// film direction u = d rotated +90°. With the 3D camera's horizontal field of view equal to the
// flatland one and the same pixel count, the rays of readback row y = 1 of a 3-row readback
// (ndc y = 0) are the flatland pixel rays exactly: same hits, same pixel coordinates.
//
// The energy. For a light matrix whose optical axis lies in the flatland plane (p4 = (a, 0) in
// world terms) and whose map rows are p1 = (in-plane film row) and p2 = c·e_z, u¹ does not depend
// on z and, in the central row, u² has no x¹ derivative. So J = ∂u/∂x is diagonal there and
//     ‖J⁻¹‖²_F = (dx¹/du¹)² + (dx²/du²)²:
// the flatland footprint f = dp/dl squared, plus an extrusion term. u¹ is the flatland lexel
// coordinate up to the map's scale; the extrusion term is the footprint along z, where the map
// spends its whole height on the few rows of the readback: (3 rows / 400 texels)² ≈ 6e-5 of the
// in-plane term. Its dependence on p4 moves the 3D optimum away from the flatland L2 angle by a
// correspondingly small amount, which the tests bound; the per-sample footprint itself matches
// exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/sampling.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {
namespace {

constexpr double kExtrusion = 2.0;  // Z: half-width of the prism along z, world units

struct Prism {
    flatland::FlatScene flat;
    Scene scene;
    Readback readback;
    LightSpace lightSpace;
    int row = 1;  // the readback row in the flatland plane
};

// The prism over a flatland case; the readback is the flatland pixel count by 3 rows. The
// flatland coordinates are rounded to float first, as the 3D mesh stores them, so that both
// worlds hold the same geometry to the last bit.
Prism MakePrism(flatland::FlatScene flat) {
    for (auto& polyline : flat.geometry)
        for (flatland::Vec2& p : polyline)
            p = {static_cast<float>(p.x()), static_cast<float>(p.y())};
    Scene scene;
    for (const auto& polyline : flat.geometry)
        for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
            const glm::vec3 a(polyline[i].x(), polyline[i].y(), 0.0f);
            const glm::vec3 b(polyline[i + 1].x(), polyline[i + 1].y(), 0.0f);
            const glm::vec3 z(0.0f, 0.0f, static_cast<float>(kExtrusion));
            TriangleMesh quad;
            quad.positions = {a - z, b - z, b + z, a + z};
            quad.triangles = {{0, 1, 2}, {0, 2, 3}};
            scene.geometry.Append(quad);
        }
    const flatland::FlatCamera& fc = flat.camera;
    const Resolution readback{fc.pixels, 3};
    Camera& camera = scene.camera;
    camera.position = {fc.wsPosition.x(), fc.wsPosition.y(), 0.0};
    camera.target = camera.position + glm::dvec3(fc.wsDirection.x(), fc.wsDirection.y(), 0.0);
    camera.up = {0.0, 0.0, -1.0};
    camera.resolution = readback;
    const double aspect = static_cast<double>(readback.width) / readback.height;
    // tan(fovY/2)·aspect = tan(fov/2): the horizontal field of view is the flatland one.
    camera.fovYDeg =
        2.0 * glm::degrees(std::atan(std::tan(0.5 * glm::radians(fc.fovDeg)) / aspect));
    camera.nearPlane = fc.near;
    camera.farPlane = std::isfinite(fc.far) ? fc.far : 1e4;
    Light light;
    light.position = {flat.wsLight.x(), flat.wsLight.y(), 0.0};
    scene.lights = {light};
    scene.readback = readback;
    const std::unique_ptr<RenderBackend> backend = MakeCpuRenderer(scene.geometry);
    Readback rb = RenderReadback(*backend, camera, readback);
    const LightSpace lightSpace(light, scene.geometry.ComputeBounds());
    return Prism{flat, std::move(scene), std::move(rb), lightSpace};
}

// Flatland's samples: every smooth pixel of the central row (the flatland pass has no notion of
// depth discontinuities, so the comparison keeps the pixels both sides use), and every visible
// point of the readback as a relevant point.
LightSamples CentralRowSamples(const Prism& prism) {
    const CameraBuffer& buf = prism.readback.buffer;
    const glm::dmat3 lsFromWs = prism.lightSpace.LsFromWsLinear();
    LightSamples s;
    for (const glm::dvec3& ws : prism.readback.wsRelevant)
        s.lsRelevant.push_back(prism.lightSpace.ToLight(ws));
    const int w = buf.resolution.width;
    for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(prism.row) * w + x;
        if (!prism.readback.smooth[i]) continue;
        s.lsX.push_back(prism.lightSpace.ToLight(buf.wsPosition[i]));
        s.dXdx1.push_back(lsFromWs * prism.readback.dWdx1[i]);
        s.dXdx2.push_back(lsFromWs * prism.readback.dWdx2[i]);
        s.pixel.push_back(static_cast<std::uint32_t>(x));
    }
    return s;
}

// The flatland lexel samples of the same pixels, the lexels spanning every visible point.
flatland::LexelSamples FlatlandSamplesAt(const flatland::SamplingPass& pass,
                                         const LightSamples& samples, double lexels) {
    std::vector<double> angle, dpdAngle;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::size_t next = 0;
    for (const flatland::FlatSample& f : pass.samples) {
        lo = std::min(lo, f.lsAngle);
        hi = std::max(hi, f.lsAngle);
        if (next < samples.pixel.size() && samples.pixel[next] == static_cast<unsigned>(f.pixel)) {
            angle.push_back(f.lsAngle);
            dpdAngle.push_back(flatland::PixelsPerRadian(pass, f));
            ++next;
        }
    }
    EXPECT_EQ(next, samples.pixel.size()) << "a 3D sample has no flatland pixel";
    return flatland::MakeLexelSamples(angle, dpdAngle, pass.wsAxis0, lexels, lo, hi);
}

// World direction of a light-space axis: p·X = (Rᵀp)·(x − L) for a point light.
glm::dvec3 WorldAxis(const LightSpace& lightSpace, const glm::dvec3& lsP) {
    return glm::transpose(lightSpace.LsFromWsLinear()) * lsP;
}

double AngleDifferenceDeg(double a, double b) { return glm::degrees(flatland::WrapAngle(a - b)); }

class PrismOverFlatland : public ::testing::TestWithParam<const char*> {};

// Per sample, the 3D Jacobian of a light matrix with an in-plane axis reproduces the flatland
// footprint dp/dl from scratch (lexel_remap.h), at several axes across the valid range.
TEST_P(PrismOverFlatland, JacobianInThePlaneIsTheFlatlandFootprint) {
    const Prism prism = MakePrism(
        cases::LoadFlatScene(std::string(LEXEL_CASES_DIR "/flatland/") + GetParam() + ".json"));
    const flatland::FlatScene& flat = prism.flat;
    const LightSamples samples = CentralRowSamples(prism);
    const flatland::SamplingPass pass = flatland::RunSamplingPass(flat, flat.camera.pixels);
    ASSERT_GT(samples.lsX.size(), pass.samples.size() * 9 / 10);

    const glm::dvec3 wsLight(flat.wsLight.x(), flat.wsLight.y(), 0.0);
    const double lexels = 1000.0;
    for (double offsetDeg : {-20.0, -5.0, 0.0, 7.0, 25.0}) {
        SCOPED_TRACE("axis offset " + std::to_string(offsetDeg) + "°");
        const double wsAxis = pass.wsAxis0 + glm::radians(offsetDeg);
        const auto reference = flatland::FootprintsFromScratch(pass, flat.wsLight, wsAxis, lexels);
        ASSERT_TRUE(reference);
        // The flatland map at this axis (lexel_remap.h): film coordinate s = (b·d)/(a·d) with
        // d = x − L, and l = N (s − s_min) / (s_max − s_min) over every visible point.
        const glm::dvec3 a(std::cos(wsAxis), std::sin(wsAxis), 0.0), b(-a.y, a.x, 0.0);
        double sLo = std::numeric_limits<double>::infinity(), sHi = -sLo;
        for (const flatland::FlatSample& f : pass.samples) {
            const glm::dvec3 d = glm::dvec3(f.wsPoint.x(), f.wsPoint.y(), 0.0) - wsLight;
            sLo = std::min(sLo, glm::dot(b, d) / glm::dot(a, d));
            sHi = std::max(sHi, glm::dot(b, d) / glm::dot(a, d));
        }
        const glm::dmat3 lsFromWs = prism.lightSpace.LsFromWsLinear();
        LightMatrix m;
        m.p4 = lsFromWs * a;
        m.p1 = lsFromWs * ((lexels / (sHi - sLo)) * (b - sLo * a));
        m.p2 = lsFromWs * glm::dvec3(0.0, 0.0, 400.0);  // any z scale: it only feeds u²
        std::size_t k = 0, compared = 0;
        for (std::size_t i = 0; i < pass.samples.size() && k < samples.pixel.size(); ++i) {
            if (static_cast<unsigned>(pass.samples[i].pixel) != samples.pixel[k]) continue;
            // The readback's central differences straddle a crease when a neighbouring pixel sees
            // another segment (the smoothness threshold lets mild creases through, by design):
            // compare only where both neighbours see the same segment as the pixel.
            const bool interior = i > 0 && i + 1 < pass.samples.size() &&
                                  pass.samples[i - 1].pixel + 1 == pass.samples[i].pixel &&
                                  pass.samples[i + 1].pixel == pass.samples[i].pixel + 1 &&
                                  pass.samples[i - 1].segment == pass.samples[i].segment &&
                                  pass.samples[i + 1].segment == pass.samples[i].segment;
            if (!interior) {
                ++k;
                continue;
            }
            glm::dvec2 row1, row2;
            SampleJacobian(m, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k], &row1, &row2);
            // J is diagonal in the flatland plane: u¹ ignores z, u² is flat along the row.
            ASSERT_NEAR(row1.y, 0.0, 1e-8 * std::abs(row1.x)) << "pixel " << samples.pixel[k];
            ASSERT_NEAR(row2.x, 0.0, 1e-8 * std::abs(row2.y)) << "pixel " << samples.pixel[k];
            ASSERT_NEAR(std::abs(1.0 / row1.x), (*reference)[i], 1e-7 * (*reference)[i])
                << "pixel " << samples.pixel[k];
            ++k;
            ++compared;
        }
        EXPECT_GT(compared, samples.lsX.size() * 9 / 10);
    }
}

// Over the whole valid range of in-plane axes, h of the fitted map (FitMapToPoints, no margin) is
// the flatland L2 objective of the same pixels times (N / W)² (N flatland lexels, W map texels
// along the flatland direction), to 1e-4: the extrusion term adds to it, and the minimum-area
// rectangle around the thin sliver of projected points may tilt by O(thickness / length), which
// changes the in-plane scale at second order.
TEST_P(PrismOverFlatland, EnergyIsTheFlatlandL2PlusASmallExtrusionTerm) {
    const Prism prism = MakePrism(
        cases::LoadFlatScene(std::string(LEXEL_CASES_DIR "/flatland/") + GetParam() + ".json"));
    const flatland::FlatScene& flat = prism.flat;
    const LightSamples samples = CentralRowSamples(prism);
    const flatland::SamplingPass pass = flatland::RunSamplingPass(flat, flat.camera.pixels);
    const double lexels = 1000.0;
    const Resolution map{400, 400};
    const flatland::LexelSamples flatSamples = FlatlandSamplesAt(pass, samples, lexels);
    const flatland::ValidInterval valid = flatland::ValidTInterval(flatSamples);
    const double expectedRatio = (lexels / map.width) * (lexels / map.width);
    const glm::dmat3 lsFromWs = prism.lightSpace.LsFromWsLinear();
    double worst = 0.0;
    for (int i = 1; i < 60; ++i) {
        const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
        const double t = std::tan(xLo + (xHi - xLo) * i / 60.0);
        const double wsAxis = flatland::WsAxisFromT(flatSamples, t);
        const glm::dvec3 a(std::cos(wsAxis), std::sin(wsAxis), 0.0);
        const std::optional<LightMatrix> m = FitMapToPoints(lsFromWs * a, samples.lsRelevant, map);
        ASSERT_TRUE(m) << "axis " << glm::degrees(wsAxis) << "°";
        const double ratio =
            Energy(*m, samples) / flatland::AngleObjective(flatSamples, Metric::kL2, t);
        ASSERT_NEAR(ratio / expectedRatio, 1.0, 1e-4) << "axis " << glm::degrees(wsAxis) << "°";
        worst = std::max(worst, std::abs(ratio / expectedRatio - 1.0));
    }
    std::printf("[ %s ] |h / ((N/W)² L2) - 1| ≤ %.2e over the valid axes\n", GetParam(), worst);
}

// Algorithm 1 with the Ceres refinement, started from the focused axis, lands on the flatland L2
// optimum's axis: in the flatland plane (no z component, by the mirror symmetry z → −z) and at
// the flatland angle up to the extrusion term's pull.
TEST_P(PrismOverFlatland, OptimalAxisIsTheFlatlandOptimum) {
    const Prism prism = MakePrism(
        cases::LoadFlatScene(std::string(LEXEL_CASES_DIR "/flatland/") + GetParam() + ".json"));
    const flatland::FlatScene& flat = prism.flat;
    const LightSamples samples = CentralRowSamples(prism);
    const flatland::SamplingPass pass = flatland::RunSamplingPass(flat, flat.camera.pixels);
    const flatland::LexelSamples flatSamples = FlatlandSamplesAt(pass, samples, 1000.0);
    const flatland::AngleSolution flatOptimum = flatland::SolveL2Exact(flatSamples);

    const BaselineContext context =
        MakeBaselineContext(prism.scene, prism.lightSpace, prism.scene.geometry.ComputeBounds(),
                            prism.readback.wsRelevant);
    const glm::dvec3 initialP4 = FocusedLightMatrix(context).p4;

    OptimizerOptions options;
    options.refine = true;
    options.refineIterations = 100;
    const OptimizerResult result = OptimizeLightMatrix(samples, initialP4, {400, 400}, options);
    const glm::dvec3 wsAxis = WorldAxis(prism.lightSpace, result.matrix.p4);
    const double optimumDeg =
        AngleDifferenceDeg(std::atan2(wsAxis.y, wsAxis.x), flatOptimum.wsAxis);
    const double initialDeg =
        AngleDifferenceDeg(std::atan2(WorldAxis(prism.lightSpace, initialP4).y,
                                      WorldAxis(prism.lightSpace, initialP4).x),
                           flatOptimum.wsAxis);
    std::printf(
        "[ %s ] flatland L2 optimum %.4f°, focused start %+.4f°, 3D optimal %+.5f° "
        "(z component %.2e), h %.6g → %.6g (search) → %.6g (refined)\n",
        GetParam(), glm::degrees(flatOptimum.wsAxis), initialDeg, optimumDeg, wsAxis.z,
        result.hAfterIteration.front(), result.hBeforeRefine, result.h);
    EXPECT_NEAR(wsAxis.z, 0.0, 1e-6 * glm::length(wsAxis));
    EXPECT_NEAR(optimumDeg, 0.0, 0.02);
}

INSTANTIATE_TEST_SUITE_P(ThesisCases, PrismOverFlatland,
                         ::testing::Values("simple_geometry", "light_from_top", "single_plane",
                                           "projection_aliasing"),
                         [](const auto& info) { return std::string(info.param); });

}  // namespace
}  // namespace lexel::spatial
