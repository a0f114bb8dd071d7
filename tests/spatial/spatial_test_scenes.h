// Small analytic scenes for the spatial tests: the unit primitives placed by corners and sizes,
// and an exact segment–box test for analytic shadows.
#pragma once

#include "spatial/scene.h"

namespace lexel::spatial::testing {

// The square [-h, h]² at y = 0, normal +y.
TriangleMesh FloorQuad(double halfSize);
// The axis-aligned box [lo, hi], outward triangles.
TriangleMesh BoxMesh(const glm::dvec3& lo, const glm::dvec3& hi);
// Whether the open segment a → b crosses the box [lo, hi] (slab test).
bool SegmentHitsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                    const glm::dvec3& hi);

}  // namespace lexel::spatial::testing
