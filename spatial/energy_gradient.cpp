#include "spatial/energy_gradient.h"

#include <ceres/jet.h>

#include <cmath>

namespace lexel::spatial {

glm::dvec3 EnergyGradientAnalytic(const LightMatrix& m, const LightSamples& samples) {
    glm::dvec3 grad(0.0);
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        const glm::dvec3& X = samples.lsX[s];
        const glm::dvec3 D[2] = {samples.dXdx1[s], samples.dXdx2[s]};
        const double w = glm::dot(m.p4, X);
        if (!InFront(m.p4, X)) continue;
        const glm::dvec3 p[2] = {m.p1, m.p2};
        double J[2][2];
        glm::dvec3 dJ[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const double pD = glm::dot(p[i], D[j]), pX = glm::dot(p[i], X);
                const double wD = glm::dot(m.p4, D[j]);
                J[i][j] = pD / w - pX * wD / (w * w);
                dJ[i][j] = -(pD / (w * w)) * X - (pX / (w * w)) * D[j] +
                           (2.0 * pX * wD / (w * w * w)) * X;  // eq. (11)
            }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (det == 0.0) continue;
        const double S =
            J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1];
        const double det2 = det * det, det3 = det2 * det;
        const double dF[2][2] = {{2 * J[0][0] / det2 - 2 * S * J[1][1] / det3,
                                  2 * J[0][1] / det2 + 2 * S * J[1][0] / det3},
                                 {2 * J[1][0] / det2 + 2 * S * J[0][1] / det3,
                                  2 * J[1][1] / det2 - 2 * S * J[0][0] / det3}};
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) grad += dF[i][j] * dJ[i][j];
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

}  // namespace lexel::spatial
