// Temporal hysteresis, Chong & Gortler report Algorithm 1 step 5 and §2.3: across frames, keep the
// previous light matrix unless the new one is a "sufficient improvement" — its median per-sample
// badness Σ_ij (∂x^i/∂u^j)² over the current samples is below 80% of the previous matrix's. The
// previous matrix is first rescaled and shifted so that its map covers the current relevant
// points ("the previous frame's P must include the necessary new scale and shift"): its axis and
// orientation are kept, and the axis-aligned bounds of the relevant points in its map are mapped
// onto [0, W] × [0, H] (with the optimizer's margin).
#pragma once

#include <optional>

#include "lexel/spatial/energy.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

inline constexpr double kSufficientImprovement = 0.8;  // report §2.3 step 5

struct HysteresisDecision {
    LightMatrix matrix;          // what this frame uses
    bool changed = true;         // the candidate replaced the previous matrix
    double medianPrevious = 0;   // median badness of the rescaled previous matrix (+inf if none)
    double medianCandidate = 0;  // median badness of the candidate
};

// Median of SampleBadness over the boundary samples (+inf when there are none in front). With
// kEdge, the median band ||nᵀJ⁻¹|| (energy.h: the edge energy sums its p-th powers, a monotone
// map, so the median sample is the same; +inf behind the plane).
double MedianBadness(const LightMatrix& matrix, const LightSamples& samples,
                     EnergyKind kind = EnergyKind::kReport);

// The previous matrix with its affine part rescaled and shifted (not rotated) to cover every
// relevant point; nullopt when a relevant point is no longer in front of its axis.
std::optional<LightMatrix> RescaleToCover(const LightMatrix& previous, const LightSamples& samples,
                                          Resolution map, double margin);

// The report's decision on MedianBadness of `kind`. The threshold is kSufficientImprovement on
// h's squared footprints, and its square root on e's linear ones (√0.8 ≈ 0.894): the same
// improvement in texel area either way.
HysteresisDecision ApplyHysteresis(const std::optional<LightMatrix>& previous,
                                   const LightMatrix& candidate, const LightSamples& samples,
                                   Resolution map, double margin,
                                   EnergyKind kind = EnergyKind::kReport);

}  // namespace lexel::spatial
