#include "lexel/solvers/polynomial.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace lexel {

double EvaluatePolynomial(std::span<const double> c, double x) {
    double value = 0.0;
    for (auto it = c.rbegin(); it != c.rend(); ++it) value = value * x + *it;  // Horner
    return value;
}

Polynomial PolyMultiply(std::span<const double> a, std::span<const double> b) {
    if (a.empty() || b.empty()) return {};
    Polynomial out(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
    return out;
}

Polynomial PolyAdd(std::span<const double> a, std::span<const double> b) {
    Polynomial out(std::max(a.size(), b.size()), 0.0);
    for (std::size_t i = 0; i < a.size(); ++i) out[i] += a[i];
    for (std::size_t i = 0; i < b.size(); ++i) out[i] += b[i];
    return out;
}

Polynomial PolyScale(std::span<const double> a, double s) {
    Polynomial out(a.begin(), a.end());
    for (double& v : out) v *= s;
    return out;
}

Polynomial PolyDerivative(std::span<const double> a) {
    if (a.size() <= 1) return {0.0};
    Polynomial out(a.size() - 1);
    for (std::size_t i = 1; i < a.size(); ++i) out[i - 1] = static_cast<double>(i) * a[i];
    return out;
}

std::vector<double> QuadraticRealRoots(double c0, double c1, double c2) {
    if (c2 == 0.0) {
        if (c1 == 0.0) return {};
        return {-c0 / c1};
    }
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0) {
        // A discriminant within rounding of zero is a double root; farther below is complex.
        const double scale = c1 * c1 + std::abs(4.0 * c2 * c0);
        if (disc < -1e-14 * scale) return {};
        return {-c1 / (2.0 * c2)};
    }
    // q = -(c1 + sign(c1) sqrt(disc))/2; roots q/c2 and c0/q never subtract nearly equal numbers.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    std::vector<double> roots;
    roots.push_back(q / c2);
    if (q != 0.0)
        roots.push_back(c0 / q);
    else
        roots.push_back(0.0);
    std::sort(roots.begin(), roots.end());
    if (roots[0] == roots[1]) roots.pop_back();
    return roots;
}

std::vector<double> PolynomialRealRoots(std::span<const double> c) {
    // Trim leading coefficients that are rounding residue.
    double largest = 0.0;
    for (double v : c) largest = std::max(largest, std::abs(v));
    if (largest == 0.0) return {};
    std::size_t degree = c.size() - 1;
    while (degree > 0 && std::abs(c[degree]) <= 1e-14 * largest) --degree;
    if (degree == 0) return {};
    if (degree <= 2) return QuadraticRealRoots(c[0], c[1], degree == 2 ? c[2] : 0.0);

    // Companion matrix of the monic polynomial: ones on the subdiagonal, -c_i/c_n in the last
    // column. Its eigenvalues are the roots.
    const int n = static_cast<int>(degree);
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
    for (int i = 0; i < n; ++i) companion(i, n - 1) = -c[i] / c[degree];
    Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, /*computeEigenvectors=*/false);
    const std::span<const double> trimmed = c.first(degree + 1);
    const Polynomial derivative = PolyDerivative(trimmed);
    std::vector<double> roots;
    for (int i = 0; i < n; ++i) {
        const std::complex<double> z = solver.eigenvalues()[i];
        if (std::abs(z.imag()) > 1e-7 * std::max(1.0, std::abs(z))) continue;
        // Polish: the QR eigenvalues are accurate to ~1e-12 relative; three Newton steps make
        // them accurate to the last bit for simple roots, and are harmless for double ones.
        double x = z.real();
        for (int step = 0; step < 3; ++step) {
            const double d = EvaluatePolynomial(derivative, x);
            if (d == 0.0) break;
            const double dx = EvaluatePolynomial(trimmed, x) / d;
            if (!std::isfinite(dx) || std::abs(dx) > 1e-3 * std::max(1.0, std::abs(x))) break;
            x -= dx;
        }
        roots.push_back(x);
    }
    std::sort(roots.begin(), roots.end());
    return roots;
}

}  // namespace lexel
