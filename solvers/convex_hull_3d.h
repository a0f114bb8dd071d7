// Vertices of the convex hull of a 3D point set, by Qhull (C. B. Barber, D. P. Dobkin & H.
// Huhdanpaa, "The Quickhull algorithm for convex hulls", ACM Transactions on Mathematical
// Software 22(4), 1996; the reentrant C library libqhull_r, Debian package libqhull-dev).
//
// Qhull works in floating point and merges facets whose orientation is within roundoff (its
// default pre-merge 'C-0'), so its hull is the exact hull up to that roundoff: every input point
// lies inside it or within Qhull's roundoff distance (a few ulps of the largest coordinate) of
// it, every vertex is an input point, and points that are collinear or coplanar with a hull edge
// or face up to rounding are not vertices. A caller that needs the extreme points of a cloud —
// the scene-optimized light matrix keeps only them (spatial/optimizer.h) — loses nothing beyond
// rounding.
//
// Most points never reach Qhull: an Akl–Toussaint pre-filter drops points certainly inside
// (convex_hull_3d.cpp).
//
// Degenerate input is handled here, not by Qhull (which stops with "initial simplex is flat"):
// fewer than 4 points, or points Qhull cannot build a hull of (coplanar, as for a camera that sees
// only the floor; collinear; coincident), are projected onto their least-squares plane (principal
// axes of the covariance) and their planar hull is taken exactly (solvers/convex_hull.h), which
// also gives the two extremes of collinear points and one of coincident points. The planar path is
// used only when every point is within kFlatTolerance of that plane; otherwise every point is
// returned, a superset of the vertices that is always correct. Qhull never prints: its error and
// warning text goes to an in-memory stream (POSIX open_memstream) that is discarded.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

namespace lexel {

// Dimensionless: a point set counts as flat when every point is within kFlatTolerance × (the
// largest coordinate magnitude, plus the set's radius about its centroid) of its least-squares
// plane; far above the ~1e-15 relative roundoff at which Qhull gives up on a flat simplex, far
// below any real depth in a scene.
inline constexpr double kFlatTolerance = 1e-12;

// Indices of the hull vertices into `points`, ascending. No points → empty; one distinct point
// (possibly repeated) → one index; collinear points → the two extremes; coplanar points → the
// corners of their planar hull; otherwise Qhull's vertices. Duplicates anywhere are fine (one of
// them is returned). Throws std::invalid_argument ("convex hull 3d: point K is not finite") on a
// NaN or infinite coordinate. Never prints. Thread-safe (one Qhull instance per call).
std::vector<std::size_t> ConvexHullVertices3D(std::span<const Eigen::Vector3d> points);

}  // namespace lexel
