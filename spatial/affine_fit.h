// Internal to lexel::spatial (included by light_matrix.cpp and optimizer.cpp; not installed): the
// affine rows of a fitted light matrix (report §2.3, Algorithm 1 step 4b-ii), written once for
// double (the search) and for Ceres Jets (the refinement differentiates the fit in p4).
#pragma once

#include <algorithm>
#include <cmath>

#include "lexel/solvers/geometry.h"
#include "lexel/spatial/camera.h"

namespace lexel::spatial::detail {

// A fitted frame in the plane p4·X = 1, in PlaneBasis(p4) coordinates y: the map's first row
// reads rowU·y, its second rowV·y (the rectangle's axes, or a parallelogram's dual axes), over
// the extents cU ± halfU and cV ± halfV (cU = rowU·centre, cV = rowV·centre).
template <typename T>
struct PlaneFrame {
    T rowU[2], rowV[2];
    T cU, cV, halfU, halfV;
};

// Smallest half extent of a fit, relative to the larger one: a zero extent (all points collinear
// or equal) gets this sliver so the map stays invertible (dimensionless). Points that all
// coincide get it relative to their distance from the plane's origin, or to 1.
inline constexpr double kSliverFraction = 1e-9;

// The rows p1, p2 that map the frame onto [0, W] × [0, H]: u¹ = W/2 + W/(2 halfU') rowU·(y -
// centre) with halfU' = max(halfU, kSliverFraction · longest) (1 + margin), and likewise u²
// (longest = max(halfU, halfV), or max(|cU|, |cV|, 1) when both are 0). With y = (b1·X,
// b2·X)/(p4·X), multiplying by p4·X gives p1 = (W/2 - kU cU) p4 + kU (rowU.x b1 + rowU.y b2), kU =
// W/(2 halfU'). `margin` is the fraction added to each half extent.
template <typename T>
void AffineRowsFromFrame(const T* p4, const T* b1, const T* b2, const PlaneFrame<T>& f,
                         Resolution map, double margin, T* p1, T* p2) {
    using std::abs, std::max;
    // Points that all coincide have no extent to take a fraction of: their distance from the
    // plane's origin (at least 1) stands in, so that the rows stay finite.
    const T extent = max(f.halfU, f.halfV);
    const T longest = extent > T(0.0) ? extent : max(max(abs(f.cU), abs(f.cV)), T(1.0));
    const T halfU = max(f.halfU, T(kSliverFraction) * longest) * T(1.0 + margin);
    const T halfV = max(f.halfV, T(kSliverFraction) * longest) * T(1.0 + margin);
    const T kU = T(0.5 * map.width) / halfU, kV = T(0.5 * map.height) / halfV;
    const T offsetU = T(0.5 * map.width) - kU * f.cU;
    const T offsetV = T(0.5 * map.height) - kV * f.cV;
    for (int c = 0; c < 3; ++c) {
        p1[c] = offsetU * p4[c] + kU * (f.rowU[0] * b1[c] + f.rowU[1] * b2[c]);
        p2[c] = offsetV * p4[c] + kV * (f.rowV[0] * b1[c] + f.rowV[1] * b2[c]);
    }
}

}  // namespace lexel::spatial::detail
