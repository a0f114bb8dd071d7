// Light space (Chong & Gortler, report §2.1): an orthonormal frame whose origin is the light, in
// which the light matrix P acts. A world point x becomes X = lsFromWs · [x; 1] (3-vector);
// the shadow-map coordinates are u^i = (p_i · X) / (p4 · X) for i = 1, 2 (report eq. 2, with the
// zeros of Fig. 1: P sends the light to infinity, so only X's direction matters to u).
//
// Directional lights (the report's footnote): the light is the point at infinity d, and P must
// annihilate it. Writing X = (e1·(x - o), e2·(x - o), s) with e1, e2 ⊥ d, o the scene centre and
// s a fixed length, every world point on a light ray has the same X, and the same formula
// u^i = (p_i·X)/(p4·X) gives exactly the light matrices that send d to infinity: p4 = (0, 0, 1) is
// an orthographic map, any other p4 a projective warp of it (as PSM-style methods use). So the
// optimizer, the fitters and the baselines treat both kinds alike.
//
// Depth is stored linearly and independently of P (the report's row 3 is free): the distance
// from a point light, or the distance along d for a directional one.
#pragma once

#include <glm/glm.hpp>

#include "lexel/spatial/bounds.h"

namespace lexel::spatial {

// A point light at `position`, or a directional light whose light travels along `direction`
// (world units; the direction need not be unit, LightSpace normalizes it).
struct Light {
    enum class Type { kPoint, kDirectional };
    Type type = Type::kPoint;
    glm::dvec3 position{0.0};
    glm::dvec3 direction{0.0, -1.0, 0.0};
};

class LightSpace {
  public:
    // Frames `light` so that X = (0, 0, +) points at the centre of `wsBounds`. Throws DomainError
    // when the bounds are empty, when a point light lies inside them ("a light inside the
    // geometry": no light matrix can see every relevant point), or when a directional light's
    // direction is zero or not finite.
    LightSpace(const Light& light, const Bounds& wsBounds);

    const Light& light() const { return light_; }
    bool IsPoint() const { return light_.type == Light::Type::kPoint; }

    // X for a world point.
    glm::dvec3 ToLight(const glm::dvec3& wsPoint) const;
    // ∂X/∂x: the 3×3 linear part (for a displacement of a world point; rows e1, e2, and e3 for a
    // point light, 0 for a directional one).
    glm::dmat3 LsFromWsLinear() const;
    // Linear depth: |x - light| for a point light, d·(x - o) + s for a directional one (> 0 over
    // the scene bounds).
    double Depth(const glm::dvec3& wsPoint) const;
    // The world ray of the points whose X is a positive multiple of lsX (lsX.z > 0 for a
    // directional light): origin (the light, or a point 2s before the scene along d) and unit
    // direction.
    void Ray(const glm::dvec3& lsX, glm::dvec3* wsOrigin, glm::dvec3* wsDirection) const;
    // The point on that ray at linear depth `depth`.
    glm::dvec3 PointAtDepth(const glm::dvec3& lsX, double depth) const;
    // Unit world direction from wsPoint towards the light (for facing tests and shadow rays).
    glm::dvec3 DirectionToLight(const glm::dvec3& wsPoint) const;
    // Distance from wsPoint to the light along that direction (+inf for a directional light).
    double DistanceToLight(const glm::dvec3& wsPoint) const;

  private:
    Light light_;
    glm::dvec3 e1_, e2_, e3_;  // world-space frame axes (rows of the rotation)
    glm::dvec3 origin_;        // world: the light (point) or the bounds centre (directional)
    double s_ = 1.0;           // directional: the fixed third coordinate, twice the bounds radius
};

}  // namespace lexel::spatial
