// The energies a light matrix is optimized for, as one family: Chong & Gortler's h (eq. 6 of the
// technical report, "A Lixel for every Pixel", Eurographics Symposium on Rendering 2004) and the
// edge energy e, each optionally with a footprint prior over all relevant points; and the collapse
// guard of the refinement.
//
//   kReport:  h = Σ_samples ||J⁻¹||_F²                  (texels per pixel)⁻², dimensionless
//   kEdge:    e = Σ_samples ||nᵀJ⁻¹||₂^p                  (readback pixels per pixel of edge)^p
// J = ∂u/∂x in texels per readback pixel at a boundary sample, n the unit normal of the shadow
// edge there in readback pixels (LightSamples::edgeNormal). ||nᵀJ⁻¹|| is how far the edge moves
// across itself, in pixels, per texel of offset of the quantized edge: with a uniform sub-texel
// phase the misclassified band is ||nᵀJ⁻¹||/4 pixels per pixel of edge, so e₁/4 (p = 1) predicts
// the misclassified pixels near the boundary (derivation: energy_gradient.h). The shipped p is
// 5/8 (kDefaultEdgeExponent): a band wider than the shadow it belongs to (a thin leg's, a grazing
// wall's) misclassifies about the shadow's width whatever the texel does, so the measured error
// grows more slowly than the band where bands are wide, and a concave p that credits shrinking
// them less closes more of the gap to the best matrix measured (RESULTS.md, "The edge energy's
// exponent"). A sample without a
// defined normal (the 3×3 Sobel gradient of the shadow decisions vanishes, e.g. a one-pixel
// line of shadow; or samples made without the shades) takes ||J⁻¹||_F/√2, the root mean square
// of ||nᵀJ⁻¹|| over uniformly distributed n: the expected band when the edge could run any way.
// Chosen over the direction of J⁻¹'s largest σ (the worst case, σ₁ ≥ ||J⁻¹||_F/√2) and over
// weight 0 (which would let the search ignore those samples and collapse on them): it keeps
// the sample, in the same units, smooth in p4.
//
// The footprint prior: priorWeight × the mean over LightSamples::lsPrior (up to kPriorPoints of
// the relevant receivers, samples.h) of the energy's own summand with no normal ((||J⁻¹||_F/√2)^p
// for kEdge, ||J⁻¹||_F² for kReport). Its unit is the summand's, and priorWeight counts
// boundary samples: weight 1 weighs the whole view like one boundary sample of the view's mean
// footprint. So it decides the map where there are no samples (every other energy is 0 there and
// the map arbitrary: it then minimizes the mean footprint over the visible receivers), steers
// lights with a handful of samples away from maps that starve the rest of the view, and moves a
// light with hundreds of samples by a fraction of a percent. Prior points with a non-finite
// summand add nothing: J is singular there for every P (the eye ray's plane contains the light
// ray: ∂u/∂X annihilates X, so J = ∂u/∂X·∂X/∂x loses rank exactly when X ∈ span(∂X/∂x)).
#pragma once

#include <limits>
#include <optional>

#include "lexel/spatial/energy_gradient.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

enum class EnergyKind {
    kReport,  // h, eq. (6) as published: today's Algorithm 1
    kEdge,  // e = Σ ||nᵀJ⁻¹||₂^p, the misclassified band's model (EnergyOptions::exponent)
};

// The prior weight of lexel's methods on e (optimal, sdsm-optimal): one boundary sample's worth.
inline constexpr double kDefaultPriorWeight = 1.0;

struct EnergyOptions {
    EnergyKind kind = EnergyKind::kReport;
    double priorWeight = 0.0;  // boundary samples (the header comment); 0: no prior
    // kEdge: each summand (the prior's too) raised to this power, e_p = Σ ||nᵀJ⁻¹||^p. 1 is the
    // error model's sum of bands; p < 1 weighs the widest bands less, as the measured error does
    // where a shadow is thinner than its band (RESULTS.md, "The edge energy's exponent"). kReport:
    // unused. The member's default, 1, is e₁ (what `{EnergyKind::kEdge, w}` gives); lexel's
    // `optimal` uses kEdgeEnergy's kDefaultEdgeExponent.
    double exponent = 1.0;
    // Whether these options give Energy(matrix, samples), h alone, bit for bit.
    bool IsReport() const { return kind == EnergyKind::kReport && priorWeight == 0.0; }
};

// The edge energy's default exponent p: 5/8, the best of p = 1/2, 5/8, 3/4, 7/8 and 1 by the share
// of optimal-h's gap to optimal-oracle closed (RESULTS.md, "The edge energy's exponent"): the
// wide bands of thin shadows and grazing receivers gain less than e₁ credits.
inline constexpr double kDefaultEdgeExponent = 0.625;

