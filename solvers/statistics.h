// Comparing measurements without luck: the 95% intervals and the noise rule every report and
// script of lexel uses (cases/report/sweep_report.cpp, spatial_report.cpp; the Python module's
// lexel.student_t95 … lexel.differ_beyond_noise, which cases/scripts/ call).
//
// A method's misclassified count on one light is a mean over K sub-texel phases with a standard
// error; two such means differ *beyond the noise* when |a − b| > z · √(se_a² + se_b²) (z = 1.96,
// independent phase means). Over L lights, a mean or a paired difference gets Student's t
// interval: mean ± t₀.₉₇₅(L − 1) · s / √L.
#pragma once

#include <cstddef>
#include <span>

namespace lexel {

// The two-sided 95% normal quantile, as every report prints and applies it (1.959964 rounded).
inline constexpr double kNormal95 = 1.96;

// The two-sided 95% quantile t₀.₉₇₅ of Student's t with `dof` degrees of freedom, to 1e-10
// (the regularized incomplete beta function inverted by bisection: for t > 0,
// P(T > t) = ½ I_{ν/(ν+t²)}(ν/2, ½)). 12.7062 for 1, 4.3027 for 2, 1.98422 for 99, → 1.959964.
// NaN for 0.
double StudentT95(std::size_t dof);

struct MeanInterval {
    double mean = 0.0;
    double halfWidth = 0.0;  // t₀.₉₇₅(n − 1) · s / √n; NaN for fewer than 2 values
};
// The mean of `values` and its 95% half-width; {NaN, NaN} for none.
MeanInterval MeanInterval95(std::span<const double> values);
// The mean of ours[i] − theirs[i] and its 95% half-width (a paired comparison over lights).
// std::invalid_argument when the spans differ in length.
MeanInterval PairedDifference95(std::span<const double> ours, std::span<const double> theirs);

// Whether two independent means differ beyond their noise: |a − b| > kNormal95 · √(se_a² + se_b²).
// False when either is NaN.
bool DifferBeyondNoise(double meanA, double standardErrorA, double meanB, double standardErrorB);

}  // namespace lexel
