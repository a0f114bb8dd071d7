// Triangle meshes of the 3D harness.
#include "lexel/spatial/harness/scene.h"

#include <cmath>

namespace lexel::spatial {

void TriangleMesh::Append(const TriangleMesh& other) {
    const auto offset = static_cast<unsigned>(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    triangles.reserve(triangles.size() + other.triangles.size());
    for (const glm::uvec3& t : other.triangles) triangles.push_back(t + glm::uvec3(offset));
}

Bounds TriangleMesh::ComputeBounds() const {
    Bounds b;
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) b.Add(positions[t[k]]);
    return b;
}

glm::dvec3 TriangleMesh::FaceNormal(std::size_t t) const {
    const glm::uvec3 tri = triangles[t];
    const glm::dvec3 &a = positions[tri[0]], &b = positions[tri[1]], &c = positions[tri[2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

glm::dmat4 UnitFrame::WorldFromUnit() const {
    glm::dmat4 m(wsScale);
    m[3] = glm::dvec4(wsOrigin, 1.0);
    return m;
}

UnitFrame UnitFrameOf(const Bounds& wsBounds) {
    UnitFrame frame;
    if (wsBounds.Empty()) return frame;
    frame.wsOrigin = wsBounds.Center();
    const double radius = wsBounds.Radius();
    if (radius > 0.0 && std::isfinite(radius)) {
        int exponent = 0;
        const double mantissa = std::frexp(radius, &exponent);  // radius = m · 2^e, m ∈ [½, 1)
        frame.wsScale = std::ldexp(1.0, mantissa == 0.5 ? exponent - 1 : exponent);
    }
    return frame;
}

}  // namespace lexel::spatial
