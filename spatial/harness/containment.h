// Whether a point lies inside closed geometry: the even-odd (Jordan) rule for a triangle soup, by
// the parity of a ray's crossings (Haines, "Point in Polygon Strategies", Graphics Gems IV, 1994,
// carried to 3D), with the nearest crossing's facing as a second witness. Used to refuse a camera
// shut inside a closed mesh, which sees only the inside of its walls: no light outside reaches it.
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <span>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// What the ray wsOrigin + t·wsDirection (t > 0) crosses in a triangle soup (Möller–Trumbore in
// double on the float vertices; degenerate triangles and triangles parallel to the ray cross
// nothing): how many triangles, and whether the nearest one is a back face (its counter-clockwise
// normal points along the ray, i.e. the ray leaves through it).
struct RayCrossings {
    int count = 0;
    double nearestT = std::numeric_limits<double>::infinity();
    bool nearestIsBackFace = false;
};
// `triangles` index wsMesh.positions (a part of wsMesh.triangles: one object of a merged scene).
RayCrossings CastThrough(const TriangleMesh& wsMesh, std::span<const glm::uvec3> triangles,
                         const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection);

// True when rays from wsPoint in three fixed, non-axis directions each cross the mesh an odd
// number of times and each leaves through a back face first: wsPoint is enclosed by an outward-
// wound closed surface (the primitives' and TransformMesh's winding). Asking three rays to agree
// keeps a ray through a shared edge or vertex (counted twice or not at all) from deciding alone;
// the back-face witness keeps a point between open sheets (a floor and a ceiling plane, each
// crossed once) outside. Test one closed object at a time (`triangles`, a part of
// wsMesh.triangles): a box standing on a floor shares its bottom's plane with the floor, and a
// ray through both would count two crossings. Costs 3 · triangles ray-triangle tests.
bool InsideClosedGeometry(const TriangleMesh& wsMesh, std::span<const glm::uvec3> triangles,
                          const glm::dvec3& wsPoint);

}  // namespace lexel::spatial
