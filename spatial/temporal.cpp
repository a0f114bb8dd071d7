#include "lexel/spatial/temporal.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lexel::spatial {

double MedianBadness(const LightMatrix& matrix, const LightSamples& samples) {
    std::vector<double> values;
    values.reserve(samples.lsX.size());
    for (std::size_t k = 0; k < samples.lsX.size(); ++k)
        values.push_back(SampleBadness(matrix, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]));
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
                                   Resolution map, double margin) {
    HysteresisDecision d;
    d.matrix = candidate;
    d.medianCandidate = MedianBadness(candidate, samples);
    d.medianPrevious = std::numeric_limits<double>::infinity();
    if (!previous) return d;
    const std::optional<LightMatrix> kept = RescaleToCover(*previous, samples, map, margin);
    if (!kept) return d;  // the old axis no longer sees every relevant point: must change
    d.medianPrevious = MedianBadness(*kept, samples);
    if (d.medianCandidate < kSufficientImprovement * d.medianPrevious) return d;
    d.matrix = *kept;
    d.changed = false;
    return d;
}

}  // namespace lexel::spatial
