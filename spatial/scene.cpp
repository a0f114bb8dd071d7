// Scene geometry helpers and the camera's matrices (report eq. 1).
#include "lexel/spatial/scene.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace lexel::spatial {

std::array<glm::dvec3, 8> Bounds::Corners() const {
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i)
        corners[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    return corners;
}

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

glm::dmat4 Camera::ViewFromWorld() const { return glm::lookAt(position, target, up); }

glm::dmat4 Camera::ClipFromView() const {
    const double aspect = static_cast<double>(resolution.width) / resolution.height;
    return glm::perspective(glm::radians(fovYDeg), aspect, nearPlane, farPlane);
}

glm::dmat4 Camera::ScreenFromWorld(Resolution at) const {
    // Viewport: NDC x ∈ [-1, 1] → [0, W]; NDC y ∈ [-1, 1] → [H, 0] (rows grow downwards);
    // NDC z ∈ [-1, 1] → [0, 1].
    glm::dmat4 screenFromNdc(1.0);
    screenFromNdc[0][0] = 0.5 * at.width;
    screenFromNdc[1][1] = -0.5 * at.height;
    screenFromNdc[2][2] = 0.5;
    screenFromNdc[3] = glm::dvec4(0.5 * at.width, 0.5 * at.height, 0.5, 1.0);
    return screenFromNdc * ClipFromView() * ViewFromWorld();
}

glm::dvec3 Camera::RayDirection(glm::dvec2 xs, Resolution at) const {
    const glm::dvec3 forward = glm::normalize(target - position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const glm::dvec3 trueUp = glm::cross(right, forward);
    const double tanHalf = std::tan(0.5 * glm::radians(fovYDeg));
    const double aspect = static_cast<double>(at.width) / at.height;
    const double ndcX = 2.0 * xs.x / at.width - 1.0;
    const double ndcY = 1.0 - 2.0 * xs.y / at.height;
    return forward + (ndcX * tanHalf * aspect) * right + (ndcY * tanHalf) * trueUp;
}

std::array<glm::dvec3, 8> Camera::FrustumCorners() const {
    std::array<glm::dvec3, 8> corners;
    const glm::dvec2 screen[4] = {{0.0, 0.0},
                                  {double(resolution.width), 0.0},
                                  {double(resolution.width), double(resolution.height)},
                                  {0.0, double(resolution.height)}};
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 dir = RayDirection(screen[i], resolution);
        corners[i] = position + nearPlane * dir;
        corners[i + 4] = position + farPlane * dir;
    }
    return corners;
}

}  // namespace lexel::spatial
