// The geometry vocabulary every module shares: angle units, 2D cross product and perpendicular, 3D
// cross and dot for any scalar type (double or a Ceres Jet), an orthonormal basis of the plane
// normal to an axis, and the central projection onto the plane axis·X = 1 in that basis (the
// projection every light-matrix fit starts from: Chong & Gortler report §2.3, step 4b-ii).
//
// The templates evaluate in the same order as GLM's own functions, so for T = double they give
// GLM's results bit for bit.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>
#include <span>

namespace lexel {

// Throws std::invalid_argument "<what>: no points" or "<what>: point K is not finite".
void RequireFinitePoints(std::span<const Eigen::Vector2d> points, const char* what);

// Degrees ↔ radians, evaluated as x · π / 180 and x · 180 / π.
constexpr double Radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
constexpr double Degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// (a × b)_z of two plane vectors: positive when b is counter-clockwise of a.
inline double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}
inline double Cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// v turned by +90° (counter-clockwise).
inline Eigen::Vector2d Perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
inline glm::dvec2 Perp(const glm::dvec2& v) { return {-v.y, v.x}; }

// a · v and a × b for a scalar type T, with a and b three T's (as glm::dot and glm::cross).
template <typename T, typename V>
T Dot3(const T* a, const V& v) {
    return a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
}
template <typename T>
void Cross3(const T* a, const T* b, T* out) {
    out[0] = a[1] * b[2] - b[1] * a[2];
    out[1] = a[2] * b[0] - b[2] * a[0];
    out[2] = a[0] * b[1] - b[0] * a[1];
}

// The world axis least aligned with the unit `axis` (ties to the lower index): locally constant in
// the axis, so the basis below is smooth wherever the helper does not switch.
inline glm::dvec3 PlaneBasisHelper(const glm::dvec3& axis) {
    const glm::dvec3 a = glm::abs(axis);
    return (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1, 0, 0)
           : (a.y <= a.z)             ? glm::dvec3(0, 1, 0)
                                      : glm::dvec3(0, 0, 1);
}

// A right-handed orthonormal basis (b1, b2) of the plane ⊥ the unit `axis`: b1 = normalize(helper
// × axis), b2 = axis × b1, with `helper` = PlaneBasisHelper(axis) chosen in double (held fixed
// when T is a Jet, so the basis is differentiable in the axis).
template <typename T>
void PlaneBasis(const T* axis, const glm::dvec3& helper, T* b1, T* b2) {
    const T h[3] = {T(helper.x), T(helper.y), T(helper.z)};
    Cross3(h, axis, b1);
    using std::sqrt;
    const T inverseLength = T(1.0) / sqrt(Dot3(b1, b1));
    for (int c = 0; c < 3; ++c) b1[c] = b1[c] * inverseLength;
    Cross3(axis, b1, b2);
}
inline void PlaneBasis(const glm::dvec3& axis, glm::dvec3* b1, glm::dvec3* b2) {
    PlaneBasis(&axis[0], PlaneBasisHelper(axis), &(*b1)[0], &(*b2)[0]);
}

// The central projection of X onto the plane axis·X = 1, in the basis (b1, b2):
// y = (b1·X, b2·X) / (axis·X). X must be strictly in front (axis·X > 0).
template <typename T, typename V>
void ProjectToAxisPlane(const T* axis, const T* b1, const T* b2, const V& X, T* y) {
    const T w = Dot3(axis, X);
    y[0] = Dot3(b1, X) / w;
    y[1] = Dot3(b2, X) / w;
}
inline glm::dvec2 ProjectToAxisPlane(const glm::dvec3& axis, const glm::dvec3& b1,
                                     const glm::dvec3& b2, const glm::dvec3& X) {
    glm::dvec2 y;
    ProjectToAxisPlane(&axis[0], &b1[0], &b2[0], X, &y[0]);
    return y;
}

}  // namespace lexel
