// The error model at a boundary sample (error_model.h, where the derivation is).
#include "lexel/spatial/error_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lexel::spatial {

glm::dvec2 EdgeNormalInTexels(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2) {
    // J = [a b; c d] (rows), J⁻¹ = [d −b; −c a] / det; g = n̂ᵀJ⁻¹.
    const double det = jRow1.x * jRow2.y - jRow1.y * jRow2.x;
    const double inf = std::numeric_limits<double>::infinity();
    if (!std::isfinite(det) || det == 0.0) return {inf, inf};
    return glm::dvec2(normal.x * jRow2.y - normal.y * jRow2.x,
                      -normal.x * jRow1.y + normal.y * jRow1.x) /
           det;
}

double ExpectedBandWidth(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2) {
    if (normal == glm::dvec2(0.0)) return 0.0;
    const glm::dvec2 g = EdgeNormalInTexels(normal, jRow1, jRow2);
    const double a = std::max(std::abs(g.x), std::abs(g.y));
    const double b = std::min(std::abs(g.x), std::abs(g.y));
    if (!std::isfinite(a)) return std::numeric_limits<double>::infinity();
    if (a == 0.0) return 0.0;
    return a / 4.0 + b * b / (12.0 * a);
}

double ExpectedBandWidthIsotropic(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2) {
    if (normal == glm::dvec2(0.0)) return 0.0;
    const glm::dvec2 g = EdgeNormalInTexels(normal, jRow1, jRow2);
    if (!std::isfinite(g.x) || !std::isfinite(g.y)) return std::numeric_limits<double>::infinity();
    return glm::length(g) / 4.0;
}

double EdgeLengthPerBoundaryPixel(glm::dvec2 normal) {
    const double l1 = std::abs(normal.x) + std::abs(normal.y);
    return l1 > 0.0 ? 1.0 / (2.0 * l1) : 0.0;
}

double FramePixelsFromReadbackArea(double readbackArea, Resolution readback, Resolution frame) {
    if (readback.Count() == 0) return 0.0;
    return readbackArea * static_cast<double>(frame.Count()) /
           static_cast<double>(readback.Count());
}

}  // namespace lexel::spatial
