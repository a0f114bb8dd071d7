// The optimization samples of Chong & Gortler's Algorithm 1 (report §2.3 step 3, §2.4, Fig. 2)
// and the energy h(P) of eq. (6) over them.
//
// Every visible receiver point of the readback is a "relevant point" that must land in the map.
// Per light, the pixels near shadow boundaries — a pixel whose 8-neighbourhood holds both a lit
// and a shadowed receiver facing the light, under a standard (focused) shadow map — are the
// samples h is summed over; their screen → light-space derivatives come from the readback
// (Appendix A, readback.h).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "lexel/solvers/footprint_metrics.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/readback.h"

namespace lexel::spatial {

// A readback pixel's shadow decision under one light's map. Only kLit and kShadowed receivers take
// part in boundary detection: kFacingAway marks receivers whose normal faces away from the light
// (in attached shadow for every map), kEmpty pixels that see nothing.
enum class Shade : std::uint8_t { kEmpty = 0, kLit = 1, kShadowed = 2, kFacingAway = 3 };

// The samples of one light.
struct LightSamples {
    std::vector<glm::dvec3> lsX;           // boundary samples (then contacts) in light space
    std::vector<glm::dvec3> dXdx1, dXdx2;  // ∂X/∂x¹, ∂X/∂x² at each
    std::vector<std::uint32_t> pixel;      // readback pixel of each
    std::vector<glm::dvec3> wsX;           // the world point of each
    // The unit normal of the shadow edge at each sample in readback pixels (x¹ = column, x² =
    // row, as ∂X/∂x^j), pointing from lit to shadowed: the Sobel gradient of the shadowed
    // indicator over the 3×3 neighbourhood (EdgeNormalAt). (0, 0) where that gradient vanishes
    // (no defined edge direction). Empty when the samples were made without the shades
    // (LightSamplesAtPixels without them, or by hand): the edge energy (energy.h) then treats
    // every sample as having no normal.
    std::vector<glm::dvec2> edgeNormal;
    std::vector<glm::dvec3> lsRelevant;  // every visible point in light space
    // The readback's wsRelevantHull in light space: generators of the cone of lsRelevant, all
    // the optimizer needs of it (optimizer.h). Empty (samples built by hand): it uses lsRelevant.
    std::vector<glm::dvec3> lsRelevantHull;
    std::size_t boundaryPixels = 0;  // boundary pixels before rejecting non-smooth ones
    // How many of the samples, the last ones, are thin-shadow contacts (ThinShadowContacts) rather
    // than boundary pixels: 0 for samples made without the shades, built by hand or split
    // among cascades (partitions.h), where every sample counts alike.
    std::size_t contactSamples = 0;
    // The footprint prior's points (energy.h): up to kPriorPoints relevant pixels with reliable
    // derivatives, evenly strided in pixel order, in light space with ∂X/∂x^j as for the
    // samples. Only receivers that need the map count: with the shades, kLit and kShadowed
    // pixels (a receiver facing away is in attached shadow under every map); without them,
    // every smooth covered pixel. Empty for samples built by hand: no prior, no collapse guard.
    std::vector<glm::dvec3> lsPrior, priorDXdx1, priorDXdx2;
    std::vector<glm::dvec3> wsPrior;  // their world points (partitions assign them by these)
};

// The most points the footprint prior keeps per light. The prior only has to rank maps by their
// footprint over the view, so 64 points spread over it (every k-th in pixel order) suffice; on the
// walkthrough 256 made optimal's searches on e 2.4 times h's (spatial_bench MultiStartEdge, one
// core), 64 make them 1.7 times.
inline constexpr std::size_t kPriorPoints = 64;

// A thin shadow's contact. Where a receiver in cast shadow touches a surface facing away from the
// light (in attached shadow), the cast shadow beside the contact is a band whose width, per unit
// of the caster's extent from the contact line, is |n_c·l| / |n_r·l| (n_c, n_r the caster's and
// the receiver's unit normals, l the unit direction to the light; derivation in samples.cpp).
// Below kThinShadowRatio the band is narrower than a tenth of what casts it: a texel that reaches
// across it from the lit receiver beyond lights it, as at a lit–shadowed edge. BoundaryPixels
// cannot see that edge when the band's lit side is out of view (both sides in the image are
// dark), so the band's pixels become samples of their own: Chong & Gortler's Algorithm 1
// samples where the map decides, and it decides there too. Measured on the shipped sets
// (RESULTS.md, "Thin shadows at contacts"): with 0.1 (and `optimal`'s view guard, optimizer.h)
// the courtyard's directional light 93 misclassifies 0 pixels (67.6 without) and no set moves
// beyond its noise; every shadowed receiver beside a facing-away one (no ratio), or beside one
// merely grazed (|n_c·l| < 0.2), cost the courtyard's point lights 1.5–2.3%.
inline constexpr double kThinShadowRatio = 0.1;
// A contact is one in space, not where a facing-away surface occludes a receiver behind it in the
// image: the two pixels' points lie within this many of the receiver pixel's footprints
// (max ||∂W/∂x^j||, world units per pixel) of each other.
inline constexpr double kContactReach = 3.0;

// The width of the shadow a plane casts on a plane it meets, per unit of the caster's extent from
// the contact line: |n_c·l| / |n_r·l| (the comment above; unit normals, `toLight` the unit
// direction to the light). +inf where the light grazes the receiver (n_r·l = 0); NaN where it
// grazes both.
double ThinShadowWidth(const glm::dvec3& casterNormal, const glm::dvec3& receiverNormal,
                       const glm::dvec3& toLight);

// The thin-shadow contacts of an image of shadow decisions, ascending: kShadowed pixels with
// reliable derivatives (readback.smooth) that have an 8-neighbour kFacingAway in contact
// (kContactReach) that casts a thin shadow on it: ThinShadowWidth below kThinShadowRatio. `shades`
// as for BoundaryPixels (std::invalid_argument otherwise). Without normals (wsNormal 0) none.
std::vector<std::uint32_t> ThinShadowContacts(const Readback& readback,
                                              const LightSpace& lightSpace,
                                              std::span<const Shade> shades);

// The samples as Chong & Gortler's report defines them: without the thin-shadow contacts
// (LightSamples::contactSamples). `optimal-report` and `optimal-shear` run on these.
LightSamples PublishedSamples(const LightSamples& samples);

// Boundary samples from the readback's shadow decisions `shades` (ShadePixels over
// readback.buffer with a standard shadow map): LightSamplesAtPixels over BoundaryPixels.
LightSamples MakeLightSamples(const Readback& readback, const LightSpace& lightSpace,
                              std::span<const Shade> shades);

// At most `maxSamples` of the boundary samples: those whose readback pixels have the least fixed
// priority (ThinningPriority, a hash of the pixel), in their order, each with its derivatives,
// pixel, world point and edge normal — a uniform random subset that is the same for the same
// pixels, so the mean energy per kept sample estimates the mean over all samples without bias,
// along edges of every direction alike. Whether a sample is kept depends on its own pixel and the
// budget's threshold alone: readbacks that differ in one boundary pixel (a GPU's and the CPU's,
// or two camera poses) keep sets that differ in at most two samples. The relevant points, their
// hull and the prior's points are kept whole, as is boundaryPixels. All of them when
// n ≤ maxSamples or maxSamples = 0. A finer readback resolves the shadow edges better, but its
// boundary samples grow with its width and the optimizer's time with them; thinned to a budget,
// the samples keep where the edges lie (OptimizerOptions::maxSamples; RESULTS.md).
LightSamples ThinSamples(const LightSamples& samples, std::size_t maxSamples);

// ThinSamples for the optimizer's fit from the hull (OptimizerOptions::hullOnce): the same kept
// samples, and as the relevant points only lsRelevantHull's vertices when there are any. They are
// relevant points and generate the same cone (optimizer.cpp's header comment), so every fit and
// decision of the search is the same, while a fine readback's hundreds of thousands of relevant
// points are not copied per light (at 720² with a budget of 512, copying them took 29% of
// `optimal`'s time per light: spatial_bench FineReadbackBudget).
LightSamples ThinSamplesForSearch(const LightSamples& samples, std::size_t maxSamples);

// ThinSamples' priority of a readback pixel: SplitMix64's finalizer of its index.
std::uint64_t ThinningPriority(std::uint32_t pixel);

// The boundary pixels of an image of shadow decisions, ascending: a kLit or kShadowed pixel with
// an 8-neighbour that is kShadowed or kLit the other way. `shades` is row-major with
// resolution.Count() entries (std::invalid_argument otherwise).
std::vector<std::uint32_t> BoundaryPixels(Resolution resolution, std::span<const Shade> shades);

// The samples at boundary pixels found elsewhere (a GPU pass): `boundaryPixels` ascending and
// inside the readback (std::invalid_argument otherwise). Pixels whose derivatives are not reliable
// (readback.smooth) are dropped and counted in LightSamples::boundaryPixels, as MakeLightSamples
// does: both give the same samples, bit for bit, from the same pixels. With `shades` (the
// readback's decisions the pixels were found in, resolution.Count() entries, else
// std::invalid_argument) the samples get their edge normals, the thin-shadow contacts that are
// not boundary pixels follow them (LightSamples::contactSamples) and the prior takes its
// lit-or-shadowed points, as MakeLightSamples; without them edgeNormal stays empty, there are
// no contacts and the prior takes every smooth covered pixel.
LightSamples LightSamplesAtPixels(const Readback& readback, const LightSpace& lightSpace,
                                  std::span<const std::uint32_t> boundaryPixels,
                                  std::span<const Shade> shades = {});

// The unit normal of the shadow edge at `pixel` in readback pixels (x¹ = column, x² = row),
// pointing from lit to shadowed: the Sobel operator (weights 1, 2, 1 across, ±1 along) on the
// indicator s = 1 for kShadowed, 0 for kLit. A neighbour outside the image is the nearest pixel
// inside (the border replicated, so an edge meeting the border keeps its direction); one neither
// lit nor shadowed takes the centre's value (it says nothing about the edge: a one-sided
// difference). (0, 0) when the gradient vanishes, e.g. a one-pixel-wide line of shadow, whose
// two sides cancel. std::invalid_argument when `shades` does not have resolution.Count() entries
// or `pixel` lies outside.
glm::dvec2 EdgeNormalAt(Resolution resolution, std::span<const Shade> shades, std::uint32_t pixel);

// J = ∂u/∂x at one sample (texels per readback pixel), as (row 1, row 2).
void SampleJacobian(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                    const glm::dvec3& dXdx2, glm::dvec2* row1, glm::dvec2* row2);

// ||J⁻¹||_F² of one sample (eq. 6's summand), or another badness of J⁻¹ (footprint_metrics.h:
// σ₁(J⁻¹) is the most pixels one texel spans): +inf where J is singular or the sample is not in
// front of p4.
double SampleBadness(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                     const glm::dvec3& dXdx2, Badness badness = Badness::kFrobeniusInverseSquared);

// h(P) = Σ over the samples (eq. 6); +inf if any sample is not in front.
double Energy(const LightMatrix& matrix, const LightSamples& samples);

// Energy for many matrices over the same samples (the optimizer's search), bit for bit, with
// three savings that change no value below the bound. The in-front margins 1e-9|X| (InFront) are
// computed once instead of once per matrix. The samples are stored as structure-of-arrays and
// SampleEnergy (energy_gradient.h) runs over blocks of them in a loop without branches, which the
// compiler vectorizes with the same operations per sample, hence the same roundings (as long as
// it contracts no a·b + c into an FMA, which GCC cannot on x86-64 without -mfma); the sum then
// runs in Energy's order. And a caller that only asks whether h is below `bound` gets an early
// stop: every summand is ≥ 0 or +inf and rounded addition is monotone, so the partial sums never
// decrease, and the sum returns as soon as it reaches `bound` with that partial sum (≥ bound).
class BoundedEnergy {
  public:
    explicit BoundedEnergy(const LightSamples& samples);
    // Energy(matrix, samples) when that is < bound; otherwise some value ≥ bound (+inf when a
    // sample is not in front).
    double operator()(const LightMatrix& matrix,
                      double bound = std::numeric_limits<double>::infinity()) const;

  private:
    std::size_t count_;
    std::array<std::vector<double>, 9> soa_;  // X, ∂X/∂x¹, ∂X/∂x², component by component
    std::vector<double> frontMargin_;         // 1e-9 |X| (light-space units)
};

}  // namespace lexel::spatial
