// The energy h(P) of Chong & Gortler eq. (6) as templated code, and its gradient with respect to
// the optical axis p4 (report Appendix A) computed twice: in closed form, and by Ceres automatic
// differentiation (Jets) through the same template that evaluates h.
//
// Per sample, with X the light-space point, D_j = ∂X/∂x^j (j = 1, 2) from the readback, and the
// affine rows p1, p2 held fixed (Algorithm 1 step 4a differentiates P's fourth row only):
//     w = p4·X,   u^i = p_i·X / w,
//     J_ij = ∂u^i/∂x^j = (p_i·D_j)/w - (p_i·X)(p4·D_j)/w²                       (Appendix A, eq. 9)
//     f = ||J⁻¹||_F² = (J11² + J12² + J21² + J22²) / det(J)²                     (eq. 10)
// and, differentiating J_ij in p4,
//     ∂J_ij/∂p4 = -(p_i·D_j) X/w² - (p_i·X) D_j/w² + 2 (p_i·X)(p4·D_j) X/w³      (eq. 11)
//     ∂f/∂J11 = 2 J11/det² - 2 S J22/det³,  ∂f/∂J12 = 2 J12/det² + 2 S J21/det³,
//     ∂f/∂J21 = 2 J21/det² + 2 S J12/det³,  ∂f/∂J22 = 2 J22/det² - 2 S J11/det³   (S = Σ J_ij²).
//
// The edge energy's summand (energy.h), Appendix A generalized. With n the unit normal of the
// shadow edge at the sample in readback pixels, the edge's normal in the map is m ∝ J⁻ᵀn; a
// texel offset δ (texels) of the quantized edge along m moves it by the pixels δx = J⁻¹ m δ/|m|,
// across itself by nᵀδx = δ (nᵀJ⁻¹J⁻ᵀn)/|J⁻ᵀn| = δ ||nᵀJ⁻¹|| (δ uniform on [-½, ½]: a band of
// ||nᵀJ⁻¹||/4 pixels per pixel of edge on average). With adj(J) = [[J22, -J12], [-J21, J11]]
// and J⁻¹ = adj(J)/det,
//     a = n1 J22 - n2 J21,   b = n2 J11 - n1 J12        ((a, b) = nᵀ adj(J))
//     q = a² + b²,   f_e = ||nᵀJ⁻¹||₂ = sqrt(q) / |det| = sqrt(q / det²)
// and where n is undefined (0: no edge direction at the sample, or a prior point) the root mean
// square of ||nᵀJ⁻¹|| over unit n uniform on the circle, since E[nnᵀ] = I/2:
//     q = S/2,   f_e = ||J⁻¹||_F / √2.
// Differentiating, with ∂det/∂J = cof(J) = [[J22, -J21], [-J12, J11]],
//     ∂f_e/∂J_ij = (∂q/∂J_ij) / (2 sqrt(q) |det|) - f_e cof_ij / det,
//     ∂q/∂J = [[2 b n2, -2 b n1], [-2 a n2, 2 a n1]]   (n defined),   ∂q/∂J = J  (q = S/2),
// then ∂f_e/∂p4 = Σ_ij ∂f_e/∂J_ij ∂J_ij/∂p4 with eq. (11), factored as in
// EnergyGradientAnalytic. The norm is not squared, so f_e is not differentiable where
// nᵀJ⁻¹ = 0; but nᵀ adj(J) = 0 with n ≠ 0 needs det(adj J) = det J = 0, where f_e is already
// +inf (0/0 or q/0, as h): at every finite f_e, q > 0 and the formula holds. Should rounding
// still give q = 0 with det ≠ 0, f_e = 0 is the norm's minimum and 0 is a subgradient there:
// both the closed form and the template return a zero derivative.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <span>

#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// J = ∂u/∂x of one sample (Appendix A, eq. 9) and det J, for rows p1, p2 (R) and axis p4 (T),
// each a pointer to 3 scalars: what SampleEnergy and SampleEdgeEnergy take the norm of.
template <typename T>
struct SampleJ {
    T j11, j12, j21, j22, det;
};
template <typename R, typename T>
SampleJ<T> SampleJacobianOf(const R* p1, const R* p2, const T* p4, const glm::dvec3& lsX,
                            const glm::dvec3& dXdx1, const glm::dvec3& dXdx2) {
    const auto dot = [](const auto* p, const glm::dvec3& v) {
        return p[0] * v.x + p[1] * v.y + p[2] * v.z;
    };
    const T w = dot(p4, lsX);
    const T wD1 = dot(p4, dXdx1);
    const T wD2 = dot(p4, dXdx2);
    const R a1 = dot(p1, lsX), a2 = dot(p2, lsX);
    const T invW = T(1.0) / w;
    const T j11 = (dot(p1, dXdx1) - a1 * wD1 * invW) * invW;
    const T j12 = (dot(p1, dXdx2) - a1 * wD2 * invW) * invW;
    const T j21 = (dot(p2, dXdx1) - a2 * wD1 * invW) * invW;
    const T j22 = (dot(p2, dXdx2) - a2 * wD2 * invW) * invW;
    const T det = j11 * j22 - j12 * j21;
    return {j11, j12, j21, j22, det};
}

