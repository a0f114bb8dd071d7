#include "spatial/spatial_test_scenes.h"

#include <algorithm>

#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/light_matrix.h"

namespace lexel::spatial::testing {

Camera ReadbackCamera() {
    Camera c;
    c.position = {0.5, 1.7, 9.0};
    c.target = {0.0, 0.5, 0.0};
    c.resolution = {180, 180};
    return c;
}

FloorAndBox EmbeddingScene() {
    FloorAndBox s;
    s.mesh = FloorQuad(20.0);
    s.mesh.Append(BoxMesh(s.boxLo, s.boxHi));
    s.camera.position = {0.0, 1.7, 12.0};
    s.camera.target = {0.0, 0.0, 0.0};
    s.camera.resolution = {160, 120};
    s.wsBounds = s.mesh.ComputeBounds();
    return s;
}

TriangleMesh FloorQuad(double h) {
    Transform t;
    t.scale = {2.0 * h, 1.0, 2.0 * h};
    return TransformMesh(MakePlane(), t);
}

LightSamples SamplesFromBoundsMap(const RenderBackend& renderer, const Readback& readback,
                                  const LightSpace& lightSpace, const Bounds& wsBounds,
                                  Resolution mapSize) {
    std::vector<glm::dvec3> lsCorners;
    for (const glm::dvec3& c : wsBounds.Corners()) lsCorners.push_back(lightSpace.ToLight(c));
    const ShadowMap map = renderer.RenderShadowMap(
        lightSpace, *FitMapToPoints({0, 0, 1}, lsCorners, mapSize), mapSize);
    return MakeLightSamples(readback, lightSpace,
                            renderer.ShadePixels(readback.buffer, lightSpace, map));
}

TriangleMesh BoxMesh(const glm::dvec3& lo, const glm::dvec3& hi) {
    Transform t;
    t.translate = 0.5 * (lo + hi);
    t.scale = hi - lo;
    return TransformMesh(MakeBox(), t);
}

bool SegmentHitsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo,
                    const glm::dvec3& hi) {
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec3 d = b - a;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (a[k] <= lo[k] || a[k] >= hi[k]) return false;
            continue;
        }
        double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 < t1;
}

}  // namespace lexel::spatial::testing
