#include "lexel/flatland/sampling.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"
#include "test_scenes.h"

namespace lexel::flatland {
namespace {

using testing::Describe;
using testing::ExampleScene;
using testing::RandomScene;

TEST(Sampling, FloorHitsLieOnTheFloorAtPixelCenters) {
    FlatScene scene = ExampleScene();
    scene.geometry = {{{-50, 0}, {1e5, 0}}};  // long enough that every downward ray hits it
    const SamplingPass pass = RunSamplingPass(scene, 100);
    // The camera at height 2 looks 14.04° down with a 60° fov: the upper rays miss the floor.
    // A ray hits y = 0 when its slope is negative: σ tan30° < tan(14.04°) → pixels k < ~71.
    ASSERT_FALSE(pass.samples.empty());
    for (const auto& s : pass.samples) {
        EXPECT_NEAR(s.wsPoint.y(), 0.0, 1e-12);
        // The hit lies on the ray through the pixel center p = k + ½ (camera frame, sampling.h).
        const Vec2 cs = s.wsPoint - scene.camera.wsPosition;
        const double sigma = 2.0 * PixelCenter(s) / pass.pixels - 1.0;
        EXPECT_NEAR(cs.dot(Perp(scene.camera.wsDirection)) / cs.dot(scene.camera.wsDirection),
                    std::tan(std::numbers::pi / 6) * sigma, 1e-12);
    }
    const double slopeLimit =
        std::tan(std::atan(0.25)) / std::tan(std::numbers::pi / 6);  // σ at the horizon
    const int lastVisible = static_cast<int>(std::floor(100 * (1 + slopeLimit) / 2 - 0.5));
    EXPECT_EQ(pass.samples.back().pixel, std::min(lastVisible, 99));
    EXPECT_EQ(pass.samples.front().pixel, 0);
}

// The analytic footprint at the normal angle equals 1/|dl/dp| from a central finite difference of
// l(p), with l recomputed by casting rays at p ± h.
TEST(Sampling, AnalyticFootprintMatchesFiniteDifference) {
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
        const FlatScene scene = RandomScene(seed);
        SCOPED_TRACE(Describe(scene));
        const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
        const LexelSamples samples = MakeLexelSamples(pass, scene.lexels);
        const auto segments = Segments(scene);
        // l(X) at the normal axis: film coordinate tan(α − θ0) mapped onto [0, N].
        auto lexelOf = [&](const Vec2& ws) {
            const Vec2 d = ws - scene.wsLight;
            const double s = std::tan(std::atan2(d.y(), d.x()) - pass.wsAxis0);
            return samples.lexels * (s - samples.tanLow) / (samples.tanHigh - samples.tanLow);
        };
        const double h = 1e-4;  // pixels; the FD error is O(h²) ~ 1e-8 relative
        int checked = 0;
        for (std::size_t i = 0; i < pass.samples.size(); ++i) {
            const auto& s = pass.samples[i];
            const auto plus = CastPixelRay(scene.camera, segments, pass.pixels, PixelCenter(s) + h);
            const auto minus =
                CastPixelRay(scene.camera, segments, pass.pixels, PixelCenter(s) - h);
            if (!plus || !minus || plus->segment != s.segment || minus->segment != s.segment)
                continue;
            const double dldp = (lexelOf(plus->wsPoint) - lexelOf(minus->wsPoint)) / (2 * h);
            EXPECT_NEAR(samples.footprint0[i] * std::abs(dldp), 1.0, 1e-6) << "pixel " << s.pixel;
            ++checked;
        }
        EXPECT_GT(checked, static_cast<int>(pass.samples.size()) / 2);
    }
}

TEST(Sampling, NearFarClipHits) {
    FlatScene scene = ExampleScene();
    scene.camera.near = 5.0;
    scene.camera.far = 20.0;
    const SamplingPass pass = RunSamplingPass(scene, 500);
    for (const auto& s : pass.samples) {
        const double depth = (s.wsPoint - scene.camera.wsPosition).dot(scene.camera.wsDirection);
        EXPECT_GE(depth, 5.0 * (1 - 1e-12));
        EXPECT_LE(depth, 20.0 * (1 + 1e-12));
    }
    // The pass's depth range is the hits' (the ray's x_c, so equal within rounding).
    EXPECT_GE(pass.depthNear, 5.0);
    EXPECT_LE(pass.depthFar, 20.0);
    EXPECT_LT(pass.depthNear, pass.depthFar);
}

TEST(Sampling, NoVisiblePixelIsAnError) {
    FlatScene scene = ExampleScene();
    scene.geometry = {{{-50, 5}, {-40, 5}}};  // behind the camera
    try {
        RunSamplingPass(scene, 100);
        FAIL() << "expected DomainError";
    } catch (const DomainError& e) {
        EXPECT_NE(std::string(e.what()).find("no camera pixel sees any geometry"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Sampling, SweepOfHalfACircleHasNoValidAngle) {
    // A light between a floor and a ceiling that the camera sees on both sides of it: the
    // visible points surround the light, so no half-plane holds them.
    FlatScene scene = ExampleScene();
    scene.wsLight = {10, 1};
    scene.camera.wsPosition = {0, 1.5};
    scene.camera.wsDirection = {1, 0};
    scene.camera.fovDeg = 90;
    scene.geometry = {{{-50, 0}, {200, 0}}, {{5, 3}, {30, 3}}};
    try {
        RunSamplingPass(scene, 400);
        FAIL() << "expected DomainError";
    } catch (const DomainError& e) {
        EXPECT_NE(std::string(e.what()).find("no lexel plane has them all in front"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Sampling, LightOnAVisibleSegmentLineIsAnError) {
    FlatScene scene = ExampleScene();
    scene.wsLight = {-60, 0};  // on the floor's line, off the segment
    scene.geometry = {{{-50, 0}, {200, 0}}};
    try {
        RunSamplingPass(scene, 100);
        FAIL() << "expected DomainError";
    } catch (const DomainError& e) {
        EXPECT_EQ(e.subject(), Subject::kSegment);
        EXPECT_EQ(e.index(), (std::array<int, 2>{0, 0}));
    }
    EXPECT_FALSE(TrySamplingPass(scene, 100));
}

TEST(Scene, DegenerateGeometryIsRejected) {
    FlatScene zero = ExampleScene();
    zero.geometry = {{{1, 1}, {1, 1}}};
    EXPECT_THROW(CheckSceneGeometry(zero), DomainError);
    FlatScene lightOn = ExampleScene();
    lightOn.wsLight = {10, 0};
    EXPECT_THROW(CheckSceneGeometry(lightOn), DomainError);
    FlatScene inside = ExampleScene();
    inside.geometry.push_back(
        {{-1, 1}, {1, 1}, {1, 3}, {-1, 3}, {-1, 1}});  // a box around the camera
    try {
        CheckSceneGeometry(inside);
        FAIL();
    } catch (const DomainError& e) {
        EXPECT_EQ(std::string(e.what()), "the camera is inside the closed polyline 2");
        EXPECT_EQ(e.subject(), Subject::kCamera);
        EXPECT_EQ(e.index()[0], 2);
    }
}

}  // namespace
}  // namespace lexel::flatland
