// Minimum-area enclosing rectangle of a planar point set, by rotating calipers.
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
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>

namespace lexel {

// An oriented rectangle: center ± halfU axisU ± halfV axisV. (axisU, axisV) is a right-handed
// orthonormal pair: axisV is axisU rotated by +90°, so axisU × axisV = +1.
struct Rectangle2 {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    Eigen::Vector2d axisU = Eigen::Vector2d::UnitX();  // unit
    Eigen::Vector2d axisV = Eigen::Vector2d::UnitY();  // unit, axisU rotated by +90°
    double halfU = 0.0;                                // half extent along axisU, ≥ 0
    double halfV = 0.0;                                // half extent along axisV, ≥ 0

    double Area() const { return 4.0 * halfU * halfV; }
    // Counter-clockwise from center - halfU axisU - halfV axisV.
    std::array<Eigen::Vector2d, 4> Corners() const;
    // Whether p lies inside or within `tolerance` of the rectangle, measured separately along
    // each axis, in the units of the coordinates (an absolute distance, not a fraction).
    bool Contains(const Eigen::Vector2d& p, double tolerance) const;
};

// Minimum-area rectangle enclosing all points (one side collinear with a hull edge). Ties are
// broken deterministically: the first minimal hull edge in ConvexHull's order wins, and axisU is
// that edge's direction. Degenerate input, exactly: no points → InputError("minimum-area
// rectangle: no points"); one distinct point → a zero-size rectangle at it with axisU = (1, 0);
// all points collinear → a zero-width rectangle (halfV = 0) centred on the segment between the
// extremes, axisU along it from the lowest-x (then lowest-y) extreme. Throws InputError on a
// non-finite coordinate.
Rectangle2 MinAreaRectangle(std::span<const Eigen::Vector2d> points);

// The same for a caller that already holds a hull in ConvexHull's form: counter-clockwise,
// strictly convex (no repeated or collinear vertices), no closing vertex; or 1 vertex, or 2
// distinct vertices. Checked in O(h), throwing InputError when it is empty, not finite, has a
// vertex that is not a strict left turn (clockwise, reflex, collinear or repeated), or winds
// more than once. The result is bit-identical to MinAreaRectangle on the hull's source points.
Rectangle2 MinAreaRectangleOfHull(std::span<const Eigen::Vector2d> ccwHull);

// The same rectangle with its longer side on U (longSideOnU) or on V (!longSideOnU). When the
// axes must swap, the pair stays right-handed: axisU' = axisV, axisV' = -axisU (a +90° turn of
// the frame), and the half extents swap. A square, or an already oriented rectangle, comes back
// unchanged.
Rectangle2 OrientLongSideAlong(const Rectangle2& r, bool longSideOnU);

}  // namespace lexel
