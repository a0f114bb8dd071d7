#include "lexel/solvers/footprint_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel {

namespace {

// Every column but the median.
FootprintStats SummarizeWithoutMedian(std::span<const double> footprints,
                                      std::span<const double> weights, long double& sumW) {
    const bool weighted = !weights.empty();
    if (weighted && weights.size() != footprints.size())
        throw std::invalid_argument("footprint weights: expected " +
                                    std::to_string(footprints.size()) + " weights, got " +
                                    std::to_string(weights.size()));
    FootprintStats stats;
    // Pass 1: sums and max. Sums in long double: a million footprints of mixed magnitude must
    // not lose the last digit the thesis tables print.
    long double sumWF = 0, sumWF2 = 0;
    sumW = 0;
    for (std::size_t i = 0; i < footprints.size(); ++i) {
        const double f = footprints[i];
        const double w = weighted ? weights[i] : 1.0;
        if (std::isnan(f) || f < 0)
            throw std::invalid_argument("footprint " + std::to_string(i) +
                                        ": must be a non-negative number");
        if (std::isnan(w) || w < 0 || std::isinf(w))
            throw std::invalid_argument("footprint weight " + std::to_string(i) +
                                        ": must be finite and non-negative");
        if (w == 0) continue;
        ++stats.count;
        sumW += w;
        sumWF += static_cast<long double>(w) * f;
        sumWF2 += static_cast<long double>(w) * f * f;
        stats.linf = std::max(stats.linf, f);
    }
    if (stats.count == 0) return stats;
    stats.weightSum = static_cast<double>(sumW);
    stats.l1 = static_cast<double>(sumWF);
    stats.l2 = static_cast<double>(sumWF2);
    const long double mean = sumWF / sumW;
    stats.average = static_cast<double>(mean);
    // Pass 2: the variance about the mean (two-pass, so no cancellation).
    long double var = 0;
    for (std::size_t i = 0; i < footprints.size(); ++i) {
        const double w = weighted ? weights[i] : 1.0;
        if (w == 0) continue;
        const long double d = footprints[i] - mean;
        var += w * d * d;
    }
    stats.sigma = static_cast<double>(std::sqrt(var / sumW));
    stats.meanPlusSigma = stats.average + stats.sigma;
    return stats;
}

// The usual middle of unit-weight values (mean of the two middles for an even count); reorders f.
double MedianInPlace(std::span<double> f) {
    const std::size_t mid = f.size() / 2;
    std::nth_element(f.begin(), f.begin() + mid, f.end());
    double median = f[mid];
    if (f.size() % 2 == 0) median = 0.5 * (median + *std::max_element(f.begin(), f.begin() + mid));
    return median;
}

}  // namespace

FootprintStats SummarizeFootprints(std::span<const double> footprints,
                                   std::span<const double> weights) {
    long double sumW = 0;
    FootprintStats stats = SummarizeWithoutMedian(footprints, weights, sumW);
    if (stats.count == 0) return stats;
    if (weights.empty()) {
        std::vector<double> f(footprints.begin(), footprints.end());
        stats.median = MedianInPlace(f);
        return stats;
    }
    // For general weights the median is the smallest f whose cumulative weight reaches half the
    // total.
    std::vector<std::size_t> order;
    order.reserve(stats.count);
    for (std::size_t i = 0; i < footprints.size(); ++i)
        if (weights[i] > 0) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return footprints[a] < footprints[b]; });
    long double cumulative = 0;
    for (std::size_t i : order) {
        cumulative += weights[i];
        if (cumulative >= 0.5L * sumW) {
            stats.median = footprints[i];
            break;
        }
    }
    return stats;
}

FootprintStats SummarizeFootprintsInPlace(std::span<double> footprints) {
    long double sumW = 0;
    FootprintStats stats = SummarizeWithoutMedian(footprints, {}, sumW);
    if (stats.count > 0) stats.median = MedianInPlace(footprints);
    return stats;
}

std::string_view MetricName(Metric metric) {
    switch (metric) {
        case Metric::kL1:
            return "l1";
        case Metric::kL2:
            return "l2";
        case Metric::kLinf:
            return "linf";
    }
    return "?";
}

std::optional<Metric> ParseMetric(std::string_view name) {
    if (name == "l1") return Metric::kL1;
    if (name == "l2") return Metric::kL2;
    if (name == "linf") return Metric::kLinf;
    return std::nullopt;
}

Eigen::Vector2d SingularValues2x2(const Eigen::Matrix2d& m) {
    // Closed form (Blinn, "Consider the lowly 2×2 matrix"): with
    // E = (a+d)/2, F = (a-d)/2, G = (c+b)/2, H = (c-b)/2,
    // σ1 = hypot(E,H) + hypot(F,G),  σ2 = |hypot(E,H) - hypot(F,G)|.
    const double e = 0.5 * (m(0, 0) + m(1, 1));
    const double f = 0.5 * (m(0, 0) - m(1, 1));
    const double g = 0.5 * (m(1, 0) + m(0, 1));
    const double h = 0.5 * (m(1, 0) - m(0, 1));
    const double q = std::hypot(e, h);
    const double r = std::hypot(f, g);
    return {q + r, std::abs(q - r)};
}

double JacobianBadness(const Eigen::Matrix2d& texelsPerPixel, Badness badness) {
    const double det =
        texelsPerPixel(0, 0) * texelsPerPixel(1, 1) - texelsPerPixel(0, 1) * texelsPerPixel(1, 0);
    const double scale = texelsPerPixel.cwiseAbs().maxCoeff();
    // A determinant below 1e-300 of the squared entry scale is a rank-deficient J at double
    // precision: a screen direction that moves zero texels, i.e. an unbounded footprint.
    if (!(std::abs(det) > 1e-300 * std::max(scale * scale, 1e-300)))
        return std::numeric_limits<double>::infinity();
    // Closed-form inverse of J = [a b; c d]:  J⁻¹ = [d -b; -c a] / det.
    Eigen::Matrix2d inverse;
    inverse << texelsPerPixel(1, 1), -texelsPerPixel(0, 1), -texelsPerPixel(1, 0),
        texelsPerPixel(0, 0);
    inverse /= det;
    switch (badness) {
        case Badness::kFrobeniusInverseSquared:
            return inverse.squaredNorm();
        case Badness::kGeometricStretch:
            return std::sqrt(0.5 * inverse.squaredNorm());
        case Badness::kLargestSingularValue:
            return SingularValues2x2(inverse)[0];
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace lexel
