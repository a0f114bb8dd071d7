#include "lexel/solvers/min_area_rectangle.h"

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel {

std::array<Eigen::Vector2d, 4> Rectangle2::Corners() const {
    const Eigen::Vector2d u = halfU * axisU;
    const Eigen::Vector2d v = halfV * axisV;
    return {center - u - v, center + u - v, center + u + v, center - u + v};
}

bool Rectangle2::Contains(const Eigen::Vector2d& p, double tolerance) const {
    const Eigen::Vector2d d = p - center;
    return std::abs(d.dot(axisU)) <= halfU + tolerance &&
           std::abs(d.dot(axisV)) <= halfV + tolerance;
}

namespace {

Eigen::Vector2d RotatedPlus90(const Eigen::Vector2d& u) { return {-u.y(), u.x()}; }

Rectangle2 PointRectangle(const Eigen::Vector2d& p) {
    Rectangle2 r;  // axisU = (1, 0), axisV = (0, 1), zero extents
    r.center = p;
    return r;
}

// Zero-width rectangle along the segment a→b (a ≠ b).
Rectangle2 SegmentRectangle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d d = b - a;
    const double length = std::hypot(d.x(), d.y());  // hypot: no overflow in the squares
    Rectangle2 r;
    r.center = 0.5 * (a + b);
    r.axisU = d / length;
    r.axisV = RotatedPlus90(r.axisU);
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
Rectangle2 RotatingCalipers(std::span<const Eigen::Vector2d> hull) {
    const std::size_t h = hull.size();
    const auto next = [h](std::size_t k) { return k + 1 == h ? 0 : k + 1; };
    std::size_t right = 1, top = 1, left = 1;
    Rectangle2 best;
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
        const Eigen::Vector2d v = RotatedPlus90(u);
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
        }
    }
    return best;
}

// Dispatch on a hull already in ConvexHull's form.
Rectangle2 RectangleOfValidHull(std::span<const Eigen::Vector2d> hull) {
    if (hull.size() == 1) return PointRectangle(hull[0]);
    if (hull.size() == 2) return SegmentRectangle(hull[0], hull[1]);
    return RotatingCalipers(hull);
}

}  // namespace

Rectangle2 MinAreaRectangle(std::span<const Eigen::Vector2d> points) {
    if (points.empty()) throw InputError("minimum-area rectangle: no points");
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw InputError("minimum-area rectangle: point " + std::to_string(k) +
                             " is not finite");
    const std::vector<Eigen::Vector2d> hull = ConvexHull(points);
    return RectangleOfValidHull(hull);
}

Rectangle2 MinAreaRectangleOfHull(std::span<const Eigen::Vector2d> ccwHull) {
    const std::size_t h = ccwHull.size();
    if (h == 0) throw InputError("minimum-area rectangle: no points");
    for (std::size_t k = 0; k < h; ++k)
        if (!ccwHull[k].allFinite())
            throw InputError("minimum-area rectangle: hull vertex " + std::to_string(k) +
                             " is not finite");
    if (h == 2 && ccwHull[0] == ccwHull[1])
        throw InputError("minimum-area rectangle: hull vertices 0 and 1 coincide");
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
                throw InputError("minimum-area rectangle: hull vertex " + std::to_string(k) +
                                 " is not a strict counter-clockwise turn");
            const Eigen::Vector2d e0 = cur - prev, e1 = nxt - cur;
            turning += std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1));
        }
        if (turning > 3.0 * std::numbers::pi)
            throw InputError("minimum-area rectangle: hull winds around more than once");
    }
    return RectangleOfValidHull(ccwHull);
}

Rectangle2 OrientLongSideAlong(const Rectangle2& r, bool longSideOnU) {
    const bool swap = longSideOnU ? r.halfU < r.halfV : r.halfV < r.halfU;
    if (!swap) return r;
    Rectangle2 s = r;
    s.axisU = r.axisV;  // a +90° turn of the frame keeps it right-handed
    s.axisV = -r.axisU;
    s.halfU = r.halfV;
    s.halfV = r.halfU;
    return s;
}

}  // namespace lexel
