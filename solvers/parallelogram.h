// An oriented parallelogram in the plane: the shape the minimum-area rectangle
// (min_area_rectangle.h, orthonormal axes) and the minimum-area parallelogram
// (min_area_parallelogram.h) return, and the frame a shadow map is fitted to.
#pragma once

#include <Eigen/Core>
#include <array>

namespace lexel {

// center ± halfU axisU ± halfV axisV, with unit axes, axisU × axisV > 0 (the axes need not be
// orthogonal; for a rectangle axisV is axisU turned by +90°) and half side lengths ≥ 0.
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

// The combinatorics of a minimum-area rectangle or parallelogram around a convex hull
// (MinAreaRectangleOfHull, MinAreaParallelogramOfHull), in hull-vertex indices, for a caller that
// re-evaluates (and differentiates) the same construction from moved vertices: the flush edge
// hull[edge] → hull[edge + 1 mod h] with unit direction u and inward normal v, edge coordinates
// s = u·(y - hull[edge]) and t = v·(y - hull[edge]); the shear k* = (s_j - s_{j+1}) / (t_{j+1} -
// t_j) with j = shearEdge (k* = 0 when shearEdge = -1, always for the rectangle); the vertices
// attaining min and max of s + k* t and max of t. edge = -1 for a hull of fewer than 3 vertices.
struct ParallelogramStructure {
    int edge = -1;
    int shearEdge = -1;
    int minS = -1, maxS = -1, top = -1;
    double shear = 0.0;  // k*, the value computed (dimensionless: s per unit of t)
};

// The same parallelogram with its longer side on U (longSideOnU) or on V (!longSideOnU), compared
// as side lengths 2 halfU and 2 halfV. When the axes must swap, the pair keeps its orientation
// (a +90° turn of the frame): axisU' = axisV, axisV' = -axisU, and the half sides swap. An
// already oriented (or rhombic) parallelogram comes back unchanged.
Parallelogram2 OrientLongSideAlong(const Parallelogram2& p, bool longSideOnU);

}  // namespace lexel
