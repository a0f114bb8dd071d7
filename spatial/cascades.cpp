#include "lexel/spatial/cascades.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lexel/solvers/lagrange_allocation.h"

namespace lexel::spatial {

double PlanarEyeDepth(const Camera& camera, const glm::dvec3& wsPoint) {
    const glm::dvec3 view = glm::normalize(camera.target - camera.position);
    return glm::dot(wsPoint - camera.position, view);
}

std::vector<double> PssmSplits(double zNear, double zFar, int k, double lambda) {
    if (!(zNear > 0.0) || !(zFar > zNear) || !std::isfinite(zFar) || k < 1 ||
        !(lambda >= 0.0 && lambda <= 1.0))
        throw std::invalid_argument("PssmSplits: needs 0 < near < far, k >= 1, lambda in [0, 1]");
    std::vector<double> splits(static_cast<std::size_t>(k) + 1);
    for (int i = 0; i <= k; ++i) {
        const double t = static_cast<double>(i) / k;
        const double logSplit = zNear * std::pow(zFar / zNear, t);
        const double uniform = zNear + (zFar - zNear) * t;
        splits[i] = lambda * logSplit + (1.0 - lambda) * uniform;
    }
    splits.front() = zNear;  // exactly, whatever pow and the blend round to
    splits.back() = zFar;
    return splits;
}

namespace {

bool InHalfSpaces(const Cascade& c, const glm::dvec3& wsPoint) {
    for (const glm::dvec4& plane : c.wsHalfSpaces)
        if (!(glm::dot(glm::dvec3(plane), wsPoint) + plane.w >= 0.0)) return false;
    return true;
}

}  // namespace

bool Cascade::Holds(double z, const glm::dvec3& wsPoint) const {
    return z >= zNear && z < zFar && InHalfSpaces(*this, wsPoint);
}

std::size_t CascadeFor(std::span<const Cascade> cascades, double z, const glm::dvec3& wsPoint,
                       bool* covered) {
    if (cascades.empty()) throw std::invalid_argument("CascadeFor: no cascades");
    std::size_t nearest = cascades.size();
    double nearestGap = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2 && nearest == cascades.size(); ++pass)
        for (std::size_t i = 0; i < cascades.size(); ++i) {
            const Cascade& c = cascades[i];
            if (c.Holds(z, wsPoint)) {
                if (covered) *covered = true;
                return i;
            }
            if (pass == 0 && !InHalfSpaces(c, wsPoint)) continue;
            const double gap = z < c.zNear ? c.zNear - z : z - c.zFar;
            if (gap < nearestGap) nearestGap = gap, nearest = i;
        }
    if (covered) *covered = false;
    return nearest;
}

namespace {

// The squarest w × h with w h ≤ texels (≥ 1 × 1).
Resolution SquarestMap(long long texels) {
    const int w = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(texels)))));
    return {w, std::max(1, static_cast<int>(texels / w))};
}

}  // namespace

std::vector<Resolution> AllocateCascadeMaps(Resolution total, std::span<const double> costs,
                                            CascadeAllocation allocation, double exponent) {
    const std::size_t k = costs.size();
    if (k == 0) throw std::invalid_argument("AllocateCascadeMaps: no cascades");
    for (double c : costs)
        if (!(c >= 0.0) || !std::isfinite(c))
            throw std::invalid_argument("AllocateCascadeMaps: costs must be finite and >= 0");
    if (allocation == CascadeAllocation::kEqual) {
        const double scale = 1.0 / std::sqrt(static_cast<double>(k));
        // Rounded down (1e-9: an exact √k stays exact), so the k maps never exceed the budget.
        const auto side = [scale](int n) {
            return std::max(1, static_cast<int>(std::floor(n * scale + 1e-9)));
        };
        const Resolution each{side(total.width), side(total.height)};
        return std::vector<Resolution>(k, each);
    }
    std::vector<Resolution> maps;
    for (int n : LagrangeCascadeTexels(total, costs, exponent)) maps.push_back(SquarestMap(n));
    return maps;
}

std::vector<int> LagrangeCascadeTexels(Resolution total, std::span<const double> costs,
                                       double exponent) {
    // Σ c_i / N_i^k is minimized by N_i ∝ c_i^(1/(k+1)) (lagrange_allocation.h): √c_i for h.
    return AllocateLexelsInteger(costs, exponent, static_cast<int>(total.Count()));
}

LightMatrix RescaleMap(const LightMatrix& matrix, Resolution from, Resolution to) {
    glm::dmat3 scale(1.0);
    scale[0][0] = static_cast<double>(to.width) / from.width;
    scale[1][1] = static_cast<double>(to.height) / from.height;
    return matrix.ThenAffine(scale);
}

}  // namespace lexel::spatial
