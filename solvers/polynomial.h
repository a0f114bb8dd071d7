// Real polynomials with coefficients in ascending order: c[0] + c[1] x + ... + c[n] x^n.
//
// The flatland optimizers reduce to polynomial root finding: the L1 objective's critical points
// are the roots of a quadratic, the L2 objective's of a quartic (see flatland/angle_solvers.h).
// Quadratics use the cancellation-free formula (Numerical Recipes §5.6); higher degrees use the
// eigenvalues of the companion matrix (Eigen), each real root polished by Newton steps.
#pragma once

#include <span>
#include <vector>

namespace lexel {

using Polynomial = std::vector<double>;  // ascending coefficients

double EvaluatePolynomial(std::span<const double> c, double x);
Polynomial PolyMultiply(std::span<const double> a, std::span<const double> b);
Polynomial PolyAdd(std::span<const double> a, std::span<const double> b);
Polynomial PolyScale(std::span<const double> a, double s);
Polynomial PolyDerivative(std::span<const double> a);

// Real roots of c2 x² + c1 x + c0, ascending, a double root reported once. Degrades to the
// linear case when c2 == 0; a zero polynomial has no isolated roots and returns none.
std::vector<double> QuadraticRealRoots(double c0, double c1, double c2);

// Real roots of any degree, ascending. Leading coefficients below 1e-14 of the largest
// coefficient are treated as zero (they are rounding residue of cancelled terms). Complex pairs
// whose imaginary part is below 1e-7 of their modulus are kept as (near-double) real roots.
std::vector<double> PolynomialRealRoots(std::span<const double> c);

}  // namespace lexel