// The eighths 8p of an exponent p that BandPower takes by square roots: p a multiple of 1/8 up to
// 4 (the case key's most, kMaxEdgeExponent in the case loader), else 0 (std::pow's branch).
inline int EdgeExponentEighths(double exponent) {
    const double eighths = 8.0 * exponent;
    return eighths == std::floor(eighths) && eighths >= 1.0 && eighths <= 32.0
               ? static_cast<int>(eighths)
               : 0;
}

// s^(p/2) for s = ||nᵀJ⁻¹||² > 0: the band to the power p. √s for p = 1; for p a multiple of 1/8
// (EdgeExponentEighths: the default 5/8) (s^(1/16))^(8p), s^(1/16) as four square roots, which
// need no library call (the search on e took 1.43–1.46× e₁'s with them against 1.53× with
// std::pow: spatial_bench MultiStartEdge, runs beside a sweep) and, for the small p lexel uses,
// are within a few ulp of std::pow (the error grows with the 8p − 1 products); std::pow
// otherwise. T is
// double or a Ceres Jet.
template <typename T>
T BandPower(const T& s, double exponent) {
    using std::pow;
    using std::sqrt;
    if (exponent == 1.0) return sqrt(s);
    if (const int eighths = EdgeExponentEighths(exponent)) {
        const T r = sqrt(sqrt(sqrt(sqrt(s))));
        T power = r;
        for (int k = 1; k < eighths; ++k) power = power * r;
        return power;
    }
    return pow(s, 0.5 * exponent);
}

// ||J⁻¹||_F² of one sample for rows p1, p2 (R) and axis p4 (T), each a pointer to 3 scalars.
// R and T are double or a Ceres Jet: the gradient differentiates p4 alone (R = double), the
// refinement also the re-fitted rows (R = T).
template <typename R, typename T>
T SampleEnergy(const R* p1, const R* p2, const T* p4, const glm::dvec3& lsX,
               const glm::dvec3& dXdx1, const glm::dvec3& dXdx2) {
    const auto [j11, j12, j21, j22, det] = SampleJacobianOf(p1, p2, p4, lsX, dXdx1, dXdx2);
    return (j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22) / (det * det);
}

// ||nᵀJ⁻¹||₂ of one sample (the header comment's f_e), or ||J⁻¹||_F/√2 where `edgeNormal` is
// (0, 0), raised to `exponent` (energy.h, EnergyOptions::exponent; 1: the norm itself, by the
// square root as before). Types as SampleEnergy. +inf or NaN where J is singular (the caller maps
// NaN to +inf).
template <typename R, typename T>
T SampleEdgeEnergy(const R* p1, const R* p2, const T* p4, const glm::dvec3& lsX,
                   const glm::dvec3& dXdx1, const glm::dvec3& dXdx2, const glm::dvec2& edgeNormal,
                   double exponent = 1.0) {
    const auto [j11, j12, j21, j22, det] = SampleJacobianOf(p1, p2, p4, lsX, dXdx1, dXdx2);
    T q;
    if (edgeNormal.x == 0.0 && edgeNormal.y == 0.0) {
        q = T(0.5) * (j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22);
    } else {
        const T a = edgeNormal.x * j22 - edgeNormal.y * j21;
        const T b = edgeNormal.y * j11 - edgeNormal.x * j12;
        q = a * a + b * b;
    }
    if (!(q > T(0.0))) return q / (det * det);  // 0 with a zero derivative (or NaN: singular)
    return BandPower(q / (det * det), exponent);
}

// ∂h/∂p4 in closed form (eq. 10–11), p1 and p2 fixed. Samples behind the plane or with a
// singular J contribute nothing (their energy is +inf for every nearby p4).
glm::dvec3 EnergyGradientAnalytic(const LightMatrix& matrix, const LightSamples& samples);

// The same by Ceres Jets through SampleEnergy.
glm::dvec3 EnergyGradientJets(const LightMatrix& matrix, const LightSamples& samples);

// Points with derivatives and, per point, an edge normal ((0, 0): none) and a weight: the
// boundary samples, or the prior's points (energy.h), as the edge gradients take them.
struct WeightedPoints {
    std::span<const glm::dvec3> lsX, dXdx1, dXdx2;
    std::span<const glm::dvec2> edgeNormal;  // empty: none for every point
    double weight = 1.0;                     // every summand is multiplied by it
    double exponent = 1.0;                   // each summand is f_e^exponent (energy.h)
};

// Σ weight · ∂(f_e^exponent)/∂p4 over the points in closed form (the header comment, times
// exponent · f_e^(exponent − 1) by the chain rule), p1 and p2 fixed. Points behind the plane or
// with a non-finite f_e contribute nothing.
glm::dvec3 EdgeEnergyGradientAnalytic(const LightMatrix& matrix, const WeightedPoints& points);

// The same by Ceres Jets through SampleEdgeEnergy.
glm::dvec3 EdgeEnergyGradientJets(const LightMatrix& matrix, const WeightedPoints& points);

}  // namespace lexel::spatial
