#include "lexel/spatial/perspective_aliasing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lexel/spatial/cascades.h"

namespace lexel::spatial {

// ∂u/∂x on the plane ⊥ the ray: the rows ∂u^i/∂X (LightMatrix::MapJacobian) times ∂X/∂x
// (LightSpace::LsFromWsLinear) applied to a unit basis (e1, e2) of that plane give the 2×2
// J_l in texels per world unit. The texel's beam cross-section is J_l⁻¹, whose largest singular
// value is σ_max(J_l) / |det J_l| (σ_min σ_max = |det|), with σ_max² = (T + √(T² − 4 det²)) / 2,
// T = ‖J_l‖_F²: no cancellation for the small singular value.
double PerspectiveAliasingOfRows(const Camera& camera, const LightSpace& lightSpace,
                                 const glm::dvec3& du1dX, const glm::dvec3& du2dX,
                                 const glm::dvec3& wsPoint) {
    const glm::dvec3 wsRay = -lightSpace.DirectionToLight(wsPoint);
    const glm::dvec3 helper =
        std::abs(wsRay.x) < 0.5 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 wsE1 = glm::normalize(glm::cross(wsRay, helper));
    const glm::dvec3 wsE2 = glm::cross(wsRay, wsE1);
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    const glm::dvec3 lsE1 = lsFromWs * wsE1, lsE2 = lsFromWs * wsE2;
    const double a = glm::dot(du1dX, lsE1), b = glm::dot(du1dX, lsE2);
    const double c = glm::dot(du2dX, lsE1), d = glm::dot(du2dX, lsE2);
    const double det = std::abs(a * d - b * c);
    if (!(det > 0.0)) return std::numeric_limits<double>::infinity();
    const double frobenius2 = a * a + b * b + c * c + d * d;
    const double sigmaMax = std::sqrt(
        0.5 * (frobenius2 + std::sqrt(std::max(0.0, frobenius2 * frobenius2 - 4.0 * det * det))));
    const double wsTexelWidth = sigmaMax / det;
    // Eq. 2 per pixel: the image beam's width at planar depth z.
    const double wsPixelWidth = 2.0 * std::tan(glm::radians(camera.fovYDeg) / 2.0) *
                                PlanarEyeDepth(camera, wsPoint) / camera.resolution.height;
    return wsTexelWidth / wsPixelWidth;
}

double PerspectiveAliasing(const Camera& camera, const LightSpace& lightSpace,
                           const LightMatrix& matrix, const glm::dvec3& wsPoint) {
    const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
    if (!InFront(matrix.p4, lsX)) return std::numeric_limits<double>::infinity();
    glm::dvec3 du1dX, du2dX;
    matrix.MapJacobian(lsX, &du1dX, &du2dX);
    return PerspectiveAliasingOfRows(camera, lightSpace, du1dX, du2dX, wsPoint);
}

}  // namespace lexel::spatial
