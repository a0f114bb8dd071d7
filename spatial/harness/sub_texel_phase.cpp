#include "lexel/spatial/harness/sub_texel_phase.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lexel::spatial {

std::vector<glm::dvec2> SubTexelPhases(int count, int first) {
    if (count < 1) throw std::invalid_argument("SubTexelPhases: count must be at least 1");
    if (first < 0) throw std::invalid_argument("SubTexelPhases: first must not be negative");
    // The plastic number: the real root of g³ = g + 1 (Roberts 2018, "The unreasonable
    // effectiveness of quasirandom sequences").
    constexpr double g = 1.32471795724474602596;
    const glm::dvec2 alpha(1.0 / g, 1.0 / (g * g));
    std::vector<glm::dvec2> phases;
    phases.reserve(static_cast<std::size_t>(count));
    for (int k = first; k < first + count; ++k) {
        const glm::dvec2 t = 0.5 + static_cast<double>(k) * alpha;
        phases.push_back(t - glm::floor(t) - 0.5);
    }
    return phases;
}

std::vector<glm::dvec2> HeldOutSubTexelPhases(int count) {
    if (count < 1) throw std::invalid_argument("HeldOutSubTexelPhases: count must be at least 1");
    return SubTexelPhases(count, count);
}

PhaseMean MeanOverPhases(std::span<const std::int64_t> perPhase) {
    PhaseMean out;
    if (perPhase.empty()) return out;
    const double k = static_cast<double>(perPhase.size());
    for (std::int64_t v : perPhase) out.mean += static_cast<double>(v);
    out.mean /= k;
    if (perPhase.size() < 2) return out;
    double squares = 0.0;
    for (std::int64_t v : perPhase) squares += (static_cast<double>(v) - out.mean) * (v - out.mean);
    out.standardError = std::sqrt(squares / (k - 1.0) / k);
    return out;
}

bool PhaseMeanSettled(const PhaseMean& mean) {
    return mean.standardError <= std::max(kPhaseResidual * mean.mean, kPhaseResidualFloor);
}

std::vector<std::int64_t> CountOverPhases(
    int phases, int maxPhases, int first,
    const std::function<std::int64_t(int k, const glm::dvec2& phase)>& countAt) {
    if (phases < 1) throw std::invalid_argument("CountOverPhases: phases must be at least 1");
    std::vector<std::int64_t> counts;
    int target = phases;
    while (true) {
        const int measured = static_cast<int>(counts.size());
        const std::vector<glm::dvec2> more = SubTexelPhases(target - measured, first + measured);
        for (int i = 0; i < static_cast<int>(more.size()); ++i)
            counts.push_back(countAt(first + measured + i, more[i]));
        if (target >= maxPhases || PhaseMeanSettled(MeanOverPhases(counts))) return counts;
        target = std::min(2 * target, maxPhases);
    }
}

}  // namespace lexel::spatial
