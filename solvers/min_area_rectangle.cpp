// Minimum-area enclosing rectangle of a planar point set, by rotating calipers
// (min_area_rectangle.h).
//
// H. Freeman & R. Shapira, "Determining the minimum-area encasing rectangle for an arbitrary
// closed curve", CACM 18(7), 1975: the minimum-area rectangle around a convex polygon has one
// side collinear with an edge of the polygon, so only the h hull-edge directions need trying.
// G. T. Toussaint, "Solving geometric problems with the rotating calipers", Proc. IEEE MELECON
// 1983: as the base edge steps counter-clockwise around the hull, the three other supporting
// vertices (farthest along the edge, farthest from it, farthest against it) only ever advance
// counter-clockwise too, so all h candidate rectangles cost O(h) together after the hull.
//
// Use in lexel: S. Brabec, T. Annen & H.-P. Seidel, "Practical Shadow Mapping", Journal of
// Graphics Tools 7(4), 2002, fit the light frustum to the minimum enclosing rectangle of the
// visible points, found by rotating calipers, then translate and scale it to use the whole
// shadow map. The 3D fitter does the same with the affine part of the light matrix: this
// rectangle around the 2D convex hull of the projected points, its longer side laid along the
// map's longer dimension (OrientLongSideAlong).
#include "lexel/solvers/min_area_rectangle.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"

namespace lexel {

namespace {

Parallelogram2 PointRectangle(const Eigen::Vector2d& p) {
    Parallelogram2 r;  // axisU = (1, 0), axisV = (0, 1), zero extents
    r.center = p;
    return r;
}

// Zero-width rectangle along the segment a→b (a ≠ b).
Parallelogram2 SegmentRectangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d d = b - a;
    const double length = std::hypot(d.x(), d.y());  // hypot: no overflow in the squares
    Parallelogram2 r;
    r.center = 0.5 * (a + b);
    r.axisU = d / length;
    r.axisV = Perp(r.axisU);
    r.halfU = 0.5 * length;
    r.halfV = 0.0;
    return r;
}

// Rotating calipers over a strictly convex counter-clockwise hull of h ≥ 3 vertices.
//
// For base edge i (direction u, inward normal v = u rotated +90°) the rectangle is bounded by the
// edge's own line (every vertex has v ≥ 0), the vertex farthest along u (`right`), the vertex
// farthest along v (`top`) and the vertex farthest against u (`left`). Going counter-clockwise
// from vertex i+1, the projection on u rises to `right` and then falls to `left`, and the
// projection on v rises all the way to `top`; so each pointer climbs while the next vertex is
// strictly farther. As i advances the supporting directions rotate counter-clockwise, so every
// pointer resumes where it stopped for the previous edge and each passes the hull about once:
// O(h) in total. Whether the next vertex is farther is the sign of a dot or cross product of two
// edge vectors, decided exactly (DotSign, CrossSign), so the climb finds the exact supporting
// vertices; only the extents computed from them are rounded.
Parallelogram2 RotatingCalipers(std::span<const Eigen::Vector2d> hull,
                                ParallelogramStructure* structure) {
    const std::size_t h = hull.size();
    const auto next = [h](std::size_t k) { return k + 1 == h ? 0 : k + 1; };
    std::size_t right = 1, top = 1, left = 1;
    Parallelogram2 best;
    double bestArea = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < h; ++i) {
        const Eigen::Vector2d& a = hull[i];
        const Eigen::Vector2d& b = hull[next(i)];
        // (next - current) · (b - a) > 0: the next vertex is farther along u.
        while (DotSign(hull[right], hull[next(right)], a, b) > 0) right = next(right);
        if (i == 0) top = right;  // afterwards each pointer resumes from its previous edge
        // (b - a) × (next - current) > 0: the next vertex is farther along v.
        while (CrossSign(a, b, hull[top], hull[next(top)]) > 0) top = next(top);
        if (i == 0) left = top;
        while (DotSign(hull[left], hull[next(left)], a, b) < 0) left = next(left);

        const Eigen::Vector2d edge = b - a;
        const Eigen::Vector2d u = edge / std::hypot(edge.x(), edge.y());
        const Eigen::Vector2d v = Perp(u);
        // Extents relative to the edge's start vertex, not the origin, so coordinates far from
        // the origin do not cost the extents their low digits.
        const double uMax = (hull[right] - a).dot(u);
        const double uMin = (hull[left] - a).dot(u);
        const double vMax = (hull[top] - a).dot(v);
        const double area = (uMax - uMin) * vMax;
        if (area < bestArea) {  // strict: the first minimal edge in hull order wins ties
            bestArea = area;
            best.axisU = u;
            best.axisV = v;
            best.halfU = 0.5 * (uMax - uMin);
            best.halfV = 0.5 * vMax;
            best.center = a + (0.5 * (uMax + uMin)) * u + best.halfV * v;
            if (structure)
                *structure = {static_cast<int>(i),    -1,
                              static_cast<int>(left), static_cast<int>(right),
                              static_cast<int>(top),  0.0};
        }
    }
    return best;
}

// Dispatch on a hull already in ConvexHull's form.
Parallelogram2 RectangleOfValidHull(std::span<const Eigen::Vector2d> hull,
                                    ParallelogramStructure* structure) {
    if (structure) *structure = {};
    if (hull.size() == 1) return PointRectangle(hull[0]);
    if (hull.size() == 2) return SegmentRectangle(hull[0], hull[1]);
    return RotatingCalipers(hull, structure);
}

}  // namespace

Parallelogram2 MinAreaRectangle(std::span<const Eigen::Vector2d> points) {
    RequireFinitePoints(points, "minimum-area rectangle");
    const std::vector<Eigen::Vector2d> hull = ConvexHull(points);
    return RectangleOfValidHull(hull, nullptr);
}

Parallelogram2 MinAreaRectangleOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                      ParallelogramStructure* structure) {
    const std::size_t h = ccwHull.size();
    if (h == 0) throw std::invalid_argument("minimum-area rectangle: no points");
    for (std::size_t k = 0; k < h; ++k)
        if (!ccwHull[k].allFinite())
            throw std::invalid_argument("minimum-area rectangle: hull vertex " + std::to_string(k) +
                                        " is not finite");
    if (h == 2 && ccwHull[0] == ccwHull[1])
        throw std::invalid_argument("minimum-area rectangle: hull vertices 0 and 1 coincide");
    if (h >= 3) {
        // Strict left turns everywhere (exact test) make the polygon locally convex; it is then
        // convex iff its edge directions turn once around, i.e. the exterior angles, each in
        // (0, π), sum to 2π rather than a multiple of it. 3π splits the two cases with margin
        // far beyond the rounding of the sum.
        double turning = 0.0;
        for (std::size_t k = 0; k < h; ++k) {
            const Eigen::Vector2d& prev = ccwHull[(k + h - 1) % h];
            const Eigen::Vector2d& cur = ccwHull[k];
            const Eigen::Vector2d& nxt = ccwHull[(k + 1) % h];
            if (OrientationSign(prev, cur, nxt) <= 0)
                throw std::invalid_argument("minimum-area rectangle: hull vertex " +
                                            std::to_string(k) +
                                            " is not a strict counter-clockwise turn");
            const Eigen::Vector2d e0 = cur - prev, e1 = nxt - cur;
            turning += std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
        }
        if (turning > 3.0 * std::numbers::pi)
            throw std::invalid_argument("minimum-area rectangle: hull winds around more than once");
    }
    return RectangleOfValidHull(ccwHull, structure);
}

}  // namespace lexel
