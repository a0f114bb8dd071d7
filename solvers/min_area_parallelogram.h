// The minimum-area enclosing parallelogram with one side pair flush with a convex-hull edge: the
// minimum-area rectangle with an exact affine shear. Chong & Gortler's report (§2.3, Algorithm 1
// step 4b-ii, Fig. 3) shears the rectangle heuristically to "better line up with the edge's
// endpoints"; here the shear is optimized exactly, edge by edge, which makes the result the
// minimum-area enclosing parallelogram (C. Schwarz, J. Teich, E. Welzl & B. Evans, 1994; G. Rote,
// arXiv:1905.11203, 2019). The construction, its proofs and the report's rule as a special case
// are in min_area_parallelogram.cpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>

#include "lexel/solvers/parallelogram.h"

namespace lexel {

// Minimum-area enclosing parallelogram of the points (the exact shear of the .cpp, best edge). Ties
// are broken like MinAreaRectangle: the first minimal hull edge in ConvexHull's order wins; axisU
// is that edge's direction and axisV = (v - k* u) / √(1 + k*²). Degenerate input: fewer than 3 hull
// vertices (one distinct point, or all collinear) gives MinAreaRectangle's rectangle, unsheared.
// Throws std::invalid_argument on no points or a non-finite coordinate.
Parallelogram2 MinAreaParallelogram(std::span<const Eigen::Vector2d> points);

// The same for a hull in ConvexHull's form (validated as MinAreaRectangleOfHull does), optionally
// reporting the structure. Bit-identical to MinAreaParallelogram on the hull's source points.
Parallelogram2 MinAreaParallelogramOfHull(std::span<const Eigen::Vector2d> ccwHull,
                                          ParallelogramStructure* structure = nullptr);

// The least parallelogram with a side pair parallel to hull edge ccwHull[edge] → ccwHull[edge + 1
// mod h], one side on that edge: the per-edge step of MinAreaParallelogramOfHull (k* closest to 0
// among the minimizers of E). The hull is validated as there and must have ≥ 3 vertices, and
// edge < h; std::invalid_argument otherwise.
Parallelogram2 ParallelogramFlushWithEdge(std::span<const Eigen::Vector2d> ccwHull,
                                          std::size_t edge,
                                          ParallelogramStructure* structure = nullptr);

}  // namespace lexel
