// Planar convex hull by Andrew's monotone chain (A. M. Andrew, "Another efficient algorithm for
// convex hulls in two dimensions", Information Processing Letters 9(5), 1979).
//
// The points are sorted lexicographically (x, then y) and exact duplicates dropped; the lower
// chain is built left to right and the upper chain right to left, each a stack whose top is
// popped while it does not make a strict left turn with the incoming point. O(n log n) for the
// sort, O(n) for the two chains. The 3D shadow-map fit (see min_area_rectangle.h) encloses the
// hull of the light-space projections of the visible points.
//
// Orientation, i.e. collinearity, is decided exactly: every decision is the sign of the cross
// product (b - a) × (c - a) of the double coordinates, evaluated in double arithmetic without
// rounding error. A floating-point filter with Shewchuk's a-priori error bound answers almost
// every call; a near-collinear triple falls back to an error-free expansion of the determinant
// (J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", Discrete & Computational Geometry 18, 1997). There is no epsilon: three points
// are collinear iff that exact determinant is zero. So the hull is deterministic, and every
// consecutive vertex triple of the output (the wrap-around included) is a strict left turn.
// Exactness needs the intermediate products to neither overflow nor underflow, which holds when
// every coordinate is zero or has a magnitude in [1e-120, 1e120]; outside that range the sign is
// the rounded floating-point one.
#pragma once

#include <Eigen/Core>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace lexel {

// Exact sign of (b - a) × (c - a): +1 when a, b, c turn counter-clockwise (c left of the directed
// line a→b), -1 clockwise, 0 exactly collinear (coincident points included).
int OrientationSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

// Exact signs of the cross and dot products of two difference vectors, (b - a) × (d - c) and
// (b - a) · (d - c), with the same filter and fallback. The rotating calipers step with these, so
// "the next vertex is farther along this edge direction" is decided exactly too.
int CrossSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
              const Eigen::Vector2d& d);
int DotSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
            const Eigen::Vector2d& d);

// Counter-clockwise hull vertices, starting from the lowest-x (then lowest-y) point, without a
// repeated closing vertex; points on the hull boundary that are not corners are dropped.
// Degenerate input: no points → empty; one distinct point (possibly repeated) → that point;
// all points collinear (two distinct points included) → the two extreme points, lowest-x
// (then lowest-y) first. Duplicates anywhere are fine. Every returned vertex is one of the
// input points, bit for bit. Throws std::invalid_argument ("convex hull: point K is not finite") on
// a NaN or infinite coordinate.
std::vector<Eigen::Vector2d> ConvexHull(std::span<const Eigen::Vector2d> points);
// The same for GLM points.
std::vector<glm::dvec2> ConvexHull(std::span<const glm::dvec2> points);

}  // namespace lexel
