// Sub-texel phases: where a shadow map's texel grid sits relative to the scene, within one texel.
//
// Moving a map's grid by δ texels (LightMatrix::Shifted, MapWarp::Shifted, a virtual map's
// VirtualMapLayout::phase, every cascade alike) leaves J = ∂u/∂x, h and every proxy unchanged,
// yet moves each quantized shadow edge by up to half a texel across itself: on the shipped scenes
// one light's misclassified pixels vary by 5–15% (coefficient of variation) over δ. A renderer
// does not choose δ (the camera and light move), so lexel measures a method by its mean over K
// phases (Evaluator, EvaluationOptions::phases), and counts a difference between two methods only
// when it exceeds the residual noise of that mean (PhaseNoise).
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lexel::spatial {

// The most phases a case or command may ask for: each costs one shadow pass and one shading of
// the frame per method, so 256 bounds a light's evaluation at 256 times a single measurement.
inline constexpr int kMaxPhases = 256;

// K phases δ_k in [−½, ½)², texels: δ_0 = (0, 0) (the unshifted map, so K = 1 is today's single
// measurement), then Roberts' R2 low-discrepancy sequence δ_k = frac(½ + k (1/g, 1/g²)) − ½, g the
// plastic number (g³ = g + 1): any first K cover the square evenly, and a larger K extends a
// smaller one. With `first` > 0 the `count` phases from δ_first on. std::invalid_argument unless
// count ≥ 1 and first ≥ 0.
std::vector<glm::dvec2> SubTexelPhases(int count, int first = 0);

// The next `count` phases of the same sequence, δ_count … δ_2count−1: as even a cover of the
// square, none of them among SubTexelPhases(count). A search that chooses a map by its measured
// mean (optimal-oracle) scores its candidates on these, so that the mean every method is reported
// at, over SubTexelPhases(count), is not biased by the choice: the minimum over many candidates
// of a noisy mean is lower than the chosen map's true mean (the winner's curse), by an amount
// that grows with the candidates and the noise. std::invalid_argument unless count ≥ 1.
std::vector<glm::dvec2> HeldOutSubTexelPhases(int count);

// The mean of per-phase counts and the standard error of that mean: s / √K with s the sample
// standard deviation over the K phases (0 for K = 1: no estimate).
struct PhaseMean {
    double mean = 0.0;
    double standardError = 0.0;
};
PhaseMean MeanOverPhases(std::span<const std::int64_t> perPhase);

// When an adaptive measurement stops adding phases (the goal: "K chosen so the residual per-light
// variation is below 2%"): once a mean's standard error is at most kPhaseResidual of the mean, or
// at most kPhaseResidualFloor pixels (a light whose mean is a few pixels would otherwise need
// hundreds of phases to pin a difference of under a pixel).
inline constexpr double kPhaseResidual = 0.02;
inline constexpr double kPhaseResidualFloor = 1.0;  // pixels
bool PhaseMeanSettled(const PhaseMean& mean);

// The most phases a mean may be taken over when measured from `phases` (K) with the cap
// `maxPhases`: the cap, or K where the cap is not above it (0: none).
inline int MostPhases(int phases, int maxPhases) { return maxPhases > phases ? maxPhases : phases; }

// A count measured at phases δ_first, δ_first+1, ...: `phases` (K) of them, then, while the mean
// is not settled (PhaseMeanSettled), as many again (2K, 4K, ...) up to `maxPhases`; exactly K when
// maxPhases ≤ K. Every count is of the same sequence, so a method measured at 4K extends its own
// measurement at K and shares its first K phases with every other method on the light.
// `countAt(k, δ_k)` measures phase k. Returns the per-phase counts, in phase order.
// std::invalid_argument unless 1 ≤ phases and first ≥ 0.
std::vector<std::int64_t> CountOverPhases(
    int phases, int maxPhases, int first,
    const std::function<std::int64_t(int k, const glm::dvec2& phase)>& countAt);

}  // namespace lexel::spatial
