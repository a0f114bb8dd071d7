#include "spatial/spatial_test_scenes.h"

#include <algorithm>

namespace lexel::spatial::testing {

TriangleMesh FloorQuad(double h) {
    TriangleMesh m;
    const float f = static_cast<float>(h);
    m.positions = {{-f, 0, -f}, {f, 0, -f}, {f, 0, f}, {-f, 0, f}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}};  // counter-clockwise seen from +y
    return m;
}

TriangleMesh BoxMesh(const glm::dvec3& lo, const glm::dvec3& hi) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                 (i & 4) ? hi.z : lo.z);
    // Faces as quads (a, b, c, d) counter-clockwise seen from outside.
    const unsigned quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                  {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
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
