// The shimmer along a case's camera_path (cases/run/camera_path.h): the share of the stable
// pixels whose shadow decision flips between two poses, by hand; a sweep's per-light shimmer is
// the camera-path study's, light for light and method for method; a camera that stands still
// does not shimmer.
#include "lexel/cases/run/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"

namespace lexel::cases {
namespace {

using spatial::Shade;

// Pixel by pixel: 0 stable and flipped; 1 and 2 stable; 3 and 5 change truth; 4 is not counted
// before (empty) and 6 not after (facing away). So 1 of 3 stable pixels flips: 33.3%.
TEST(CameraPath, ShimmerIsTheShareOfStablePixelsThatFlip) {
    const std::vector<Shade> before = {Shade::kLit,     Shade::kShadowed, Shade::kLit,
                                       Shade::kLit,     Shade::kEmpty,    Shade::kLit,
                                       Shade::kShadowed};
    const std::vector<Shade> after = {Shade::kShadowed,  Shade::kShadowed, Shade::kLit,
                                      Shade::kLit,       Shade::kLit,      Shade::kLit,
                                      Shade::kFacingAway};
    const std::vector<std::uint8_t> truthBefore = {0, 1, 0, 1, 0, 0, 1};
    const std::vector<std::uint8_t> truthAfter = {0, 1, 0, 0, 0, 1, 1};
    EXPECT_DOUBLE_EQ(ShimmerPercent(before, truthBefore, after, truthAfter), 100.0 / 3.0);
    // Nothing stable: 0, not NaN.
    EXPECT_EQ(ShimmerPercent(std::vector<Shade>{Shade::kEmpty}, std::vector<std::uint8_t>{0},
                             std::vector<Shade>{Shade::kLit}, std::vector<std::uint8_t>{0}),
              0.0);
}

// The courtyard at a 200² frame (its camera_path has three poses), with its two fixed lights.
spatial::Scene SmallCourtyard() {
    spatial::Scene scene =
        LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial/courtyard.json");
    scene.camera.resolution = {200, 200};
    for (spatial::Camera& pose : scene.cameraPath) pose.resolution = {200, 200};
    return scene;
}

TEST(CameraPath, SweepShimmerIsTheStudysLightForLight) {
    const spatial::Scene scene = SmallCourtyard();
    ASSERT_EQ(scene.cameraPath.size(), 3u);
    const std::vector<std::string> methods = {"focused", "tsm"};
    const auto backend = spatial::MakeCpuRenderer(scene.geometry);
    const std::vector<CameraPathStudy> studies = RunCameraPathStudy(scene, *backend, methods);
    const SweepResult sweep = RunSweep(scene, methods, scene.lights, {}, BackendKind::kCpu, {}, 3);
    ASSERT_EQ(sweep.shimmerPoses, 3);
    double total = 0.0;
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        for (std::size_t m = 0; m < methods.size(); ++m) {
            EXPECT_DOUBLE_EQ(sweep.cells[l][m].shimmer, studies[l].shimmerPercent[m])
                << "light " << l << " " << methods[m];
            total += sweep.cells[l][m].shimmer;
        }
    EXPECT_GT(total, 0.0);  // the maps refit as the camera walks: some stable pixels flip
}

TEST(CameraPath, AStillCameraDoesNotShimmer) {
    spatial::Scene scene = SmallCourtyard();
    scene.cameraPath = {scene.camera, scene.camera};
    const std::vector<std::string> methods = {"focused", "tsm", "rtw"};
    const SweepResult sweep = RunSweep(scene, methods, scene.lights, {}, BackendKind::kCpu, {}, 2);
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        for (std::size_t m = 0; m < methods.size(); ++m)
            EXPECT_EQ(sweep.cells[l][m].shimmer, 0.0) << "light " << l << " " << methods[m];
    // Without shimmer poses the cells say so.
    const SweepResult none = RunSweep(scene, {"focused"}, scene.lights);
    EXPECT_EQ(none.shimmerPoses, 0);
    EXPECT_TRUE(std::isnan(none.cells[0][0].shimmer));
}

}  // namespace
}  // namespace lexel::cases
