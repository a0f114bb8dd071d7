// The minimum-area enclosing parallelogram flush with a hull edge (min_area_parallelogram.h).
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
#include "lexel/solvers/min_area_parallelogram.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"
#include "lexel/solvers/min_area_rectangle.h"

namespace lexel {

namespace {

// One candidate: the least parallelogram flush with hull edge i → i+1 (h ≥ 3, strictly convex,
// counter-clockwise), by the breakpoint walk of the header comment. `s` and `t` are scratch of
// size h.
struct EdgeCandidate {
    Parallelogram2 parallelogram;
    ParallelogramStructure structure;
    double area = 0.0;
};

EdgeCandidate FitEdge(std::span<const Eigen::Vector2d> hull, std::size_t i, std::vector<double>& s,
                      std::vector<double>& t) {
    const std::size_t h = hull.size();
    const auto next = [h](std::size_t k) { return k + 1 == h ? 0 : k + 1; };
    const std::size_t iB = next(i);
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d edge = hull[iB] - a;
    const Eigen::Vector2d u = edge / std::hypot(edge.x(), edge.y());
    const Eigen::Vector2d v = Perp(u);
    // Edge coordinates relative to a (far-from-origin clouds keep their low digits). The edge's
    // own endpoints are put exactly on t = 0, so that the stretch where b and a attain the max and
    // the min has slope exactly 0 below.
    double height = 0.0;
    std::size_t top = iB;
    for (std::size_t k = 0; k < h; ++k) {
        const Eigen::Vector2d d = hull[k] - a;
        s[k] = d.dot(u);
        t[k] = (k == i || k == iB) ? 0.0 : d.dot(v);
        if (t[k] > height) height = t[k], top = k;
    }

    // Breakpoints of hull edge j → j+1: where its endpoints tie in s + k t. Edges rising in t
    // form the right chain (the max passes j → j+1), falling ones the left chain (the min does);
    // edges parallel to the base (equal t) never change an extreme. Both chains are walked in
    // counter-clockwise order from b, which is increasing k along each (convexity).
    const auto breakpoint = [&](std::size_t j) {
        return (s[j] - s[next(j)]) / (t[next(j)] - t[j]);
    };
    const auto rising = [&](std::size_t j) {
        return t[next(j)] > t[j] && std::isfinite(breakpoint(j));
    };
    const auto falling = [&](std::size_t j) {
        return t[next(j)] < t[j] && std::isfinite(breakpoint(j));
    };
    // Next edge of a chain at or after j, stopping at the base edge i (no more breakpoints).
    const auto seek = [&](std::size_t j, bool right) {
        while (j != i && !(right ? rising(j) : falling(j))) j = next(j);
        return j;
    };
    std::size_t r = seek(iB, true), l = seek(iB, false);
    std::size_t argMax = iB;               // b attains the max as k → -∞ ...
    std::size_t argMin = l == i ? iB : l;  // ... and the top-most, left-most vertex the min
    double kLo = 0.0, kHi = 0.0;
    std::ptrdiff_t loEdge = -1, hiEdge = -1;
    bool stepped = false;
    // Slope of E between breakpoints: t_R - t_L. Walk up to the first breakpoint after which it
    // is ≥ 0: E's minimum.
    while (t[argMax] - t[argMin] < 0.0 && (r != i || l != i)) {
        const bool takeRight = l == i || (r != i && breakpoint(r) <= breakpoint(l));
        const std::size_t j = takeRight ? r : l;
        kLo = breakpoint(j);
        loEdge = static_cast<std::ptrdiff_t>(j);
        stepped = true;
        if (takeRight) {
            argMax = next(r);
            r = seek(next(r), true);
        } else {
            argMin = next(l);
            l = seek(next(l), false);
        }
    }
    kHi = kLo;
    hiEdge = loEdge;
    if (stepped && t[argMax] - t[argMin] == 0.0 && (r != i || l != i)) {
        // Flat stretch: every k up to the next breakpoint is optimal too.
        const bool takeRight = l == i || (r != i && breakpoint(r) <= breakpoint(l));
        const std::size_t j = takeRight ? r : l;
        kHi = breakpoint(j);
        hiEdge = static_cast<std::ptrdiff_t>(j);
    }
    // Of the minimizers [kLo, kHi], the one closest to 0: no shear when the rectangle is already
    // optimal for this edge.
    EdgeCandidate c;
    double k = 0.0;
    if (stepped && kLo > 0.0) {
        k = kLo;
        c.structure.shearEdge = static_cast<int>(loEdge);
    } else if (stepped && kHi < 0.0) {
        k = kHi;
        c.structure.shearEdge = static_cast<int>(hiEdge);
    }

    // The extents at k over all vertices, whatever rounding did to the walk: the parallelogram
    // always encloses the hull.
    struct Extents {
        double lo, hi;
        std::size_t argLo, argHi;
    };
    const auto extentsAt = [&](double shear) {
        Extents e{s[i], s[i], i, i};
        for (std::size_t q = 0; q < h; ++q) {
            const double sq = s[q] + shear * t[q];
            if (sq < e.lo) e.lo = sq, e.argLo = q;
            if (sq > e.hi) e.hi = sq, e.argHi = q;
        }
        return e;
    };
    Extents e = extentsAt(k);
    if (k != 0.0) {
        // A gain below 1e-12 of the extent is a tie (the extents carry rounding of ~1e-16 of
        // themselves; e.g. a rectangle of points whose sides are perpendicular only to rounding):
        // the tie goes to k = 0, as among exact minimizers.
        const Extents e0 = extentsAt(0.0);
        if (e.hi - e.lo >= (1.0 - 1e-12) * (e0.hi - e0.lo)) {
            k = 0.0;
            c.structure.shearEdge = -1;
            e = e0;
        }
    }
    const double sLo = e.lo, sHi = e.hi;
    const std::size_t minS = e.argLo, maxS = e.argHi;
    c.area = (sHi - sLo) * height;
    c.structure.edge = static_cast<int>(i);
    c.structure.minS = static_cast<int>(minS);
    c.structure.maxS = static_cast<int>(maxS);
    c.structure.top = static_cast<int>(top);
    c.structure.shear = k;
    // s' = s + k t ∈ [sLo, sHi], t ∈ [0, H]: sides along u (length sHi - sLo) and along v - k u
    // (length H √(1 + k²)); the centre at s' = (sLo + sHi)/2, t = H/2.
    const double norm = std::hypot(1.0, k);
    const double sMid = 0.5 * (sLo + sHi), tMid = 0.5 * height;
    Parallelogram2& p = c.parallelogram;
    p.axisU = u;
    p.axisV = (v - k * u) / norm;
    p.halfU = 0.5 * (sHi - sLo);
    p.halfV = tMid * norm;
    p.center = a + (sMid - k * tMid) * u + tMid * v;
    return c;
}

// Dispatch on a hull already in ConvexHull's form.
Parallelogram2 ParallelogramOfValidHull(std::span<const Eigen::Vector2d> hull,
                                        ParallelogramStructure* structure) {
    if (hull.size() < 3) {
        if (structure) *structure = {};
        return MinAreaRectangleOfHull(hull);
    }
    std::vector<double> s(hull.size()), t(hull.size());
    EdgeCandidate best;
    best.area = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < hull.size(); ++i) {
        EdgeCandidate c = FitEdge(hull, i, s, t);
        if (c.area < best.area) best = c;  // strict: the first minimal edge in hull order wins
    }
    if (structure) *structure = best.structure;
    return best.parallelogram;
}

}  // namespace

