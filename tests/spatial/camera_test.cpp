// The camera's one definition of a pixel's ray (camera.h): RayDirection is ScreenFromWorld's
// inverse on the ray for every aspect ratio of camera and image. Before: RayDirection took the
// aspect ratio from the image while ScreenFromWorld took it from the camera, so the GL backend's
// readback (which rebuilds its points along RayDirection) saw another frustum than the CPU's
// whenever the readback's aspect ratio was not the camera's.
#include "lexel/spatial/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace lexel::spatial {
namespace {

struct Aspect {
    const char* name;
    Resolution camera;
};

const std::vector<Aspect>& Cameras() {
    static const std::vector<Aspect> cameras = {
        {"1:1", {120, 120}}, {"4:3", {160, 120}}, {"16:9", {192, 108}}, {"9:16", {108, 192}}};
    return cameras;
}

// Images of every camera: square, the camera's own aspect at another size, and the other ones.
std::vector<Resolution> Images() {
    std::vector<Resolution> images = {{64, 64}, {180, 180}, {7, 3}};
    for (const Aspect& a : Cameras()) images.push_back({a.camera.width / 2, a.camera.height / 2});
    return images;
}

Camera TiltedCamera(Resolution resolution) {
    Camera camera;
    camera.position = {2.0, 3.0, -9.0};
    camera.target = {0.5, 0.5, 1.0};
    camera.fovYDeg = 50.0;
    camera.resolution = resolution;
    camera.nearPlane = 0.1;
    camera.farPlane = 50.0;
    return camera;
}

TEST(Camera, RayDirectionIsScreenFromWorldsInverseForEveryAspectRatio) {
    std::mt19937_64 rng(24);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const Aspect& a : Cameras()) {
        const Camera camera = TiltedCamera(a.camera);
        const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
        for (const Resolution at : Images()) {
            const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(at);
            double worst = 0.0;
            for (int k = 0; k < 200; ++k) {
                const glm::dvec2 xs(unit(rng) * at.width, unit(rng) * at.height);
                const glm::dvec3 direction = camera.RayDirection(xs, at);
                ASSERT_NEAR(glm::dot(direction, forward), 1.0, 1e-14);
                for (const double t : {camera.nearPlane, 1.0, camera.farPlane}) {
                    const glm::dvec4 h =
                        screenFromWorld * glm::dvec4(camera.position + t * direction, 1.0);
                    worst = std::max(worst, glm::length(glm::dvec2(h) / h.w - xs));
                }
            }
            // Pixels: rounding of a 4×4 product at coordinates up to 200.
            EXPECT_LT(worst, 1e-10)
                << "camera " << a.name << ", image " << at.width << "×" << at.height;
        }
    }
}

// The frustum's corners are the image corners at window depth 0 (near) and 1 (far), in every
// image size.
TEST(Camera, FrustumCornersAreTheImageCornersAtTheNearAndFarPlanes) {
    for (const Aspect& a : Cameras()) {
        const Camera camera = TiltedCamera(a.camera);
        const auto corners = camera.FrustumCorners();
        for (const Resolution at : Images()) {
            const glm::dvec2 screen[4] = {{0.0, 0.0},
                                          {double(at.width), 0.0},
                                          {double(at.width), double(at.height)},
                                          {0.0, double(at.height)}};
            const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(at);
            for (int i = 0; i < 8; ++i) {
                const glm::dvec4 h = screenFromWorld * glm::dvec4(corners[i], 1.0);
                EXPECT_LT(glm::length(glm::dvec2(h) / h.w - screen[i % 4]), 1e-9)
                    << "camera " << a.name << ", corner " << i;
                EXPECT_NEAR(h.z / h.w, i < 4 ? 0.0 : 1.0, 1e-9) << "camera " << a.name;
            }
        }
    }
}

// A 4:3 camera's square readback spans the same view angles as its frame: the horizontal half
// angle is atan(aspect · tan(fov/2)), not the vertical one (the bug gave 1:1 ray spreads).
TEST(Camera, SquareImageOfAWideCameraSpansTheCamerasHorizontalAngle) {
    Camera camera = TiltedCamera({160, 120});
    camera.position = {0.0, 0.0, 0.0};
    camera.target = {0.0, 0.0, -1.0};
    const glm::dvec3 edge = camera.RayDirection({64.0, 32.0}, {64, 64});  // right edge, centre row
    const double halfAngle = std::atan(edge.x / -edge.z);
    EXPECT_NEAR(halfAngle, std::atan(4.0 / 3.0 * std::tan(glm::radians(25.0))), 1e-15);
}

}  // namespace
}  // namespace lexel::spatial
