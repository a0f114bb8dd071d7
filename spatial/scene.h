// The 3D world of Chong & Gortler's experiments (report §2.1, §3): a triangle soup in world space,
// a pinhole camera (the report's Q), point and directional lights, and the resolutions of the
// shadow map and of the low-resolution camera readback.
//
// Conventions used by every spatial file:
//   - world space is right-handed with +y up; the floor of the generated scenes is y = 0;
//   - screen space (the report's x¹, x²) is in pixels: x¹ grows to the right over [0, width],
//     x² grows downwards over [0, height]; pixel (i, j) has its centre at (i + ½, j + ½);
//   - map space (the report's u¹, u²) is in texels with the same convention over the shadow map.
#pragma once

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace lexel::spatial {

// Width × height in pixels (screen, readback) or texels (shadow map).
struct Resolution {
    int width = 0, height = 0;
    std::size_t Count() const { return static_cast<std::size_t>(width) * height; }
};

// Axis-aligned bounds in world units; empty until a point is added.
struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    bool Empty() const { return !(lo.x <= hi.x); }
    void Add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    glm::dvec3 Center() const { return 0.5 * (lo + hi); }
    double Radius() const { return 0.5 * glm::length(hi - lo); }  // of the enclosing sphere
    // Strictly inside (not on the boundary).
    bool Contains(const glm::dvec3& p) const {
        return glm::all(glm::lessThan(lo, p)) && glm::all(glm::lessThan(p, hi));
    }
    std::array<glm::dvec3, 8> Corners() const;
};

// Indexed triangles, world units. Positions are stored as float, as a renderer would; the passes
// recompute every intersection in double from them.
struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;

    void Append(const TriangleMesh& other);
    Bounds ComputeBounds() const;
    // Unit geometric normal of triangle t, counter-clockwise winding; zero when degenerate.
    glm::dvec3 FaceNormal(std::size_t t) const;
};

// The viewer. Screen from world is Q = viewport · projection · view (report eq. 1); the
// projection is OpenGL's (depth in [-1, 1] before the viewport, which maps it to [0, 1]).
struct Camera {
    glm::dvec3 position{0.0, 1.7, 10.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDeg = 60.0;
    Resolution resolution{750, 750};
    double nearPlane = 0.1, farPlane = 200.0;

    glm::dmat4 ViewFromWorld() const;
    glm::dmat4 ClipFromView() const;
    // Q: world → (x¹ w, x² w, x³ w, w) with x¹, x² in pixels of `at` and x³ the window depth in
    // [0, 1] (affine in 1/z_view, so exactly affine in screen space over a plane).
    glm::dmat4 ScreenFromWorld(Resolution at) const;
    // World-space ray through screen point (x¹, x²) of a `at`-sized image: origin at the eye,
    // direction not normalized, scaled so that it has unit length along the view axis.
    glm::dvec3 RayDirection(glm::dvec2 xs, Resolution at) const;
    // The eight corners of the view frustum in world space (near face first, then far face).
    std::array<glm::dvec3, 8> FrustumCorners() const;
};

struct Light {
    enum class Type { kPoint, kDirectional };
    Type type = Type::kPoint;
    glm::dvec3 position{0.0};              // point lights, world units
    glm::dvec3 direction{0.0, -1.0, 0.0};  // directional lights: unit, the way light travels
};

// `light_sweep` of a case: `count` point lights uniformly at random on the upper hemisphere
// (y ≥ centre.y) of radius `radius` around the centre of the floor, as in report §3.
struct LightSweep {
    int count = 500;
    std::uint64_t seed = 7;
    double radius = 100.0;
};

struct Scene {
    std::string name;
    Camera camera;
    std::vector<Light> lights;
    Resolution shadowMap{400, 400};
    Resolution readback{180, 180};
    TriangleMesh geometry;
    // The floor plane n·x + d = 0 as (n, d) with |n| = 1, n facing up: set from the first `plane`
    // primitive or by the floor_objects generator; plane-optimal needs it.
    std::optional<glm::dvec4> floorPlane;
    std::optional<LightSweep> lightSweep;
    std::vector<Camera> cameraPath;  // optional sequence of poses (temporal hysteresis)
};

}  // namespace lexel::spatial
