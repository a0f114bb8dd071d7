#include "lexel/spatial/gl/visibility.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace lexel::spatial::gl {

CameraBuffer CameraBufferFromTriangles(const TriangleMesh& geometry, const Camera& camera,
                                       Resolution resolution,
                                       std::span<const std::int32_t> triangle) {
    const std::size_t n = resolution.Count();
    if (triangle.size() != n)
        throw std::invalid_argument(
            "CameraBufferFromTriangles: " + std::to_string(triangle.size()) + " ids for " +
            std::to_string(n) + " pixels");
    const auto triangles = static_cast<std::int64_t>(geometry.triangles.size());
    for (const std::int32_t t : triangle)
        if (t >= triangles)
            throw std::invalid_argument("CameraBufferFromTriangles: triangle id " +
                                        std::to_string(t) + " out of range");
    CameraBuffer out;
    out.resolution = resolution;
    out.windowDepth.assign(n, 1.0);
    out.wsPosition.assign(n, glm::dvec3(0.0));
    out.wsNormal.assign(n, glm::dvec3(0.0));
    out.triangle.assign(triangle.begin(), triangle.end());
    // Q·[x; 1] = Q_eye·[x − eye; 1], with Q_eye the same camera moved to the origin (as the CPU
    // renderer computes it): the window depth without the large translation whose cancellation
    // would cost it digits in a scene far from the origin.
    Camera eyeCentred = camera;
    eyeCentred.target = camera.target - camera.position;
    eyeCentred.position = glm::dvec3(0.0);
    const glm::dmat4 screenFromEye = eyeCentred.ScreenFromWorld(resolution);
    const glm::dvec3 wsEye = camera.position;
    tbb::parallel_for(0, resolution.height, [&](int y) {
        for (int x = 0; x < resolution.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * resolution.width + x;
            const std::int32_t t = triangle[i];
            if (t < 0) continue;
            glm::dvec3 n = geometry.FaceNormal(static_cast<std::size_t>(t));
            const glm::dvec3 v0(geometry.positions[geometry.triangles[t][0]]);
            const glm::dvec3 direction = camera.RayDirection({x + 0.5, y + 0.5}, resolution);
            const double s = glm::dot(n, v0 - wsEye) / glm::dot(n, direction);
            if (!(s > 0.0) || !std::isfinite(s)) {  // edge-on (0/0, x/0) or behind the eye
                out.triangle[i] = -1;
                continue;
            }
            const glm::dvec3 ws = wsEye + s * direction;
            const glm::dvec4 h = screenFromEye * glm::dvec4(s * direction, 1.0);
            out.wsPosition[i] = ws;
            out.windowDepth[i] = h.z / h.w;
            if (glm::dot(n, wsEye - ws) < 0.0) n = -n;
            out.wsNormal[i] = n;
        }
    });
    return out;
}

}  // namespace lexel::spatial::gl
