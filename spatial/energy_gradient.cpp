#include "lexel/spatial/energy_gradient.h"

#include <ceres/jet.h>

#include <cmath>

namespace lexel::spatial {

namespace {

// One sample's J = ∂(u, v)/∂(x1, x2) under `m`, with what its derivative by p4 needs (the
// header's eq. (11)): u_i = p_i·X / w and v_j = p4·D_j / w, w = p4·X.
struct SampleJacobianTerms {
    glm::dvec3 X, D[2];
    double invW = 0.0, u[2] = {}, v[2] = {}, J[2][2] = {}, det = 0.0;
};

SampleJacobianTerms JacobianTermsAt(const LightMatrix& m, const glm::dvec3& X, const glm::dvec3& D1,
                                    const glm::dvec3& D2) {
    SampleJacobianTerms s{X, {D1, D2}};
    const glm::dvec3 p[2] = {m.p1, m.p2};
    s.invW = 1.0 / glm::dot(m.p4, X);
    const double wD[2] = {glm::dot(m.p4, D1), glm::dot(m.p4, D2)};
    for (int i = 0; i < 2; ++i) {
        s.u[i] = glm::dot(p[i], X) * s.invW;
        s.v[i] = wD[i] * s.invW;
    }
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) s.J[i][j] = (glm::dot(p[i], s.D[j]) - s.u[i] * wD[j]) * s.invW;
    s.det = s.J[0][0] * s.J[1][1] - s.J[0][1] * s.J[1][0];
    return s;
}

// The header's eq. (11) factored: ∂J_ij/∂p4 = -(1/w) [(J_ij - u_i v_j) X + u_i D_j], so
// Σ_ij dF_ij ∂J_ij/∂p4 = -(1/w) [c_X X + c_1 D_1 + c_2 D_2] with c_X = Σ_ij dF_ij (J_ij - u_i v_j)
// and c_j = Σ_i dF_ij u_i: two divisions per sample. Returns (weight/w) [c_X X + c_1 D_1 + c_2
// D_2], the negated sum scaled by `weight`.
glm::dvec3 NegatedChainToP4(const SampleJacobianTerms& s, const double dF[2][2], double weight) {
    double cX = 0.0, c[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            cX += dF[i][j] * (s.J[i][j] - s.u[i] * s.v[j]);
            c[j] += dF[i][j] * s.u[i];
        }
    return (weight * s.invW) * (cX * s.X + c[0] * s.D[0] + c[1] * s.D[1]);
}

glm::dvec2 NormalOf(const WeightedPoints& points, std::size_t k) {
    return points.edgeNormal.empty() ? glm::dvec2(0.0) : points.edgeNormal[k];
}

}  // namespace

glm::dvec3 EnergyGradientAnalytic(const LightMatrix& m, const LightSamples& samples) {
    // Per sample ∂f/∂J of f = ‖J‖²_F / det², then NegatedChainToP4.
    glm::dvec3 grad(0.0);
    for (std::size_t k = 0; k < samples.lsX.size(); ++k) {
        if (!InFront(m.p4, samples.lsX[k])) continue;
        const SampleJacobianTerms s =
            JacobianTermsAt(m, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]);
        const auto& J = s.J;
        if (s.det == 0.0) continue;
        const double S =
            J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1];
        const double invDet = 1.0 / s.det;
        const double g = 2.0 * invDet * invDet, t = g * S * invDet;  // 2/det², 2S/det³
        const double dF[2][2] = {{g * J[0][0] - t * J[1][1], g * J[0][1] + t * J[1][0]},
                                 {g * J[1][0] + t * J[0][1], g * J[1][1] - t * J[0][0]}};
        grad -= NegatedChainToP4(s, dF, 1.0);
    }
    return grad;
}

glm::dvec3 EnergyGradientJets(const LightMatrix& m, const LightSamples& samples) {
    using Jet = ceres::Jet<double, 3>;
    const Jet p4[3] = {Jet(m.p4.x, 0), Jet(m.p4.y, 1), Jet(m.p4.z, 2)};
    glm::dvec3 grad(0.0);
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        if (!InFront(m.p4, samples.lsX[s])) continue;
        const Jet f = SampleEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, samples.lsX[s],
                                   samples.dXdx1[s], samples.dXdx2[s]);
        if (!std::isfinite(f.a)) continue;
        grad += glm::dvec3(f.v[0], f.v[1], f.v[2]);
    }
    return grad;
}

glm::dvec3 EdgeEnergyGradientAnalytic(const LightMatrix& m, const WeightedPoints& points) {
    // The header comment's ∂f_e/∂J, then NegatedChainToP4.
    glm::dvec3 grad(0.0);
    for (std::size_t k = 0; k < points.lsX.size(); ++k) {
        if (!InFront(m.p4, points.lsX[k])) continue;
        const SampleJacobianTerms s =
            JacobianTermsAt(m, points.lsX[k], points.dXdx1[k], points.dXdx2[k]);
        const auto& J = s.J;
        const glm::dvec2 n = NormalOf(points, k);
        double dQ[2][2], q;
        if (n.x == 0.0 && n.y == 0.0) {
            q = 0.5 *
                (J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1]);
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) dQ[i][j] = J[i][j];
        } else {
            const double a = n.x * J[1][1] - n.y * J[1][0], b = n.y * J[0][0] - n.x * J[0][1];
            q = a * a + b * b;
            dQ[0][0] = 2.0 * b * n.y, dQ[0][1] = -2.0 * b * n.x;
            dQ[1][0] = -2.0 * a * n.y, dQ[1][1] = 2.0 * a * n.x;
        }
        if (s.det == 0.0 || !(q > 0.0)) continue;  // +inf (singular) or the norm's minimum
        const double root = std::sqrt(q), absDet = std::abs(s.det);
        const double f = root / absDet;
        if (!std::isfinite(f)) continue;
        const double cof[2][2] = {{J[1][1], -J[1][0]}, {-J[0][1], J[0][0]}};
        // ∂(f_e^p)/∂J = p f_e^(p−1) ∂f_e/∂J (1 for p = 1: the norm's own derivative), f_e^(p−1)
        // as f_e^p / f_e with f_e^p the summand's own BandPower, no std::pow. A point whose
        // summand is not finite (det² underflows while f_e does not) adds nothing, as its energy.
        const double summand = BandPower(q / (s.det * s.det), points.exponent);
        if (!std::isfinite(summand)) continue;
        const double power = points.exponent == 1.0 ? 1.0 : points.exponent * summand / f;
        const double g = power * 0.5 / (root * absDet), t = power * f / s.det;
        double dF[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) dF[i][j] = g * dQ[i][j] - t * cof[i][j];
        grad -= NegatedChainToP4(s, dF, points.weight);
    }
    return grad;
}

glm::dvec3 EdgeEnergyGradientJets(const LightMatrix& m, const WeightedPoints& points) {
    using Jet = ceres::Jet<double, 3>;
    const Jet p4[3] = {Jet(m.p4.x, 0), Jet(m.p4.y, 1), Jet(m.p4.z, 2)};
    glm::dvec3 grad(0.0);
    for (std::size_t s = 0; s < points.lsX.size(); ++s) {
        if (!InFront(m.p4, points.lsX[s])) continue;
        const Jet f = SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4,
                                       points.lsX[s], points.dXdx1[s], points.dXdx2[s],
                                       NormalOf(points, s), points.exponent);
        if (!std::isfinite(f.a)) continue;
        grad += points.weight * glm::dvec3(f.v[0], f.v[1], f.v[2]);
    }
    return grad;
}

}  // namespace lexel::spatial