// e with the footprint prior: what `optimal`, `optimal-refined`, `sdsm-optimal` and their
// hysteresis minimize (it orders methods as their measured errors better than h).
inline constexpr EnergyOptions kEdgeEnergy{EnergyKind::kEdge, kDefaultPriorWeight,
                                           kDefaultEdgeExponent};

// How the energy falls with a map's texels N at a fixed matrix shape: as N^-k. h sums squared
// footprints (texel areas), k = 1; e_p sums footprint lengths to the power p, k = p/2 (1/2 for
// e). The Lagrange allocation's exponent (lagrange_allocation.h).
inline constexpr double EnergyExponent(const EnergyOptions& energy) {
    return energy.kind == EnergyKind::kEdge ? 0.5 * energy.exponent : 1.0;
}

// The chosen energy over the samples (plus the prior): +inf if a boundary sample is not in front
// of p4 or has a singular J. Energy(matrix, samples) exactly when options.IsReport().
double Energy(const LightMatrix& matrix, const LightSamples& samples, const EnergyOptions& options);

// The prior term alone (0 without prior points or weight).
double PriorEnergy(const LightMatrix& matrix, const LightSamples& samples,
                   const EnergyOptions& options);

// ∂/∂p4 of Energy(matrix, samples, options), p1 and p2 fixed, in closed form
// (EnergyGradientAnalytic exactly when options.IsReport(); EdgeEnergyGradientAnalytic for the
// edge energy and the prior), and the same by Ceres Jets. Samples that are +inf contribute
// nothing, as there.
glm::dvec3 EnergyGradient(const LightMatrix& matrix, const LightSamples& samples,
                          const EnergyOptions& options);
glm::dvec3 EnergyGradientJets(const LightMatrix& matrix, const LightSamples& samples,
                              const EnergyOptions& options);

// The samples of LightSamples as the edge gradients take them (the boundary samples with their
// normals, weight 1; the prior points with no normal, weight priorWeight / |lsPrior|).
WeightedPoints BoundaryPoints(const LightSamples& samples, double exponent);
WeightedPoints PriorPoints(const LightSamples& samples, double priorWeight, double exponent);

// The search's energy: Energy(matrix, samples, options) when below `bound`, else some value
// ≥ bound (+inf where a sample is not in front). BoundedEnergy (samples.h) when
// options.IsReport(), so the search on h is today's, bit for bit. Otherwise the same savings as
// BoundedEnergy, with the same values as Energy bit for bit: the points as structure-of-arrays
// with their in-front margins, the summands in blocks without branches (the edge summand's
// choice between n and no normal made by a 0/1 factor: 1·x + 0·y = x exactly for finite y), the
// samples with the early stop, then the prior (its non-finite terms are skipped; the bound is
// checked after each block). `samples` must outlive the object (Gradient reads it for h).
class SearchEnergy {
  public:
    SearchEnergy(const LightSamples& samples, const EnergyOptions& options);
    double operator()(const LightMatrix& matrix,
                      double bound = std::numeric_limits<double>::infinity()) const;
    // EnergyGradient(matrix, samples, options), bit for bit: for e, its operations in their order
    // in blocks without branches (in the scalar loop, with std::pow for f_e^(p−1), the gradient
    // took 47% of `optimal`'s profile at 720²; packed, `optimal` takes 20% less time: perf and
    // spatial_bench FineReadbackBudget); for h, EnergyGradient itself.
    glm::dvec3 Gradient(const LightMatrix& matrix) const;

    // Points with derivatives, edge normals and in-front margins, component by component.
    struct Points {
        std::size_t count = 0;
        std::vector<double> c[11];  // X, ∂X/∂x¹, ∂X/∂x², n (2), component by component
        std::vector<double> hasNormal, frontMargin;
    };

  private:
    EnergyOptions options_;
    const LightSamples* source_;
    std::optional<BoundedEnergy> report_;
    Points samples_, prior_;
};

// The collapse guard's measure: the mean over the prior points of ||J⁻¹||_F (readback pixels
// per texel), the footprint of the map over the view; nullopt without prior points or where none
// is finite.
std::optional<double> RelevantFootprint(const LightMatrix& matrix, const LightSamples& samples);

// Whether `refined` collapses the map against `start`: its relevant footprint exceeds
// `factor` times the start's (a refinement that drives the energy of a few samples down by
// shrinking their texels while the rest of the view's texels grow). False when either footprint
// is undefined (no prior points: nothing to judge by) or factor ≤ 0 (the guard is off).
bool Collapses(const LightMatrix& start, const LightMatrix& refined, const LightSamples& samples,
               double factor);

}  // namespace lexel::spatial
