// The viewer of Chong & Gortler's experiments (report §2.1, eq. 1): a pinhole camera with
// OpenGL's projection, and the resolutions of images and shadow maps.
//
// Conventions used by every spatial file:
//   - world space is right-handed; the generated scenes have +y up and the floor at y = 0;
//   - screen space (the report's x¹, x²) is in pixels: x¹ grows to the right over [0, width],
//     x² grows downwards over [0, height]; pixel (i, j) has its centre at (i + ½, j + ½);
//   - map space (the report's u¹, u²) is in texels with the same convention over the shadow map.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>

namespace lexel::spatial {

// Width × height in pixels (screen, readback) or texels (shadow map).
struct Resolution {
    int width = 0, height = 0;
    std::size_t Count() const { return static_cast<std::size_t>(width) * height; }
};

// A pinhole camera looking from `position` at `target`. Screen from world is
// Q = viewport · projection · view (report eq. 1); the projection is OpenGL's (depth in [-1, 1]
// before the viewport, which maps it to [0, 1]). Lengths in world units, angles in degrees.
struct Camera {
    glm::dvec3 position{0.0, 1.7, 10.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDeg = 60.0;            // full vertical field of view
    Resolution resolution{750, 750};  // of the final frame; sets the aspect ratio
    double nearPlane = 0.1, farPlane = 200.0;

    // width / height of `resolution`: the frustum's aspect ratio, for images of every size.
    double AspectRatio() const;
    glm::dmat4 ViewFromWorld() const;
    glm::dmat4 ClipFromView() const;  // OpenGL's: NDC z ∈ [-1, 1], -1 at the near plane
    // Q: world → (x¹ w, x² w, x³ w, w) with x¹, x² in pixels of an image of size `at` and x³ the
    // window depth in [0, 1] (affine in 1/z_view, so exactly affine in screen space over a plane).
    // Every image covers the camera's frustum (aspect ratio AspectRatio()): an `at` of another
    // aspect ratio, such as a square readback of a 16:9 camera, has non-square pixels.
    glm::dmat4 ScreenFromWorld(Resolution at) const;
    // World-space ray through screen point (x¹, x²) of an `at`-sized image, the one definition of
    // a pixel's ray for this camera: origin at the eye, direction not normalized, scaled to unit
    // length along the view axis. It is ScreenFromWorld(at)'s: every point eye + t·direction,
    // t > 0, maps to (x¹, x²) (tests/spatial/camera_test.cpp holds them together for every
    // aspect ratio of camera and image).
    glm::dvec3 RayDirection(glm::dvec2 xs, Resolution at) const;
    // The eight corners of the view frustum in world space (near face first, then far face, the
    // same winding).
    std::array<glm::dvec3, 8> FrustumCorners() const;
};

}  // namespace lexel::spatial
