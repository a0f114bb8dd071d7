// Small analytic scenes for the spatial tests, built inline so that the renderer's tests do not
// depend on the primitive and mesh loaders.
#pragma once

#include "spatial/scene.h"

namespace lexel::spatial::testing {

// The square [-h, h]² at y = 0 as two triangles, normal +y.
TriangleMesh FloorQuad(double halfSize);
// The axis-aligned box [lo, hi] as 12 outward triangles.
TriangleMesh BoxMesh(const glm::dvec3& lo, const glm::dvec3& hi);
// Whether the open segment a → b crosses the box [lo, hi] (slab test).
bool SegmentHitsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                    const glm::dvec3& hi);

}  // namespace lexel::spatial::testing
