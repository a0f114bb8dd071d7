// Partitioned shadow maps: k light matrices, each serving the pixels of one interval of planar eye
// depth (z-partitioning, Lloyd et al. 2006 §5, eqs. 15–16; parallel-split shadow maps, Zhang et
// al. 2006; sample distribution shadow maps, Lauritzen et al. 2011), and how k maps share one
// texel budget: equally (SDSM), or by the Lagrange allocation the thesis uses for light frusta
// (Chong 2003 §3.2) lifted to 3D.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_matrix.h"

namespace lexel::spatial {

// One map of a partitioned method: it serves the pixels whose planar eye depth z lies in
// [zNear, zFar) (world units along the camera's unit view direction).
struct Cascade {
    LightMatrix matrix;
    Resolution map;
    double zNear = 0.0;
    double zFar = std::numeric_limits<double>::infinity();
    // Further world half-spaces n·x + d ≥ 0 it is limited to (face partitioning's wedges); none
    // for z-partitions.
    std::vector<glm::dvec4> wsHalfSpaces;
    std::size_t visiblePoints = 0;  // readback points it serves; 0: an empty partition

    bool Holds(double z, const glm::dvec3& wsPoint) const;
};

// (wsPoint - eye) · v, v the unit view direction: the depth partitions are cut by (Lloyd §5).
double PlanarEyeDepth(const Camera& camera, const glm::dvec3& wsPoint);

// The k + 1 split depths of PSSM over [zNear, zFar]: C_i = λ n (f/n)^(i/k) + (1 - λ)(n + (f - n)
// i/k), i = 0..k; λ = 1 is Lloyd's logarithmic split (eq. 15), λ = 0 the uniform one. The first is
// n and the last f exactly. std::invalid_argument unless 0 < n < f finite, k ≥ 1, λ ∈ [0, 1].
std::vector<double> PssmSplits(double zNear, double zFar, int k, double lambda);

// The cascade serving a world point of planar eye depth z: the first that holds it; when none does
// (a frame pixel nearer or farther than every readback sample) the nearest by depth among those
// whose half-spaces hold the point (or among all), and *covered = false. std::invalid_argument for
// no cascades.
std::size_t CascadeFor(std::span<const Cascade> cascades, double z, const glm::dvec3& wsPoint,
                       bool* covered = nullptr);

enum class CascadeAllocation {
    kEqual,     // k maps of (W/√k) × (H/√k), rounded down (SDSM)
    kLagrange,  // N_i = N c_i^(1/(k+1)) / Σ c_j^(1/(k+1)) for E_i = c_i / N_i^k (the thesis's)
};

// The cascades' resolutions for a budget of total.Count() texels. For kLagrange, costs[i] = c_i ≥
// 0 (E_i · N_i^k measured at any resolution: h scales as 1/N for square maps, k = 1; the edge
// energy e_p as N^(−p/2), k = p/2; EnergyExponent): integer texel counts summing to the budget,
// each cascade with c_i > 0 at least 1 texel, laid out as the squarest map w × h ≤ N_i. A cascade
// with c_i = 0 (an empty partition, or one without boundary samples and prior) gets the 1 × 1
// map. kEqual ignores costs. std::invalid_argument for no cascades or negative or non-finite
// costs.
std::vector<Resolution> AllocateCascadeMaps(Resolution total, std::span<const double> costs,
                                            CascadeAllocation allocation, double exponent = 1.0);

// kLagrange's integer texel counts before the layout: Σ N_i = total.Count(), N_i = 0 for c_i = 0,
// and no single texel moved between two cascades lowers Σ c_i / N_i (lagrange_allocation.h).
// std::invalid_argument as AllocateLexelsInteger (more cascades with c_i > 0 than texels).
std::vector<int> LagrangeCascadeTexels(Resolution total, std::span<const double> costs,
                                       double exponent = 1.0);

// The same light matrix for a map of another resolution: u' = u · (W'/W, H'/H).
LightMatrix RescaleMap(const LightMatrix& matrix, Resolution from, Resolution to);

}  // namespace lexel::spatial
