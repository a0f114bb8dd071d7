// Clipping convex polyhedra by planes and convex polygons by convex polygons: the bodies and
// regions the focused and warping shadow-map baselines fit their maps to (Wimmer et al.'s
// LiSPSM "body", EGSR 2004; the frustum-limiting step of Chong & Gortler report §3;
// Sutherland–Hodgman, CACM 17(1), 1974).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lexel {

// A convex polyhedron as its faces, each a planar convex polygon (orientation irrelevant).
struct ConvexPolyhedron {
    std::vector<std::vector<glm::dvec3>> faces;
    std::vector<glm::dvec3> Vertices() const;  // with repeats (each vertex once per face)
};

// The frustum (or box) with corners 0-3 on the near face and 4-7 on the far face, in the same
// winding (Camera::FrustumCorners' layout).
ConvexPolyhedron FrustumPolyhedron(const std::array<glm::dvec3, 8>& corners);
// The part with plane.xyz · x + plane.w ≥ 0, capped by a face on the plane; empty (no faces)
// when nothing is left.
ConvexPolyhedron ClipPolyhedron(const ConvexPolyhedron& polyhedron, const glm::dvec4& plane);
// The part inside the axis-aligned box [lo, hi].
ConvexPolyhedron ClipToBox(const ConvexPolyhedron& polyhedron, const glm::dvec3& lo,
                           const glm::dvec3& hi);

// subject ∩ clip for two counter-clockwise convex polygons (Sutherland–Hodgman: clip the subject
// by each edge's left half-plane in turn). Empty when they do not overlap; a clip polygon with
// fewer than 3 vertices gives an empty result.
std::vector<glm::dvec2> IntersectConvexPolygons(std::span<const glm::dvec2> subject,
                                                std::span<const glm::dvec2> clip);

}  // namespace lexel
