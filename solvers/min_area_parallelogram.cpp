#include "lexel/solvers/min_area_parallelogram.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel {

double Parallelogram2::Area() const {
    const double sine = axisU.x() * axisV.y() - axisU.y() * axisV.x();
    return 4.0 * halfU * halfV * sine;
}

std::array<Eigen::Vector2d, 4> Parallelogram2::Corners() const {
    const Eigen::Vector2d u = halfU * axisU;
    const Eigen::Vector2d v = halfV * axisV;
    return {center - u - v, center + u - v, center + u + v, center - u + v};
}

std::array<Eigen::Vector2d, 2> Parallelogram2::DualAxes() const {
    // The rows of [axisU axisV]⁻¹: each axis turned a quarter and divided by the determinant.
    const double det = axisU.x() * axisV.y() - axisU.y() * axisV.x();
    return {Eigen::Vector2d(axisV.y(), -axisV.x()) / det,
            Eigen::Vector2d(-axisU.y(), axisU.x()) / det};
}

bool Parallelogram2::Contains(const Eigen::Vector2d& p, double tolerance) const {
    const auto [dualU, dualV] = DualAxes();
    const Eigen::Vector2d d = p - center;
    return std::abs(dualU.dot(d)) <= halfU + tolerance &&
           std::abs(dualV.dot(d)) <= halfV + tolerance;
}

Parallelogram2 ToParallelogram(const Rectangle2& r) {
    Parallelogram2 p;
    p.center = r.center;
    p.axisU = r.axisU;
    p.axisV = r.axisV;
    p.halfU = r.halfU;
    p.halfV = r.halfV;
    return p;
}

namespace {

Eigen::Vector2d RotatedPlus90(const Eigen::Vector2d& u) { return {-u.y(), u.x()}; }

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
    const Eigen::Vector2d v = RotatedPlus90(u);
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
        return ToParallelogram(MinAreaRectangleOfHull(hull));
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
    if (points.empty()) throw InputError("minimum-area parallelogram: no points");
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw InputError("minimum-area parallelogram: point " + std::to_string(k) +
                             " is not finite");
    const std::vector<Eigen::Vector2d> hull = ConvexHull(points);
    return ParallelogramOfValidHull(hull, nullptr);
}

Parallelogram2 MinAreaParallelogramOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                          ParallelogramStructure* structure) {
    MinAreaRectangleOfHull(ccwHull);  // the same validation, O(h); throws InputError
    return ParallelogramOfValidHull(ccwHull, structure);
}

Parallelogram2 ParallelogramFlushWithEdge(std::span<const Eigen::Vector2d> ccwHull,
                                          std::size_t edge, ParallelogramStructure* structure) {
    MinAreaRectangleOfHull(ccwHull);
    if (ccwHull.size() < 3)
        throw InputError("minimum-area parallelogram: a flush edge needs at least 3 hull vertices");
    if (edge >= ccwHull.size())
        throw InputError("minimum-area parallelogram: edge " + std::to_string(edge) +
                         " of a hull of " + std::to_string(ccwHull.size()) + " vertices");
    std::vector<double> s(ccwHull.size()), t(ccwHull.size());
    EdgeCandidate c = FitEdge(ccwHull, edge, s, t);
    if (structure) *structure = c.structure;
    return c.parallelogram;
}

Parallelogram2 OrientLongSideAlong(const Parallelogram2& p, bool longSideOnU) {
    const bool swap = longSideOnU ? p.halfU < p.halfV : p.halfV < p.halfU;
    if (!swap) return p;
    Parallelogram2 q = p;
    q.axisU = p.axisV;  // (axisV, -axisU) has the same orientation as (axisU, axisV)
    q.axisV = -p.axisU;
    q.halfU = p.halfV;
    q.halfV = p.halfU;
    return q;
}

}  // namespace lexel
