// The minimum-area enclosing parallelogram with one side pair flush with a convex-hull edge: the
// minimum-area rectangle (min_area_rectangle.h) with an exact affine shear.
//
// Chong & Gortler's report (§2.3, Algorithm 1 step 4b-ii, Fig. 3) adds a heuristic shear to the
// minimum-area rectangle: while looping over the hull edges, "check to see if the minimum and
// maximum extents in the current edge direction can be shifted to better line up with the edge's
// endpoints". Here that shear is optimized exactly.
//
// For hull edge a → b let u be its unit direction and v = u rotated +90° (the inward normal of a
// counter-clockwise hull), and give every hull vertex y_i the edge coordinates
//   s_i = u·(y_i - a),  t_i = v·(y_i - a) ≥ 0          (t = 0 on the edge's own line),
// with height H = max t_i. The shear s' = s + k t fixes the edge (t = 0) and the height and slides
// every point along u in proportion to its height. The region s' ∈ [min, max], t ∈ [0, H] is a
// parallelogram (sides along u and along v - k u) of area E(k) · H, where
//   E(k) = max_i (s_i + k t_i) - min_i (s_i + k t_i)
// is a maximum of lines minus a minimum of lines: convex and piecewise linear in k. Its slope is
// t_R - t_L, the heights of the vertices R and L that attain the max and the min. Those change only
// where two adjacent hull vertices j, j+1 tie, at the breakpoint
//   κ_j = (s_j - s_{j+1}) / (t_{j+1} - t_j)      (hull edges not parallel to a → b),
// the edge normal's direction: on the right chain (b up to the top, t rising) R steps j → j+1, on
// the left chain (the top down to a, t falling) L does. As k → -∞ the max is b's (t = 0) and the
// min the top's (t = H): slope -H; each breakpoint adds |t_{j+1} - t_j|, up to +H at k → +∞. So
// E is bounded below and its minimizers form a closed interval [kLo, kHi] that starts at the
// first breakpoint where the slope becomes ≥ 0 and ends at the next one when the slope is exactly
// 0 there (the flat stretch where R = b, L = a: the extent is then |b - a|, the least any shear can
// give). Merging the two chains' breakpoints in increasing k finds it in O(h); among the minimizers
// k* is the one closest to 0 (clamp(0, kLo, kHi)), so an edge that cannot gain keeps k* = 0 and
// its rectangle exactly. A gain under 1e-12 of E(0) counts as none (rounding, e.g. points on a
// rectangle whose sides are perpendicular only to the last bit), so k* = 0 there too. The shear is
// bounded: E(k) ≥ |k| H - E(0) and E(k*) ≤ E(0) give |k*| ≤ 2 E(0) / H, finite whenever H > 0,
// which holds for every edge of a hull of ≥ 3 strictly convex vertices.
//
// The report's rule is a special case. In Fig. 3 both extents of the vertices off the edge lie
// left of the edge's endpoints (min < s_a = 0, max < s_b); shearing right until the leftmost
// off-edge vertex lines up with a is exactly the walk above stopping at the left-chain breakpoint
// where the min passes to a. If no vertex overshoots b on the way, the slope there becomes
// t_b - t_a = 0 and k* is that breakpoint (the plateau's end nearest 0) with extent |b - a|; if
// one does, the exact walk stops earlier, where the overshoot would start to cost more than the
// alignment gains, and the result is never larger than the heuristic's.
//
// Over all edges the least E(k*) · H is the minimum-area enclosing parallelogram of the hull. Some
// minimum has a side pair flush with a hull edge: with one pair's direction θ2 fixed, the strip
// of the other pair, with lines at angle θ, has width w(θ) = d |cos(θ - φ)| while its two
// supporting vertices stay the same (d, φ fixed by them), and the area w(θ) / |sin(θ - θ2)| · w2
// has derivative ∓ d w2 cos(θ2 - φ) / sin²(θ - θ2), of one sign there; so it is least where the
// supporting vertices change, i.e. where θ is a hull-edge direction. For that edge the best other
// direction is the k*-optimal one. (Both pairs can be made flush, and the optimum found in O(h) by
// rotating calipers: C. Schwarz, J. Teich, E. Welzl & B. Evans, 1994 technical report, presented
// with proofs by G. Rote, "The largest contained quadrilateral and the smallest enclosing
// parallelogram of a convex polygon", arXiv:1905.11203, 2019.) Here each edge costs O(h), O(h²)
// in all: h, the hull size, is small in the 3D fitter, and the hull itself is O(n log n).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <span>

