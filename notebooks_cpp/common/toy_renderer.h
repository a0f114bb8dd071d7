// A stand-in for a renderer, for the 3D teaching programs that use lexel's public API only (08,
// 09, 14): a camera over a floor with a box on it, lit by a point light, traced exactly. It hands
// lexel what a renderer would: the depth buffer of its camera pass with the matrix that made it,
// and per light a shadow mask of the readback (here exact, where a renderer would use a standard
// shadow map). Not part of lexel's API.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "lexel/spatial/bounds.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"

namespace lexel::notebooks {

class ToyRenderer {
  public:
    // The floor y = 0 over |x|, |z| ≤ 20, the box [-1, 1] × [0, 2] × [-1, 1], a camera at
    // (0, 1.7, 12) looking at the origin (60° vertical field of view) with `resolution` pixels,
    // and the point light at (10, 8, 6).
    explicit ToyRenderer(spatial::Resolution resolution);

    struct Hit {
        glm::dvec3 wsPoint, wsNormal;  // the nearest surface point and its unit normal
    };
    // What the camera sees through screen point xs (pixels, x² down), if anything.
    std::optional<Hit> Trace(glm::dvec2 xs) const;

    // The camera pass: window depth in [0, 1] per pixel (row 0 at the top, 1 where empty), made
    // with ScreenFromWorld().
    std::vector<float> DepthBuffer() const;
    glm::dmat4 ScreenFromWorld() const { return camera_.ScreenFromWorld(resolution_); }
    spatial::Resolution resolution() const { return resolution_; }
    const spatial::Camera& camera() const { return camera_; }
    glm::dvec3 wsLight() const { return {10.0, 8.0, 6.0}; }
    spatial::Bounds SceneBounds() const;  // floor and box

    // The renderer's shadow decision at every readback pixel: exact segment tests against the box.
    std::vector<spatial::Shade> ShadowMask(const spatial::Readback& readback) const;

  private:
    spatial::Resolution resolution_;
    spatial::Camera camera_;
    glm::dvec3 boxLo_{-1.0, 0.0, -1.0}, boxHi_{1.0, 2.0, 1.0};
    double floorHalf_ = 20.0;
};

}  // namespace lexel::notebooks
