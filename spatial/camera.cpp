// The camera's matrices (report eq. 1).
#include "lexel/spatial/camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lexel::spatial {

glm::dmat4 Camera::ViewFromWorld() const { return glm::lookAt(position, target, up); }

double Camera::AspectRatio() const {
    return static_cast<double>(resolution.width) / resolution.height;
}

glm::dmat4 Camera::ClipFromView() const {
    return glm::perspective(glm::radians(fovYDeg), AspectRatio(), nearPlane, farPlane);
}

glm::dmat4 Camera::ScreenFromWorld(Resolution at) const {
    // Viewport: NDC x ∈ [-1, 1] → [0, W]; NDC y ∈ [-1, 1] → [H, 0] (rows grow downwards);
    // NDC z ∈ [-1, 1] → [0, 1].
    glm::dmat4 screenFromNdc(1.0);
    screenFromNdc[0][0] = 0.5 * at.width;
    screenFromNdc[1][1] = -0.5 * at.height;
    screenFromNdc[2][2] = 0.5;
    screenFromNdc[3] = glm::dvec4(0.5 * at.width, 0.5 * at.height, 0.5, 1.0);
    return screenFromNdc * ClipFromView() * ViewFromWorld();
}

// The inverse of ScreenFromWorld(at) on the ray: NDC (x, y) = (2x¹/W - 1, 1 - 2x²/H) of the
// `at`-sized image, and glm::perspective's x_ndc = x_view / (aspect tan(fov/2) z), y_ndc =
// y_view / (tan(fov/2) z) at view depth z, with the aspect of `resolution`, as ClipFromView: the
// image covers the camera's frustum whatever its own aspect ratio.
glm::dvec3 Camera::RayDirection(glm::dvec2 xs, Resolution at) const {
    const glm::dvec3 forward = glm::normalize(target - position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 trueUp = glm::cross(right, forward);
    const double tanHalf = std::tan(0.5 * glm::radians(fovYDeg));
    const double aspect = AspectRatio();
    const double ndcX = 2.0 * xs.x / at.width - 1.0;
    const double ndcY = 1.0 - 2.0 * xs.y / at.height;
    return forward + (ndcX * tanHalf * aspect) * right + (ndcY * tanHalf) * trueUp;
}

std::array<glm::dvec3, 8> Camera::FrustumCorners() const {
    std::array<glm::dvec3, 8> corners;
    const glm::dvec2 screen[4] = {{0.0, 0.0},
                                  {double(resolution.width), 0.0},
                                  {double(resolution.width), double(resolution.height)},
                                  {0.0, double(resolution.height)}};
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 dir = RayDirection(screen[i], resolution);
        corners[i] = position + nearPlane * dir;
        corners[i + 4] = position + farPlane * dir;
    }
    return corners;
}

}  // namespace lexel::spatial
