// The light matrix P of Chong & Gortler (report §2.1, Fig. 1), the rows that matter to sampling.
//
// In light space P = [p1ᵀ 0; p2ᵀ 0; (row 3, free: depth is stored linearly); p4ᵀ 0], so a
// light-space point X lands on the shadow map at u^i = (p_i · X) / (p4 · X), i = 1, 2, in texels.
// p4 is the unit optical axis (the projective freedom, 2 DOF); p1, p2 carry the 6 affine
// freedoms, which act as a 2D affine map of the shadow-map domain (report eq. 3). A point is
// usable only strictly in front of the plane p4 · X = 0: behind it, it maps through infinity.
//
// World form: with X = A [x; 1] (LightSpace), the 4×4 "map from world" P·A has rows p1ᵀA, p2ᵀA,
// 0, p4ᵀA; FromScreenRows goes back from such rows, which is how the baselines built as classic
// 4×4 view/projection products (LiSPSM, PSM) become LightMatrix values.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "lexel/solvers/geometry.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial {

struct LightMatrix {
    glm::dvec3 p1{1, 0, 0}, p2{0, 1, 0}, p4{0, 0, 1};

    // (p1·X, p2·X, p4·X): u = xy / z where z > 0.
    glm::dvec3 Homogeneous(const glm::dvec3& lsX) const {
        return {glm::dot(p1, lsX), glm::dot(p2, lsX), glm::dot(p4, lsX)};
    }
    glm::dvec2 Map(const glm::dvec3& lsX) const {
        const glm::dvec3 h = Homogeneous(lsX);
        return {h.x / h.z, h.y / h.z};
    }
    // The light-space direction X with Map(X) = u and p4·X = 1 (M⁻¹ (u, 1), M = [p1; p2; p4]).
    glm::dvec3 Unmap(glm::dvec2 u) const;
    // ∂u/∂X at X (2×3 as two rows): ∂u^i/∂X = (p_i - u^i p4) / (p4·X).
    void MapJacobian(const glm::dvec3& lsX, glm::dvec3* du1dX, glm::dvec3* du2dX) const;
    // M = [p1; p2; p4] as a glm matrix (column-major: M[c][r]).
    glm::dmat3 Rows() const;
    // The same map after a 2D affine change of map coordinates u' = a · (u, 1)
    // (a: 3×3 with last row (0, 0, 1)).
    LightMatrix ThenAffine(const glm::dmat3& a) const;
};

// The LightMatrix equal to a world-space 4×4 whose rows 1, 2, 4 send world points to texels
// (u^i = row_i·[x;1] / row_4·[x;1]); row 3 is ignored. The rows must annihilate the light (send it
// to infinity, report Fig. 1, relative tolerance 1e-9); nullopt otherwise, with the reason in
// *failure when given. The result is scaled so that |p4| = 1 and p4 · X > 0 at `wsCenter`.
std::optional<LightMatrix> FromScreenRows(const LightSpace& lightSpace,
                                          const glm::dmat4& screenFromWorld,
                                          const glm::dvec3& wsCenter,
                                          std::string* failure = nullptr);

// Whether X is strictly in front of the plane p4·X = 0, with a relative margin: p4·X > ε|X| where
// ε = 1e-9 (dimensionless; guards against points on the horizon that would map to ±huge texels).
bool InFront(const glm::dvec3& p4, const glm::dvec3& lsX);

struct FitOptions {
    // Fraction added to each half-extent of the fitted rectangle (report §2.4: the subsampled
    // readback makes a tight fit slightly too aggressive). 0 for an exact fit.
    double margin = 0.0;
    // The report's optional affine shear (§2.3 step 4b-ii, Fig. 3), optimized exactly: the
    // minimum-area enclosing parallelogram instead of the rectangle (see FitMapToPoints). false
    // keeps the rectangle fit bit for bit.
    bool shear = false;
};

// The affine freedoms for optical axis p4 (report Algorithm 1 step 4b-ii): project the points
// centrally onto the plane p4·X = 1, take the minimum-area rectangle around their convex hull
// (Freeman & Shapira; solvers/min_area_rectangle), lay its longer side along the map's longer
// dimension and map it onto [0, width] × [0, height]. Returns nullopt when a point is not strictly
// in front (InFront) or there are no points. A rectangle of zero width is given a width of 1e-9
// of its length so the map stays invertible.
//
// With options.shear the rectangle becomes a parallelogram. The report (§2.3, Fig. 3) shears
// heuristically: for each hull edge's rectangle, "check to see if the minimum and maximum extents
// in the current edge direction can be shifted to better line up with the edge's endpoints"; in
// Fig. 3 the off-edge points all lie left of the edge's extents and are sheared right until the
// leftmost one lines up with the edge's left end. Exactly: for hull edge e with unit direction u
// and inward normal v, in the edge coordinates s = u·y, t = v·y - lo ≥ 0 (the edge on t = 0),
// the shear s' = s + k t keeps the edge and the height H fixed, and the extent E(k) of the hull
// in s' is convex and piecewise linear in k. Its minimum lies at a breakpoint where two adjacent
// hull vertices tie for the max or the min (a flat stretch of minimizers contains k = 0 or ends
// at such a breakpoint); it is found exactly (solvers/min_area_parallelogram.h, which also shows
// that the report's rule is the special case where lining up with the edge's endpoint is that
// breakpoint, and that |k*| ≤ 2 E(0) / H, finite because H > 0 for every edge of a hull of ≥ 3
// vertices). Of the minimizers the one closest to 0 is taken, so an edge that cannot gain keeps
// its rectangle. The edge with the least E(k*) H wins, which makes the result the minimum-area
// enclosing parallelogram. The shear enters the 2D affine map through the map row that reads
// along the edge: s' = (u + k v)·y, so that row (p1, or p2 after a long-side swap) gains a
// component along the v direction, while the other still reads v·y.
//   - Long side: the parallelogram's longer side (side lengths E and H √(1 + k²)) goes on the
//     map's longer dimension, as the rectangle's does. Of the two assignments this one has the
//     smaller ||M||_F, M the inverse linear part of the 2D map (columns: the side vectors over
//     the texel counts W, H_map on their map axes): E²/W² + H²(1 + k²)/H_map² against the swap.
//   - Margin: both half sides grow by the same fraction, i.e. the parallelogram is scaled about
//     its centre, exactly as the rectangle is.
//   - Degenerate hulls (1 or 2 distinct projected points, all collinear): the unsheared fit,
//     sliver included; the shear is never NaN or infinite.
// The sheared fit jumps with p4 more often than the rectangle fit does: near a minimum flush with
// hull edges on both side pairs, the two hull edges next to one of them give parallelograms of
// nearly equal area but different shear, and which one wins flips as p4 moves (an area tie is a
// jump for the rectangle too, but its candidates differ more). h differs between such twins by
// several percent: the area the shear minimizes is not the h it is meant to serve. The report finds
// the shear of "minimal benefit in practice"; README.md has this toolkit's measurement (method
// optimal-shear).
std::optional<LightMatrix> FitMapToPoints(const glm::dvec3& p4,
                                          std::span<const glm::dvec3> lsPoints, Resolution map,
                                          const FitOptions& options = {});

// The same fit from points already on the plane p4·X = 1, in the orthonormal plane basis
// (b1, b2) returned by PlaneBasis(p4): y = (b1·X, b2·X) / (p4·X).
std::optional<LightMatrix> FitMapToPlanePoints(const glm::dvec3& p4,
                                               std::span<const glm::dvec2> planePoints,
                                               Resolution map, const FitOptions& options = {});

}  // namespace lexel::spatial
