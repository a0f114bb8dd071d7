#include "lexel/spatial/energy.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace lexel::spatial {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec2 EdgeNormalOf(const LightSamples& samples, std::size_t k) {
    return samples.edgeNormal.size() == samples.lsX.size() ? samples.edgeNormal[k]
                                                           : glm::dvec2(0.0);
}

// One summand of the chosen energy, no in-front test (NaN: singular).
double Summand(const LightMatrix& m, EnergyKind kind, const glm::dvec3& X, const glm::dvec3& D1,
               const glm::dvec3& D2, const glm::dvec2& n) {
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    if (kind == EnergyKind::kReport)
        return SampleEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, X, D1, D2);
    return SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, X, D1, D2, n);
}

// Σ over the boundary samples, stopping at `bound` (every summand ≥ 0 or +inf).
double SampleSum(const LightMatrix& m, const LightSamples& s, EnergyKind kind, double bound) {
    double total = 0.0;
    for (std::size_t k = 0; k < s.lsX.size(); ++k) {
        if (!InFront(m.p4, s.lsX[k])) return kInf;
        const double f = Summand(m, kind, s.lsX[k], s.dXdx1[k], s.dXdx2[k], EdgeNormalOf(s, k));
        total += std::isnan(f) ? kInf : f;
        if (total >= bound) return total;
    }
    return total;
}

}  // namespace

double PriorEnergy(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options) {
    if (options.priorWeight == 0.0 || s.lsPrior.empty()) return 0.0;
    double total = 0.0;
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
        if (!InFront(m.p4, s.lsPrior[k])) continue;
        const double f =
            Summand(m, options.kind, s.lsPrior[k], s.priorDXdx1[k], s.priorDXdx2[k], {0.0, 0.0});
        if (std::isfinite(f)) total += f;
    }
    return options.priorWeight * total / static_cast<double>(s.lsPrior.size());
}

double Energy(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options) {
    if (options.IsReport()) return Energy(m, s);
    const double samplesPart = SampleSum(m, s, options.kind, kInf);
    return samplesPart + PriorEnergy(m, s, options);
}

WeightedPoints BoundaryPoints(const LightSamples& s) {
    return {s.lsX, s.dXdx1, s.dXdx2,
            s.edgeNormal.size() == s.lsX.size() ? std::span<const glm::dvec2>(s.edgeNormal)
                                                : std::span<const glm::dvec2>(),
            1.0};
}

WeightedPoints PriorPoints(const LightSamples& s, double priorWeight) {
    const double weight = s.lsPrior.empty() ? 0.0 : priorWeight / double(s.lsPrior.size());
    return {s.lsPrior, s.priorDXdx1, s.priorDXdx2, {}, weight};
}

namespace {

// Σ weight ∂||J⁻¹||_F²/∂p4 over the prior points (h's summand, eq. 10–11).
glm::dvec3 ReportPriorGradient(const LightMatrix& m, const LightSamples& s, double priorWeight,
                               bool jets) {
    if (priorWeight == 0.0 || s.lsPrior.empty()) return glm::dvec3(0.0);
    LightSamples prior;
    prior.lsX = s.lsPrior;
    prior.dXdx1 = s.priorDXdx1;
    prior.dXdx2 = s.priorDXdx2;
    const glm::dvec3 g = jets ? EnergyGradientJets(m, prior) : EnergyGradientAnalytic(m, prior);
    return priorWeight / double(s.lsPrior.size()) * g;
}

glm::dvec3 Gradient(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options,
                    bool jets) {
    if (options.kind == EnergyKind::kReport) {
        const glm::dvec3 g = jets ? EnergyGradientJets(m, s) : EnergyGradientAnalytic(m, s);
        if (options.priorWeight == 0.0) return g;
        return g + ReportPriorGradient(m, s, options.priorWeight, jets);
    }
    const auto edge = jets ? &EdgeEnergyGradientJets : &EdgeEnergyGradientAnalytic;
    glm::dvec3 g = edge(m, BoundaryPoints(s));
    if (options.priorWeight != 0.0) g += edge(m, PriorPoints(s, options.priorWeight));
    return g;
}

}  // namespace

glm::dvec3 EnergyGradient(const LightMatrix& m, const LightSamples& s,
                          const EnergyOptions& options) {
    return Gradient(m, s, options, false);
}

glm::dvec3 EnergyGradientJets(const LightMatrix& m, const LightSamples& s,
                              const EnergyOptions& options) {
    return Gradient(m, s, options, true);
}

SearchEnergy::SearchEnergy(const LightSamples& samples, const EnergyOptions& options)
    : samples_(samples), options_(options) {
    if (options.IsReport()) report_.emplace(samples);
}

double SearchEnergy::operator()(const LightMatrix& m, double bound) const {
    if (report_) return (*report_)(m, bound);
    // The prior first: it is bounded and cheap, so a poor candidate stops early in the samples.
    const double prior = PriorEnergy(m, samples_, options_);
    if (prior >= bound) return prior;
    const double sum = SampleSum(m, samples_, options_.kind, bound - prior);
    // Stopped early: keep the result ≥ bound whatever the rounding of the subtraction.
    return sum >= bound - prior ? std::max(sum + prior, bound) : sum + prior;
}

std::optional<double> RelevantFootprint(const LightMatrix& m, const LightSamples& s) {
    double total = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
        if (!InFront(m.p4, s.lsPrior[k])) continue;
        // ||J⁻¹||_F = √2 · f_e without a normal.
        const double f = Summand(m, EnergyKind::kEdge, s.lsPrior[k], s.priorDXdx1[k],
                                 s.priorDXdx2[k], glm::dvec2(0.0));
        if (std::isfinite(f)) total += std::sqrt(2.0) * f, ++count;
    }
    if (count == 0) return std::nullopt;
    return total / static_cast<double>(count);
}

bool Collapses(const LightMatrix& start, const LightMatrix& refined, const LightSamples& s,
               double factor) {
    if (!(factor > 0.0)) return false;
    const std::optional<double> before = RelevantFootprint(start, s);
    const std::optional<double> after = RelevantFootprint(refined, s);
    if (!before || !after) return false;
    return *after > factor * *before;
}

}  // namespace lexel::spatial