#include "lexel/solvers/min_area_rectangle.h"

namespace lexel {

// A parallelogram: center ± halfU axisU ± halfV axisV, with unit axes, axisU × axisV > 0 (the
// axes need not be orthogonal) and half side lengths halfU, halfV ≥ 0.
struct Parallelogram2 {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    Eigen::Vector2d axisU = Eigen::Vector2d::UnitX();  // unit
    Eigen::Vector2d axisV = Eigen::Vector2d::UnitY();  // unit, counter-clockwise of axisU
    double halfU = 0.0;                                // half side length along axisU, ≥ 0
    double halfV = 0.0;                                // half side length along axisV, ≥ 0

    // 4 halfU halfV sin(angle between the axes).
    double Area() const;
    // Counter-clockwise from center - halfU axisU - halfV axisV.
    std::array<Eigen::Vector2d, 4> Corners() const;
    // The dual axes (dualU, dualV): dualU·axisU = dualV·axisV = 1, dualU·axisV = dualV·axisU = 0,
    // so p = center + a axisU + b axisV with a = dualU·(p - center), b = dualV·(p - center).
    std::array<Eigen::Vector2d, 2> DualAxes() const;
    // Whether p = center + a axisU + b axisV has |a| ≤ halfU + tolerance and |b| ≤ halfV +
    // tolerance: tolerance is a distance along the axes, in the units of the coordinates.
    bool Contains(const Eigen::Vector2d& p, double tolerance) const;
};

// The rectangle as a parallelogram (same center, axes and half extents).
Parallelogram2 ToParallelogram(const Rectangle2& r);

// The combinatorics of MinAreaParallelogramOfHull's result, in hull-vertex indices, for a caller
// that re-evaluates (and differentiates) the same construction from moved vertices: the flush
// edge hull[edge] → hull[edge + 1 mod h], the shear k* = (s_j - s_{j+1}) / (t_{j+1} - t_j) with
// j = shearEdge (or k* = 0 when shearEdge = -1), and the vertices attaining min and max of
// s + k* t and max of t. edge = -1 for a hull of fewer than 3 vertices (the rectangle is used).
struct ParallelogramStructure {
    int edge = -1;
    int shearEdge = -1;
    int minS = -1, maxS = -1, top = -1;
    double shear = 0.0;  // k*, the value computed (dimensionless: s per unit of t)
};

// Minimum-area enclosing parallelogram of the points (see above). Ties are broken like
// MinAreaRectangle: the first minimal hull edge in ConvexHull's order wins; axisU is that edge's
// direction and axisV = (v - k* u) / √(1 + k*²). Degenerate input: fewer than 3 hull vertices (one
// distinct point, or all collinear) gives MinAreaRectangle's rectangle, unsheared. Throws
// InputError on no points or a non-finite coordinate.
Parallelogram2 MinAreaParallelogram(std::span<const Eigen::Vector2d> points);

// The same for a hull in ConvexHull's form (validated as MinAreaRectangleOfHull does), optionally
// reporting the structure. Bit-identical to MinAreaParallelogram on the hull's source points.
Parallelogram2 MinAreaParallelogramOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                          ParallelogramStructure* structure = nullptr);

// The least parallelogram with a side pair parallel to hull edge ccwHull[edge] → ccwHull[edge + 1
// mod h], one side on that edge: the per-edge step of MinAreaParallelogramOfHull (k* closest to 0
// among the minimizers of E). The hull is validated as there and must have ≥ 3 vertices, and
// edge < h; InputError otherwise.
Parallelogram2 ParallelogramFlushWithEdge(std::span<const Eigen::Vector2d> ccwHull,
                                          std::size_t edge,
                                          ParallelogramStructure* structure = nullptr);

// The same parallelogram with its longer side on U (longSideOnU) or on V (!longSideOnU), compared
// as side lengths 2 halfU and 2 halfV. When the axes must swap, the pair keeps its orientation:
// axisU' = axisV, axisV' = -axisU, and the half sides swap. An already oriented (or rhombic)
// parallelogram comes back unchanged.
Parallelogram2 OrientLongSideAlong(const Parallelogram2& p, bool longSideOnU);

}  // namespace lexel
