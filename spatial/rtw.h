// Rectilinear texture warping (P. Rosen, "Rectilinear Texture Warping for Fast Adaptive Shadow
// Mapping", I3D 2012): one shadow map plus two 1-D warping maps, built from an importance map of
// what the camera asks of the light, and the same warps from the thesis's Lagrange allocation
// (H. Chong, "Real-Time Perspective Optimal Shadow Maps", 2003, §3.2: lexels ∝ cost^(1/(k+1))).
//
// The paper's steps (§3–4), as lexel builds them from Algorithm 1's readback:
//   1. importance map — per texel of a base (focused) map, the largest sampling rate the frame
//      pixels landing there ask for. Rosen's backward analysis projects each output pixel into
//      the map and keeps the maximum of an importance function there. Ours is the rate itself:
//      Lloyd et al. 2006's perspective aliasing w_l/w_i under the base map
//      (perspective_aliasing.h), how many frame pixels wide one base texel is there. It leaves
//      out the receiver's orientation (projection aliasing): no warp of the map serves that, and
//      the footprint σ₁(J⁻¹), which includes it, grows without bound where a receiver nears its
//      light ray — a few grazing pixels then took most of the texels (measured: `rtw` on σ₁
//      misclassified +139% against `optimal` on the walkthrough's point lights, on w_l/w_i
//      −27%; RESULTS.md, "What engines ship"). Each readback pixel stands for the frame pixels
//      it covers, so it is splatted over the parallelogram its pixel covers in the map (at most
//      kRtwMaxSplat importance texels from its centre each way). At the shadow boundary pixels
//      of the standard map (samples.h) the importance is multiplied by 1 + kRtwEdgeWeight: the
//      paper's shadow-edge importance function, which raises importance where the output image
//      has shadow edges;
//   2. the 2-D map collapsed to two 1-D maps by the maximum of each column and each row (§4.2);
//   3. each 1-D map blurred (Gaussian, σ = kRtwBlurSigma of its length), so that the warp
//      changes smoothly and the readback's gaps between pixels are covered;
//   4. a floor of kRtwDensityFloor × the mean, so that every base texel keeps some texels and the
//      warp stays invertible; the density is max(blurred, floor);
//   5. the cumulative sums, normalized, as the warps: w(b) = Σ_{i < b} d_i / Σ d (linear within a
//      bin), monotone from w(0) = 0 to w(1) = 1, with texel density d_i / mean(d) in bin i.
// The warped map has the same W × H texels as the base map; map coordinates u = W w(b / W).
//
// What the paper's text in our hands does not fix, and we assumed: the edge weight (4), the blur
// width (σ = 1/180 of the map side: about 2 texels at 400²), the floor (0.1 of the mean), and
// the importance map's resolution (the shadow map's own). They are named constants here and
// options of RtwOptions; the tests check the construction, not these values.
//
// rtw-lagrange replaces steps 1–2 by the thesis's allocation along each axis: a per-sample cost
// separable by map axis, c_x / d_x^k + c_y / d_y^k at local texel densities (d_x, d_y) relative
// to the base map (SeparableCost), summed over the boundary samples in each column and row gives
// that bin's cost C_i; minimizing Σ C_i / d_i^k subject to Σ d_i = n (the same texels) gives
// d_i ∝ C_i^(1/(k+1)) (solvers/lagrange_allocation.h): √C for a cost linear in the footprint
// (k = 1: the thesis's L1, the edge energy e), ∛C for h's squared footprint (k = 2).
// Steps 3–5 are the same.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/map_warp.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

inline constexpr double kRtwEdgeWeight = 4.0;  // importance × (1 + w) at shadow edges (ours)
inline constexpr double kRtwBlurSigma = 1.0 / 180.0;  // of the 1-D map's length (ours)
inline constexpr double kRtwDensityFloor = 0.1;       // of the mean density (ours)
inline constexpr int kRtwMaxSplat = 16;               // importance texels from a pixel's centre

