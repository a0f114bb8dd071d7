// Unit primitives (plane, box, sphere, cylinder) and affine placement of triangle meshes, the
// building blocks of the 3D case files (cases/README.md) and of the floor-objects scene of
// Chong & Gortler's experiment (report §3: "a few dozen objects on or near a floor").
//
// Every primitive is a closed, outward-facing mesh with counter-clockwise winding seen from
// outside (TriangleMesh::FaceNormal points out), except the plane, which is one-sided with normal
// +y. Closed primitives share their vertices, so every edge is used by exactly two triangles.
#pragma once

#include <glm/glm.hpp>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// Scale, then rotate, then translate: Matrix() = T · Rz · Ry · Rx · S. The rotation turns about the
// fixed world axes, X first, then Y, then Z (equivalently intrinsic Z, Y′, X″), by the angles of
// rotateDeg in degrees, counter-clockwise looking down each axis towards the origin (right hand).
struct Transform {
    glm::dvec3 translate{0.0};
    glm::dvec3 rotateDeg{0.0};
    glm::dvec3 scale{1.0};

    glm::dmat4 Matrix() const;
};

// Applies t to every position. A mirroring transform (negative determinant) also reverses each
// triangle's winding, so outward faces stay outward.
TriangleMesh TransformMesh(const TriangleMesh& mesh, const Transform& t);
TriangleMesh TransformMesh(const TriangleMesh& mesh, const glm::dmat4& wsFromOs);

// The square [-0.5, 0.5]² in the plane y = 0, normal +y (2 triangles); `scale` sets its size.
TriangleMesh MakePlane();
// The unit cube [-0.5, 0.5]³ (8 vertices, 12 triangles).
TriangleMesh MakeBox();
// The unit sphere as a UV sphere inscribed in it: `slices` ≥ 3 meridians, `stacks` ≥ 2 bands,
// one vertex at each pole; 2·slices·(stacks − 1) triangles.
TriangleMesh MakeSphere(int slices = 32, int stacks = 16);
// The capped cylinder of radius 1 around the y axis, y ∈ [-0.5, 0.5]: `slices` ≥ 3 sides, each cap
// a fan around its centre; 4·slices triangles.
TriangleMesh MakeCylinder(int slices = 32);

// Signed volume enclosed by a closed mesh, Σ a·(b × c) / 6 (divergence theorem); positive when the
// faces point outward.
double SignedVolume(const TriangleMesh& mesh);

}  // namespace lexel::spatial
