// Minimum-area enclosing rectangle of a planar point set, by rotating calipers (H. Freeman &
// R. Shapira, CACM 18(7), 1975; G. T. Toussaint, Proc. IEEE MELECON 1983). Brabec et al.,
// "Practical Shadow Mapping" (JGT 7(4), 2002), fit the light frustum to this rectangle around
// the visible points; lexel's light-matrix fit does the same in the plane p4·X = 1.
#pragma once

#include <Eigen/Core>
#include <span>

#include "lexel/solvers/parallelogram.h"

namespace lexel {

// The minimum-area rectangle enclosing all points, as a Parallelogram2 with orthonormal axes
// (axisV is axisU turned by +90°); one side is collinear with a convex-hull edge. Ties: the first
// minimal hull edge in ConvexHull's order wins, and axisU is that edge's direction. Degenerate
// input, exactly: one distinct point → a zero-size rectangle at it with axisU = (1, 0); all
// points collinear → a zero-width rectangle (halfV = 0) centred on the segment between the
// extremes, axisU along it from the lowest-x (then lowest-y) extreme. Throws std::invalid_argument
// on no points or a non-finite coordinate. O(n log n) for the hull, O(h) for the calipers.
Parallelogram2 MinAreaRectangle(std::span<const Eigen::Vector2d> points);

// The same from a hull already in ConvexHull's form: counter-clockwise, strictly convex, no
// closing vertex; or 1 vertex, or 2 distinct vertices. Validated in O(h): std::invalid_argument
// when it is empty, not finite, has a vertex that is not a strict left turn, or winds more than
// once. Bit-identical to MinAreaRectangle on the hull's source points. With `structure`, also its
// combinatorics (edge = -1 for hulls of 1 or 2 vertices).
Parallelogram2 MinAreaRectangleOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                      ParallelogramStructure* structure = nullptr);

}  // namespace lexel
