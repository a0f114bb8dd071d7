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
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// ||J⁻¹||_F² of one sample for rows p1, p2 (R) and axis p4 (T), each a pointer to 3 scalars.
// R and T are double or a Ceres Jet: the gradient differentiates p4 alone (R = double), the
// refinement also the re-fitted rows (R = T).
template <typename R, typename T>
T SampleEnergy(const R* p1, const R* p2, const T* p4, const glm::dvec3& lsX,
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
    return (j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22) / (det * det);
}

// ∂h/∂p4 in closed form (eq. 10–11), p1 and p2 fixed. Samples behind the plane or with a
// singular J contribute nothing (their energy is +inf for every nearby p4).
glm::dvec3 EnergyGradientAnalytic(const LightMatrix& matrix, const LightSamples& samples);

// The same by Ceres Jets through SampleEnergy.
glm::dvec3 EnergyGradientJets(const LightMatrix& matrix, const LightSamples& samples);

}  // namespace lexel::spatial
