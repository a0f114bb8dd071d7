// Triangle meshes of the 3D harness.
#include "lexel/spatial/harness/scene.h"

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
        for (int k = 0; k < 3; ++k) b.Add(glm::dvec3(positions[t[k]]));
    return b;
}

glm::dvec3 TriangleMesh::FaceNormal(std::size_t t) const {
    const glm::uvec3 tri = triangles[t];
    const glm::dvec3 a(positions[tri[0]]), b(positions[tri[1]]), c(positions[tri[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

}  // namespace lexel::spatial