Parallelogram2 MinAreaParallelogram(std::span<const Eigen::Vector2d> points) {
    RequireFinitePoints(points, "minimum-area parallelogram");
    const std::vector<Eigen::Vector2d> hull = ConvexHull(points);
    return ParallelogramOfValidHull(hull, nullptr);
}

Parallelogram2 MinAreaParallelogramOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                          ParallelogramStructure* structure) {
    MinAreaRectangleOfHull(ccwHull);  // the same validation, O(h); throws std::invalid_argument
    return ParallelogramOfValidHull(ccwHull, structure);
}

Parallelogram2 ParallelogramFlushWithEdge(std::span<const Eigen::Vector2d> ccwHull,
                                          std::size_t edge, ParallelogramStructure* structure) {
    MinAreaRectangleOfHull(ccwHull);
    if (ccwHull.size() < 3)
        throw std::invalid_argument(
            "minimum-area parallelogram: a flush edge needs at least 3 hull vertices");
    if (edge >= ccwHull.size())
        throw std::invalid_argument("minimum-area parallelogram: edge " + std::to_string(edge) +
                                    " of a hull of " + std::to_string(ccwHull.size()) +
                                    " vertices");
    std::vector<double> s(ccwHull.size()), t(ccwHull.size());
    EdgeCandidate c = FitEdge(ccwHull, edge, s, t);
    if (structure) *structure = c.structure;
    return c.parallelogram;
}

}  // namespace lexel
