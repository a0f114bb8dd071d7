#include "lexel/solvers/parallelogram.h"

#include <cmath>

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
