#include "lexel/solvers/statistics.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <unsupported/Eigen/SpecialFunctions>
#include <vector>

namespace lexel {

namespace {

// I_x(a, b), the regularized incomplete beta function (Eigen's).
double RegularizedBeta(double a, double b, double x) {
    Eigen::Array<double, 1, 1> aa, bb, xx;
    aa << a;
    bb << b;
    xx << x;
    return Eigen::betainc(aa, bb, xx)(0);
}

}  // namespace

double StudentT95(std::size_t dof) {
    if (dof == 0) return std::numeric_limits<double>::quiet_NaN();
    const double nu = static_cast<double>(dof);
    // Two-sided: P(|T| > t) = I_x(ν/2, ½) with x = ν/(ν + t²), increasing in x; find
    // I_x = 0.05 by bisection on x ∈ (0, 1), then t = √(ν (1 − x) / x).
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
        const double mid = 0.5 * (lo + hi);
        (RegularizedBeta(0.5 * nu, 0.5, mid) < 0.05 ? lo : hi) = mid;
    }
    const double x = 0.5 * (lo + hi);
    return std::sqrt(nu * (1.0 - x) / x);
}

MeanInterval MeanInterval95(std::span<const double> values) {
    const std::size_t n = values.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (n == 0) return {nan, nan};
    const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
    if (n < 2) return {mean, nan};
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    return {mean, StudentT95(n - 1) * std::sqrt(squares / (n - 1.0) / n)};
}

MeanInterval PairedDifference95(std::span<const double> ours, std::span<const double> theirs) {
    if (ours.size() != theirs.size())
        throw std::invalid_argument("PairedDifference95: the two spans differ in length");
    std::vector<double> differences(ours.size());
    for (std::size_t i = 0; i < ours.size(); ++i) differences[i] = ours[i] - theirs[i];
    return MeanInterval95(differences);
}

bool DifferBeyondNoise(double meanA, double standardErrorA, double meanB, double standardErrorB) {
    return std::abs(meanA - meanB) > kNormal95 * std::hypot(standardErrorA, standardErrorB);
}

}  // namespace lexel
