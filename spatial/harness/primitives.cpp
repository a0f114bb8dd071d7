// Unit primitives and mesh transforms (see primitives.h).
#include "lexel/spatial/harness/primitives.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

namespace lexel::spatial {

glm::dmat4 Transform::Matrix() const {
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translate);
    // Right-multiplied, so the last factor applied here (Rx) acts first on a point.
    m = glm::rotate(m, glm::radians(rotateDeg.z), glm::dvec3(0.0, 0.0, 1.0));
    m = glm::rotate(m, glm::radians(rotateDeg.y), glm::dvec3(0.0, 1.0, 0.0));
    m = glm::rotate(m, glm::radians(rotateDeg.x), glm::dvec3(1.0, 0.0, 0.0));
    return glm::scale(m, scale);
}

TriangleMesh TransformMesh(const TriangleMesh& mesh, const glm::dmat4& wsFromOs) {
    TriangleMesh out;
    out.positions.reserve(mesh.positions.size());
    for (const glm::dvec3& osPoint : mesh.positions)
        out.positions.push_back(glm::dvec3(wsFromOs * glm::dvec4(osPoint, 1.0)));
    out.triangles = mesh.triangles;
    if (glm::determinant(glm::dmat3(wsFromOs)) < 0.0)
        for (glm::uvec3& t : out.triangles) std::swap(t[1], t[2]);
    return out;
}

TriangleMesh TransformMesh(const TriangleMesh& mesh, const Transform& t) {
    return TransformMesh(mesh, t.Matrix());
}

TriangleMesh MakePlane() {
    TriangleMesh mesh;
    // Counter-clockwise seen from +y: -z edge to +z edge on the left, then back on the right.
    mesh.positions = {{-0.5, 0.0, -0.5}, {-0.5, 0.0, 0.5}, {0.5, 0.0, 0.5}, {0.5, 0.0, -0.5}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return mesh;
}

TriangleMesh MakeBox() {
    TriangleMesh mesh;
    // Corner i has x, y, z = +0.5 where bit 0, 1, 2 of i is set.
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back(
            {(i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5});
    // Each face as a quad, counter-clockwise seen from outside.
    const unsigned quads[6][4] = {
        {0, 4, 6, 2},  // -x
        {1, 3, 7, 5},  // +x
        {0, 1, 5, 4},  // -y
        {2, 6, 7, 3},  // +y
        {0, 2, 3, 1},  // -z
        {4, 5, 7, 6},  // +z
    };
    for (const auto& q : quads) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
    }
    return mesh;
}

TriangleMesh MakeSphere(int slices, int stacks) {
    if (slices < 3 || stacks < 2)
        throw std::invalid_argument("MakeSphere: needs slices >= 3 and stacks >= 2, got " +
                                    std::to_string(slices) + ", " + std::to_string(stacks));
    TriangleMesh mesh;
    const double pi = std::numbers::pi;
    // Vertex 0 is the north pole (+y), then rings 1 .. stacks-1 from north to south, then the
    // south pole. Polar angle θ from +y, azimuth φ; p = (sinθ cosφ, cosθ, sinθ sinφ), for which
    // ∂p/∂φ × ∂p/∂θ points outward, so (ring i, j), (i, j+1), (i+1, j) is counter-clockwise.
    mesh.positions.push_back({0.0, 1.0, 0.0});
    for (int i = 1; i < stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * pi * j / slices;
            mesh.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                      std::sin(theta) * std::sin(phi)});
        }
    }
    const unsigned south = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.push_back({0.0, -1.0, 0.0});

    auto ring = [slices](int i, int j) {
        return static_cast<unsigned>(1 + (i - 1) * slices + (j % slices));
    };
    for (int j = 0; j < slices; ++j) {
        mesh.triangles.push_back({0u, ring(1, j + 1), ring(1, j)});
        for (int i = 1; i + 1 < stacks; ++i) {
            mesh.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j)});
            mesh.triangles.push_back({ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j)});
        }
        mesh.triangles.push_back({ring(stacks - 1, j), ring(stacks - 1, j + 1), south});
    }
    return mesh;
}

TriangleMesh MakeCylinder(int slices) {
    if (slices < 3)
        throw std::invalid_argument("MakeCylinder: needs slices >= 3, got " +
                                    std::to_string(slices));
    TriangleMesh mesh;
    const double pi = std::numbers::pi;
    // Top ring 0 .. n-1, bottom ring n .. 2n-1, then the top and bottom cap centres.
    for (double y : {0.5, -0.5})
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * pi * j / slices;
            mesh.positions.push_back({std::cos(phi), y, std::sin(phi)});
        }
    const unsigned n = static_cast<unsigned>(slices);
    const unsigned topCentre = 2 * n, bottomCentre = 2 * n + 1;
    mesh.positions.push_back({0.0, 0.5, 0.0});
    mesh.positions.push_back({0.0, -0.5, 0.0});
    for (unsigned j = 0; j < n; ++j) {
        const unsigned k = (j + 1) % n;
        // Side: same orientation argument as the sphere (top ring plays θ small).
        mesh.triangles.push_back({j, k, n + j});
        mesh.triangles.push_back({k, n + k, n + j});
        mesh.triangles.push_back({topCentre, k, j});
        mesh.triangles.push_back({bottomCentre, n + j, n + k});
    }
    return mesh;
}

double SignedVolume(const TriangleMesh& mesh) {
    double sixVolume = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                         &c = mesh.positions[t[2]];
        sixVolume += glm::dot(a, glm::cross(b, c));
    }
    return sixVolume / 6.0;
}

}  // namespace lexel::spatial
