// Lexel remapping (Chong 2003, §3.1): the footprint of every sample at any lexel plane angle,
// from one pass at an initial angle.
//
// Derivation (re-derived; the thesis's printed dl/dl'(x) came through PDF extraction).
// Light at L, optical axis at world angle θ (unit a, film direction b = a rotated +90°). A point
// at light angle α lies on the film line at s = tan(α − θ); the tight extents are the extreme
// visible angles α_min, α_max, and the N lexels span them:
//     l = N (tan(α−θ) − tan(α_min−θ)) / W(θ),    W(θ) = tan(α_max−θ) − tan(α_min−θ).
// Hence dl/dα = N sec²(α−θ) / W(θ), and with g = |dp/dα| from the sampling pass
//     f(θ) = |dp/dl| = g W(θ) cos²(α−θ) / N.                                          (R1)
// Take the initial axis θ0 (the normal shadow map's bisector), write x = θ − θ0, t = tan x,
// and T = tan(α − θ0) for each sample, T_hi = tan(α_max − θ0), T_lo = tan(α_min − θ0). Since
// cos(α − θ) = cos(α − θ0) cos x (1 + t T), the cos x factors cancel in (R1) and
//     f(t) = f0 · (1 + tT)² / ((1 + tT_hi)(1 + tT_lo)),                              (R2)
// where f0 is the footprint at θ0. The factor is the thesis's dl/dl'(x):
//     dl/dl'(x) = cos θ_t cos θ_b sec(θ_t−x) sec(θ_b−x) (cos x + sin x tan α)² / cos² α ... ,
// the printed form with tan α = ((1+l) tan θ_t + (1−l) tan θ_b)/2 for l ∈ [−1, 1].
// x is valid (every visible point strictly in front of the film) iff 1 + tT > 0 for every sample,
// i.e. t ∈ (−1/T_hi, −1/T_lo); at both ends the denominator of (R2) vanishes and f → ∞.
//
// The thesis rescales l and dp/dl when a frustum is split (§3.2); building LexelSamples from the
// (α, g) of the wedge's samples is that rescaling done exactly (tests check the equivalence).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "lexel/flatland/sampling.h"

namespace lexel::flatland {

struct LexelSamples {
    double wsAxis0 = 0.0;            // θ0, world radians: the bisector of this sample set's sweep
    double tanLow = 0.0;             // T_lo = tan(α_min − θ0) < 0
    double tanHigh = 0.0;            // T_hi = tan(α_max − θ0) > 0
    double lexels = 1.0;             // N (real-valued so that frusta can be measured at N = 1)
    std::vector<double> tanOffset;   // T_i
    std::vector<double> footprint0;  // f0_i = dp/dl at θ0, pixels per lexel
    std::size_t size() const { return tanOffset.size(); }
};

// Builds the optimizer's samples from light angles α_i (radians, relative to wsAxisRef) and
// g_i = |dp/dα| of one light frustum with N lexels. Requires a sweep in (0, π).
LexelSamples MakeLexelSamples(std::span<const double> lsAngle, std::span<const double> dpdAngle,
                              double wsAxisRef, double lexels);
LexelSamples MakeLexelSamples(const SamplingPass& pass, double lexels);
// MakeLexelSamples(pass, lexels) without the per-sample vectors: θ0, T_lo, T_hi and N only, for
// ValidTInterval and WsAxisFromT on a pass whose samples need not be optimized over.
LexelSamples MakeLexelFrame(const SamplingPass& pass, double lexels);
// As above with the frustum's extents given as light angles [lsLow, lsHigh] (relative to
// wsAxisRef) instead of the samples' own extremes; every angle must lie inside them.
LexelSamples MakeLexelSamples(std::span<const double> lsAngle, std::span<const double> dpdAngle,
                              double wsAxisRef, double lexels, double lsLow, double lsHigh);
// The same, converting the two vectors in place into tanOffset and footprint0 (no copy).
LexelSamples MakeLexelSamples(std::vector<double>&& lsAngle, std::vector<double>&& dpdAngle,
                              double wsAxisRef, double lexels, double lsLow, double lsHigh);

// l_i at θ0, in [0, N].
double LexelCoordinate(const LexelSamples& samples, std::size_t i);

// The open interval of valid t = tan(θ − θ0).
struct ValidInterval {
    double lo, hi;
    bool Contains(double t) const { return t > lo && t < hi; }
};
ValidInterval ValidTInterval(const LexelSamples& samples);

// dl/dl'(t) of (R2) for a sample with offset tangent T.
inline double RemapFactor(double tanOffset, double t, double tanLow, double tanHigh) {
    const double n = 1.0 + t * tanOffset;
    return n * n / ((1.0 + t * tanHigh) * (1.0 + t * tanLow));
}
std::vector<double> RemappedFootprints(const LexelSamples& samples, double t);

double WsAxisFromT(const LexelSamples& samples, double t);  // θ0 + atan t
// t for a lexel plane angle in degrees (the plane's orientation is unsigned; tan has period π).
double TFromLexelPlaneDeg(const LexelSamples& samples, double lexelPlaneDeg);

// Footprints recomputed from scratch in world space at optical axis wsAxis (radians): film
// coordinate s = (d·b)/(d·a) with d = X − L, tight extents, dl/dλ from the segment tangent, and
// dp/dλ from the pass. Independent of (R1)/(R2); used for reporting and to test them.
// Returns nothing when some visible point is not strictly in front of the film.
std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels);
// As above for a frustum bounded by the world rays at angles wsRayLow < wsRayHigh (radians)
// rather than by its samples' extremes.
std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels, double wsRayLow,
                                                         double wsRayHigh);
// As above for the samples pass.samples[indices[k]] only (a frustum's), in that order.
std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         std::span<const std::uint32_t> indices,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels, double wsRayLow,
                                                         double wsRayHigh);

}  // namespace lexel::flatland
