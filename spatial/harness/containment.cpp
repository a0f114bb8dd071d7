#include "lexel/spatial/harness/containment.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lexel::spatial {

namespace {

// Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection": the ray parameter t
// where the ray meets the triangle inside or on its edges, or 0 for no crossing at t > 0. `det` =
// e1 · (d × e2) = −d · (e1 × e2): negative when the ray runs along the counter-clockwise normal.
double CrossingT(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& p0,
                 const glm::dvec3& p1, const glm::dvec3& p2, double* det) {
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
    const glm::dvec3 pvec = glm::cross(direction, e2);
    *det = glm::dot(e1, pvec);
    if (*det == 0.0) return 0.0;  // parallel to the plane, or degenerate
    const double invDet = 1.0 / *det;
    const glm::dvec3 tvec = origin - p0;
    const double u = glm::dot(tvec, pvec) * invDet;
    if (u < 0.0 || u > 1.0) return 0.0;
    const glm::dvec3 qvec = glm::cross(tvec, e1);
    const double v = glm::dot(direction, qvec) * invDet;
    if (v < 0.0 || u + v > 1.0) return 0.0;
    return std::max(0.0, glm::dot(e2, qvec) * invDet);
}

}  // namespace

RayCrossings CastThrough(const TriangleMesh& wsMesh, std::span<const glm::uvec3> triangles,
                         const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection) {
    RayCrossings out;
    for (const glm::uvec3& tri : triangles) {
        double det = 0.0;
        const double t = CrossingT(wsOrigin, wsDirection, glm::dvec3(wsMesh.positions[tri.x]),
                                   glm::dvec3(wsMesh.positions[tri.y]),
                                   glm::dvec3(wsMesh.positions[tri.z]), &det);
        if (!(t > 0.0)) continue;
        ++out.count;
        if (t < out.nearestT) {
            out.nearestT = t;
            out.nearestIsBackFace = det < 0.0;
        }
    }
    return out;
}

bool InsideClosedGeometry(const TriangleMesh& wsMesh, std::span<const glm::uvec3> triangles,
                          const glm::dvec3& wsPoint) {
    // Unit directions with irrational-looking components: no axis, no primitive's edge direction.
    static const std::array<glm::dvec3, 3> kDirections = {
        glm::normalize(glm::dvec3(0.5377, 0.8324, 0.1347)),
        glm::normalize(glm::dvec3(-0.7071, -0.3137, 0.6337)),
        glm::normalize(glm::dvec3(0.2113, -0.5921, -0.7775)),
    };
    for (const glm::dvec3& wsDirection : kDirections) {
        const RayCrossings crossings = CastThrough(wsMesh, triangles, wsPoint, wsDirection);
        if (crossings.count % 2 == 0 || !crossings.nearestIsBackFace) return false;
    }
    return true;
}

}  // namespace lexel::spatial
