// The metric layer shared by flatland and spatial.
//
// Chong 2003, ch. 2.1: the "badness" of a pixel is its footprint f = |dp/dl|, pixels per lexel.
// The discrete metrics over the visible pixels Ω are
//     L1 = Σ_Ω f,      L2 = Σ_Ω f²,      L∞ = max_Ω f,
// and their continuous forms ∫_Ω f dp, ∫_Ω f² dp are the same sums read as Riemann sums with a
// unit pixel width (Δp = 1), so the discrete values here are also the continuous ones at the
// sampling resolution. The tables of ch. 4.1.3 report Worst (= L∞), Average (= L1/|Ω|) and
// Mean+σ (population σ); SummarizeFootprints returns exactly those columns.
//
// Chong & Gortler (EG tech report), eq. (5)-(6): in 3D a sample's badness comes from the 2×2
// Jacobian J = ∂u/∂x (shadow-map texels per screen pixel). Its inverse J⁻¹ = ∂x/∂u is the 3D
// footprint (pixels per texel), and the report's energy sums Σ_ij (∂x^i/∂u^j)², the squared
// Frobenius norm of J⁻¹. Two alternatives are offered: Sander et al.'s geometric (L2) stretch
// sqrt((σ1² + σ2²)/2) of J⁻¹ (thesis 4.2.1) and its largest singular value σ1 (L∞ stretch).
// Per-sample badness values go through the same aggregates as the 2D footprints.
//
// Weights: every aggregate accepts optional non-negative per-sample weights w (e.g. pixel areas
// or importance). Weighted forms: L1 = Σ w f, L2 = Σ w f², mean = Σ w f / Σ w, σ² = Σ w (f-mean)²/Σ
// w, median = weighted median, L∞ = max over samples with w > 0. Unweighted is w ≡ 1.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace lexel {

// Aggregates of per-sample footprints (or 3D badness values); the columns of the thesis tables.
struct FootprintStats {
    std::size_t count = 0;       // samples with positive weight
    double weightSum = 0.0;      // Σ w (== count when unweighted)
    double l1 = 0.0;             // Σ w f
    double l2 = 0.0;             // Σ w f²
    double linf = 0.0;           // max f (the thesis's "Worst")
    double average = 0.0;        // Σ w f / Σ w
    double sigma = 0.0;          // population standard deviation
    double meanPlusSigma = 0.0;  // average + sigma (the thesis's "Mean+σ")
    double median = 0.0;         // (weighted) median
    double worst() const { return linf; }
};

// Aggregates f (and optional weights of the same length). Throws std::invalid_argument on a NaN, a
// negative footprint, a negative weight, or mismatched lengths. An empty input gives all zeros.
FootprintStats SummarizeFootprints(std::span<const double> footprints,
                                   std::span<const double> weights = {});
// The same for unit weights without a copy: the median reorders `footprints` (nth_element).
FootprintStats SummarizeFootprintsInPlace(std::span<double> footprints);

// The three norms the optimizers minimize (ch. 2.1).
enum class Metric { kL1, kL2, kLinf };
std::string_view MetricName(Metric metric);                // "l1", "l2", "linf"
std::optional<Metric> ParseMetric(std::string_view name);  // nullopt for an unknown name

// 3D badness of one sample from J = ∂u/∂x (texels per pixel).
enum class Badness {
    kFrobeniusInverseSquared,  // Σ_ij (∂x^i/∂u^j)² = ||J⁻¹||_F², Chong & Gortler eq. (6)
    kGeometricStretch,         // sqrt((σ1² + σ2²)/2) of J⁻¹, Sander et al. 2001 L2 stretch
    kLargestSingularValue,     // σ1 of J⁻¹, Sander et al. L∞ stretch
};

// Singular values (σ1 ≥ σ2 ≥ 0) of a 2×2 matrix in closed form.
Eigen::Vector2d SingularValues2x2(const Eigen::Matrix2d& m);

// Badness of J⁻¹ computed from J. A singular J (a pixel direction that maps to zero texels)
// has an unbounded footprint and returns +infinity, never NaN.
double JacobianBadness(const Eigen::Matrix2d& texelsPerPixel, Badness badness);

}  // namespace lexel
