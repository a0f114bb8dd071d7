#include "lexel/spatial/energy_gradient.h"

#include <ceres/jet.h>

#include <cmath>

namespace lexel::spatial {

glm::dvec3 EnergyGradientAnalytic(const LightMatrix& m, const LightSamples& samples) {
    // The header's eq. (11) factored: with u_i = p_i·X / w and v_j = p4·D_j / w,
    //     ∂J_ij/∂p4 = -(1/w) [(J_ij - u_i v_j) X + u_i D_j],
    // so Σ_ij ∂f/∂J_ij ∂J_ij/∂p4 = -(1/w) [c_X X + c_1 D_1 + c_2 D_2] with
    // c_X = Σ_ij ∂f/∂J_ij (J_ij - u_i v_j) and c_j = Σ_i ∂f/∂J_ij u_i: two divisions per sample.
    glm::dvec3 grad(0.0);
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        const glm::dvec3& X = samples.lsX[s];
        if (!InFront(m.p4, X)) continue;
        const glm::dvec3 D[2] = {samples.dXdx1[s], samples.dXdx2[s]};
        const glm::dvec3 p[2] = {m.p1, m.p2};
        const double invW = 1.0 / glm::dot(m.p4, X);
        const double wD[2] = {glm::dot(m.p4, D[0]), glm::dot(m.p4, D[1])};
        const double u[2] = {glm::dot(p[0], X) * invW, glm::dot(p[1], X) * invW};
        const double v[2] = {wD[0] * invW, wD[1] * invW};
        double J[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) J[i][j] = (glm::dot(p[i], D[j]) - u[i] * wD[j]) * invW;
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (det == 0.0) continue;
        const double S =
            J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1];
        const double invDet = 1.0 / det;
        const double g = 2.0 * invDet * invDet, t = g * S * invDet;  // 2/det², 2S/det³
        const double dF[2][2] = {{g * J[0][0] - t * J[1][1], g * J[0][1] + t * J[1][0]},
                                 {g * J[1][0] + t * J[0][1], g * J[1][1] - t * J[0][0]}};
        double cX = 0.0, c[2] = {0.0, 0.0};
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                cX += dF[i][j] * (J[i][j] - u[i] * v[j]);
                c[j] += dF[i][j] * u[i];
            }
        grad -= invW * (cX * X + c[0] * D[0] + c[1] * D[1]);
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

namespace {

glm::dvec2 NormalOf(const WeightedPoints& points, std::size_t k) {
    return points.edgeNormal.empty() ? glm::dvec2(0.0) : points.edgeNormal[k];
}

}  // namespace

glm::dvec3 EdgeEnergyGradientAnalytic(const LightMatrix& m, const WeightedPoints& points) {
    // The header comment's ∂f_e/∂J, then ∂J/∂p4 factored as in EnergyGradientAnalytic.
    glm::dvec3 grad(0.0);
    const glm::dvec3 p[2] = {m.p1, m.p2};
    for (std::size_t s = 0; s < points.lsX.size(); ++s) {
        const glm::dvec3& X = points.lsX[s];
        if (!InFront(m.p4, X)) continue;
        const glm::dvec3 D[2] = {points.dXdx1[s], points.dXdx2[s]};
        const double invW = 1.0 / glm::dot(m.p4, X);
        const double wD[2] = {glm::dot(m.p4, D[0]), glm::dot(m.p4, D[1])};
        const double u[2] = {glm::dot(p[0], X) * invW, glm::dot(p[1], X) * invW};
        const double v[2] = {wD[0] * invW, wD[1] * invW};
        double J[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) J[i][j] = (glm::dot(p[i], D[j]) - u[i] * wD[j]) * invW;
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        const glm::dvec2 n = NormalOf(points, s);
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
        if (det == 0.0 || !(q > 0.0)) continue;  // +inf (singular) or the norm's minimum
        const double root = std::sqrt(q), absDet = std::abs(det);
        const double f = root / absDet;
        if (!std::isfinite(f)) continue;
        const double cof[2][2] = {{J[1][1], -J[1][0]}, {-J[0][1], J[0][0]}};
        const double g = 0.5 / (root * absDet), t = f / det;
        double cX = 0.0, c[2] = {0.0, 0.0};
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const double dF = g * dQ[i][j] - t * cof[i][j];
                cX += dF * (J[i][j] - u[i] * v[j]);
                c[j] += dF * u[i];
            }
        grad -= (points.weight * invW) * (cX * X + c[0] * D[0] + c[1] * D[1]);
    }
    return grad;
}

glm::dvec3 EdgeEnergyGradientJets(const LightMatrix& m, const WeightedPoints& points) {
    using Jet = ceres::Jet<double, 3>;
    const Jet p4[3] = {Jet(m.p4.x, 0), Jet(m.p4.y, 1), Jet(m.p4.z, 2)};
    glm::dvec3 grad(0.0);
    for (std::size_t s = 0; s < points.lsX.size(); ++s) {
        if (!InFront(m.p4, points.lsX[s])) continue;
        const Jet f =
            SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, points.lsX[s],
                             points.dXdx1[s], points.dXdx2[s], NormalOf(points, s));
        if (!std::isfinite(f.a)) continue;
        grad += points.weight * glm::dvec3(f.v[0], f.v[1], f.v[2]);
    }
    return grad;
}

}  // namespace lexel::spatial
