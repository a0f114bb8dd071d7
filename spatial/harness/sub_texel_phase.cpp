#include "lexel/spatial/harness/sub_texel_phase.h"

#include <cmath>
#include <stdexcept>

namespace lexel::spatial {

std::vector<glm::dvec2> SubTexelPhases(int count) {
    if (count < 1) throw std::invalid_argument("SubTexelPhases: count must be at least 1");
    // The plastic number: the real root of g³ = g + 1 (Roberts 2018, "The unreasonable
    // effectiveness of quasirandom sequences").
    constexpr double g = 1.32471795724474602596;
    const glm::dvec2 alpha(1.0 / g, 1.0 / (g * g));
    std::vector<glm::dvec2> phases;
    phases.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        const glm::dvec2 t = 0.5 + static_cast<double>(k) * alpha;
        phases.push_back(t - glm::floor(t) - 0.5);
    }
    return phases;
}

std::vector<glm::dvec2> HeldOutSubTexelPhases(int count) {
    if (count < 1) throw std::invalid_argument("HeldOutSubTexelPhases: count must be at least 1");
    std::vector<glm::dvec2> phases = SubTexelPhases(2 * count);
    phases.erase(phases.begin(), phases.begin() + count);
    return phases;
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

}  // namespace lexel::spatial
