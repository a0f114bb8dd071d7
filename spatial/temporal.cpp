#include "lexel/spatial/temporal.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lexel::spatial {

namespace {

double EdgeBadness(const LightMatrix& m, const LightSamples& s, std::size_t k) {
    if (!InFront(m.p4, s.lsX[k])) return std::numeric_limits<double>::infinity();
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    const glm::dvec2 n = s.edgeNormal.size() == s.lsX.size() ? s.edgeNormal[k] : glm::dvec2(0.0);
    const double f = SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, s.lsX[k],
                                      s.dXdx1[k], s.dXdx2[k], n);
    return std::isnan(f) ? std::numeric_limits<double>::infinity() : f;
}

}  // namespace

double MedianBadness(const LightMatrix& matrix, const LightSamples& samples, EnergyKind kind) {
    std::vector<double> values;
    values.reserve(samples.lsX.size());
    for (std::size_t k = 0; k < samples.lsX.size(); ++k)
        values.push_back(
            kind == EnergyKind::kEdge
                ? EdgeBadness(matrix, samples, k)
                : SampleBadness(matrix, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]));
    if (values.empty()) return std::numeric_limits<double>::infinity();
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    if (values.size() % 2) return values[mid];
    const double upper = values[mid];
    return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + mid));
}

std::optional<LightMatrix> RescaleToCover(const LightMatrix& previous, const LightSamples& samples,
                                          Resolution map, double margin) {
    if (samples.lsRelevant.empty()) return previous;
    return ScaleMapToCover(previous, samples.lsRelevant, map, margin);
}

HysteresisDecision ApplyHysteresis(const std::optional<LightMatrix>& previous,
                                   const LightMatrix& candidate, const LightSamples& samples,
                                   Resolution map, double margin, EnergyKind kind) {
    HysteresisDecision d;
    d.matrix = candidate;
    d.medianCandidate = MedianBadness(candidate, samples, kind);
    d.medianPrevious = std::numeric_limits<double>::infinity();
    if (!previous) return d;
    const std::optional<LightMatrix> kept = RescaleToCover(*previous, samples, map, margin);
    if (!kept) return d;  // the old axis no longer sees every relevant point: must change
    d.medianPrevious = MedianBadness(*kept, samples, kind);
    const double threshold =
        kind == EnergyKind::kEdge ? std::sqrt(kSufficientImprovement) : kSufficientImprovement;
    if (d.medianCandidate < threshold * d.medianPrevious) return d;
    d.matrix = *kept;
    d.changed = false;
    return d;
}

}  // namespace lexel::spatial
