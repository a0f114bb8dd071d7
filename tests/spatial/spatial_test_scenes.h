// Small analytic scenes for the spatial tests: the unit primitives placed by corners and sizes,
// and an exact segment–box test for analytic shadows.
#pragma once

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial::testing {

// A 180² camera at (0.5, 1.7, 9) looking at (0, 0.5, 0): the readback of the test scenes.
Camera ReadbackCamera();
// The square [-h, h]² at y = 0, normal +y.
TriangleMesh FloorQuad(double halfSize);
// The axis-aligned box [lo, hi], outward triangles.
TriangleMesh BoxMesh(const glm::dvec3& lo, const glm::dvec3& hi);
// Algorithm 1 step 1 with a plain standard map: boundary samples of the light from a shadow map
// with axis (0, 0, 1) fitted to the corners of `wsBounds`, `mapSize` texels.
LightSamples SamplesFromBoundsMap(const RenderBackend& renderer, const Readback& readback,
                                  const LightSpace& lightSpace, const Bounds& wsBounds,
                                  Resolution mapSize);
// The embedding example's scene (spatial/README.md, tests/install/consumer,
// notebook 14): the floor |x|, |z| ≤ 20 at y = 0 and the box [-1, 1] × [0, 2] × [-1, 1], seen
// by a 160×120 camera at (0, 1.7, 12) looking at the origin (60° vertical field of view).
struct FloorAndBox {
    TriangleMesh mesh;
    Camera camera;
    Bounds wsBounds;
    glm::dvec3 boxLo{-1.0, 0.0, -1.0}, boxHi{1.0, 2.0, 1.0};
};
FloorAndBox EmbeddingScene();
// Whether the open segment a → b crosses the box [lo, hi] (slab test).
bool SegmentHitsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                    const glm::dvec3& hi);

}  // namespace lexel::spatial::testing
