// The light matrix P of Chong & Gortler (report §2.1, Fig. 1), the rows that matter to sampling.
//
// In light space P = [p1ᵀ 0; p2ᵀ 0; (row 3, free: depth is stored linearly); p4ᵀ 0], so a
// light-space point X lands on the shadow map at u^i = (p_i · X) / (p4 · X), i = 1, 2, in texels.
// p4 is the unit optical axis (the projective freedom, 2 DOF); p1, p2 carry the 6 affine
// freedoms, which act as a 2D affine map of the shadow-map domain (report eq. 3). A point is
// usable only strictly in front of the plane p4 · X = 0: behind it, it maps through infinity.
//
// World form: with X = A [x; 1] (LightSpace), the 4×4 "map from world" P·A has rows p1ᵀA, p2ᵀA,
// 0, p4ᵀA (MapFromWorld, clip_matrix.h); FromScreenRows goes back from such rows, which is how
// the baselines built as classic
// 4×4 view/projection products (LiSPSM, PSM) become LightMatrix values.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

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
    // The same map with its texel grid moved by `texels`: u' = u + texels (p_i += texels_i p4).
    // A sub-texel phase (|texels| < 1) changes which texel a point lands in, not J.
    LightMatrix Shifted(const glm::dvec2& texels) const {
        return {p1 + texels.x * p4, p2 + texels.y * p4, p4};
    }
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

// The matrix with its map scaled and shifted along its own axes (not rotated) so that the
// axis-aligned bounds of the points' images, each half extent grown by `margin`, fill
// [0, W] × [0, H] texels. nullopt when a point is not InFront of p4 or there are none. A zero
// extent gets a sliver of 1e-12 map units.
std::optional<LightMatrix> ScaleMapToCover(const LightMatrix& matrix,
                                           std::span<const glm::dvec3> lsPoints, Resolution map,
                                           double margin);

// The central projections y = (b1·X, b2·X) / (p4·X) of the points onto the plane p4·X = 1, in the
// basis PlaneBasis(p4) FitMapToPlanePoints expects; nullopt when a point is not InFront of p4.
std::optional<std::vector<glm::dvec2>> ProjectToPlaneInFront(const glm::dvec3& p4,
                                                             std::span<const glm::dvec3> lsPoints);

struct FitOptions {
    // Fraction added to each half-extent of the fitted rectangle (report §2.4: the subsampled
    // readback makes a tight fit slightly too aggressive). 0 for an exact fit.
    double margin = 0.0;
    // The report's optional affine shear (§2.3 step 4b-ii, Fig. 3), optimized exactly: the
    // minimum-area enclosing parallelogram instead of the rectangle (see FitMapToPoints). false
    // keeps the rectangle fit bit for bit.
    bool shear = false;
    // FitMapBoxToPoints only: when > 0 (in plane units), every half extent, margin included, is
    // rounded up to snapUnit · 2^m and the centre to a whole texel, so that a camera moving in a
    // fixed direction shifts the map by whole texels and its shadows do not shimmer (SDSM §5.3;
    // meaningful for directional lights, whose plane units are world units over the frame's s).
    double snapUnit = 0.0;
};

// The affine freedoms for optical axis p4 (report Algorithm 1 step 4b-ii; Brabec et al. 2002):
// project the points centrally onto the plane p4·X = 1, take the minimum-area rectangle around
// them (solvers/min_area_rectangle.h), lay its longer side along the map's longer dimension and
// map it, grown by options.margin, onto [0, width] × [0, height] texels. With options.shear the
// minimum-area enclosing parallelogram instead (the report's Fig. 3 shear, exact; the rows and
// their long-side rule in light_matrix.cpp). A zero extent gets a sliver (1e-9 of the other) so
// the map stays invertible (points that all project to one point get one of 1e-9 of their
// distance from the plane's origin, or of 1). nullopt when a point is not InFront of p4, there
// are no points, or the rows would not be finite.
std::optional<LightMatrix> FitMapToPoints(const glm::dvec3& p4,
                                          std::span<const glm::dvec3> lsPoints, Resolution map,
                                          const FitOptions& options = {});

// The axis-aligned box instead of the minimum-area rectangle, its first map axis along the unit
// plane direction `axisU` (in PlaneBasis(p4) coordinates), the second turned +90° from it: the
// light-space bounding box of SDSM (Lauritzen et al. 2011 §4), grown by options.margin (and
// snapped with options.snapUnit), with a 1e-9 sliver for a zero extent. options.shear is ignored.
// nullopt as FitMapToPoints.
std::optional<LightMatrix> FitMapBoxToPoints(const glm::dvec3& p4, const glm::dvec2& axisU,
                                             std::span<const glm::dvec3> lsPoints, Resolution map,
                                             const FitOptions& options = {});

// The same fit from points already on the plane p4·X = 1, in the orthonormal plane basis
// (b1, b2) returned by PlaneBasis(p4): y = (b1·X, b2·X) / (p4·X).
std::optional<LightMatrix> FitMapToPlanePoints(const glm::dvec3& p4,
                                               std::span<const glm::dvec2> planePoints,
                                               Resolution map, const FitOptions& options = {});

}  // namespace lexel::spatial