struct RtwOptions {
    double edgeWeight = kRtwEdgeWeight;
    double blurSigma = kRtwBlurSigma;
    double densityFloor = kRtwDensityFloor;
};

// A 2-D map of non-negative values over a map's texels, row-major (row 0 at v = 0).
struct ImportanceMap {
    Resolution resolution;
    std::vector<double> value;
};

// Per column (x) and per row (y) of a map: 1-D importance, cost or density.
struct AxisProfile {
    std::vector<double> x, y;
};

// Step 1 over the readback: for every covered readback pixel whose point is InFront of `base`,
// its rate w_l/w_i (PerspectiveAliasing under `base`, against the pixels of a `frame`-sized image
// of the same camera), × (1 + options.edgeWeight) at `edgePixels` (readback pixel indices),
// max-splatted over the pixel's parallelogram in an importance map of base's resolution `map`.
// The parallelogram comes from the pixel's derivatives: PlaneDerivatives' (exact on the pixel's
// plane), or the readback's where it has no normal and is smooth; pixels with neither, or where
// the map is singular, are left out.
ImportanceMap RtwImportance(const Readback& readback, const Camera& camera,
                            const LightSpace& lightSpace, const LightMatrix& base, Resolution map,
                            Resolution frame, std::span<const std::uint32_t> edgePixels,
                            const RtwOptions& options = {});

// Step 2: the maximum of each column (x) and each row (y).
AxisProfile RowColumnMaxima(const ImportanceMap& importance);

// Step 3: a Gaussian of standard deviation `sigma` bins (truncated at 3σ, renormalized at the
// ends); sigma ≤ 0 returns the values unchanged.
std::vector<double> GaussianBlur(std::span<const double> values, double sigma);

// Step 4: max(v_i, floor · mean(v)); all ones when v is all zero (no information: no warp).
std::vector<double> FlooredDensity(std::span<const double> values, double floor);

// Step 5: the warp's knot values w_0 = 0, w_i = Σ_{j<i} d_j / Σ d, w_n = 1 (n = d.size() ≥ 1,
// d_j > 0). Strictly increasing.
std::vector<double> CumulativeWarp(std::span<const double> density);

// Steps 3–5 for both axes of a W × H base map: the MapWarp u = (W w_x(b_x / W), H w_y(b_y / H)).
// profile.x has one bin per base column range (any count ≥ 1), profile.y per row range.
MapWarp RectilinearWarp(const LightMatrix& base, Resolution map, const AxisProfile& profile,
                        const RtwOptions& options = {});

// The per-sample cost of rtw-lagrange (the header comment): terms(k, c1, c2) = (c_x, c_y) of
// sample k, where c1, c2 are the columns of J⁻¹ under the base map (readback pixels per base
// texel along map x and y); with densities (d_x, d_y) the sample costs c_x/d_x^k + c_y/d_y^k.
struct SeparableCost {
    int exponent = 2;  // k
    std::function<glm::dvec2(std::size_t sample, const glm::dvec2& c1, const glm::dvec2& c2)> terms;
};
// h's per-sample term (eq. 6): ‖J⁻¹ D⁻¹‖_F² = |c1|²/d_x² + |c2|²/d_y², exactly; k = 2.
SeparableCost EnergyHCost();

// Each column's and row's summed cost over the samples (bins of `bins` over the W × H base map);
// samples off the base map or with a singular J are left out.
AxisProfile LagrangeAxisCosts(const LightSamples& samples, const LightMatrix& base, Resolution map,
                              Resolution bins, const SeparableCost& cost);
// The Lagrange densities per axis: d_i = n C_i^(1/(k+1)) / Σ C^(1/(k+1)) (all zero without cost).
AxisProfile LagrangeDensities(const AxisProfile& costs, int exponent);

}  // namespace lexel::spatial
