#include "lexel/solvers/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

// Error-free transformations (Knuth, TAOCP vol. 2 §4.2.2; Dekker 1971; Shewchuk 1997 §2): `x` is
// the rounded result and `y` the exact rounding error, so x + y is the real result exactly. They
// need round-to-nearest IEEE doubles without excess precision (x86-64 SSE2, AArch64) and no
// overflow or underflow. None contains a multiply that the compiler could fuse into an FMA except
// TwoProduct, which uses the FMA on purpose: fma(a, b, -ab) is the exact product's low part.
void TwoSum(double a, double b, double& x, double& y) {
    x = a + b;
    const double bVirtual = x - a;
    const double aVirtual = x - bVirtual;
    y = (a - aVirtual) + (b - bVirtual);
}

void TwoDiff(double a, double b, double& x, double& y) {
    x = a - b;
    const double bVirtual = a - x;
    const double aVirtual = x + bVirtual;
    y = (a - aVirtual) + (bVirtual - b);
}

void TwoProduct(double a, double b, double& x, double& y) {
    x = a * b;
    y = std::fma(a, b, -x);
}

int Sign(double x) { return (x > 0) - (x < 0); }

// Exact sign of (a1 - a2)(b1 - b2) - (c1 - c2)(d1 - d2). Each difference is split into a rounded
// part and its error (TwoDiff), so the determinant is exactly a sum of 8 products, each split
// into two doubles (TwoProduct): 16 doubles in all. Grow-Expansion (Shewchuk 1997, Theorem 10)
// adds them into a nonoverlapping expansion whose components increase in magnitude (zeros
// aside); the largest nonzero component then carries the sign of the whole sum.
int ExactDeterminantSign(double a1, double a2, double b1, double b2, double c1, double c2,
                         double d1, double d2) {
    std::array<double, 2> a, b, c, d;
    TwoDiff(a1, a2, a[0], a[1]);
    TwoDiff(b1, b2, b[0], b[1]);
    TwoDiff(c1, c2, c[0], c[1]);
    TwoDiff(d1, d2, d[0], d[1]);
    std::array<double, 16> terms;
    std::size_t termCount = 0;
    for (double x : a)
        for (double y : b) {
            TwoProduct(x, y, terms[termCount], terms[termCount + 1]);
            termCount += 2;
        }
    for (double x : c)
        for (double y : d) {
            TwoProduct(-x, y, terms[termCount], terms[termCount + 1]);  // negation is exact
            termCount += 2;
        }

    std::array<double, 16> expansion;
    std::size_t length = 0;
    for (double term : terms) {
        double carry = term;
        for (std::size_t i = 0; i < length; ++i) {
            double sum, error;
            TwoSum(carry, expansion[i], sum, error);
            expansion[i] = error;
            carry = sum;
        }
        expansion[length++] = carry;
    }
    for (std::size_t i = length; i-- > 0;)
        if (expansion[i] != 0) return Sign(expansion[i]);
    return 0;
}

// Sign of (a1 - a2)(b1 - b2) - (c1 - c2)(d1 - d2): Shewchuk's orient2d filter, then the exact
// fallback. The rounded determinant has the right sign whenever its magnitude is at least
// kErrorBound × (|left| + |right|); that bound, (3 + 16ε)ε with ε = 2⁻⁵³ the unit roundoff, is
// Shewchuk's ccwerrboundA for four rounded differences, two rounded products and one rounded
// subtraction (a compiler fusing the last two into an FMA only lowers the error). It is an a
// priori error bound, not a tolerance: a call it cannot settle is settled exactly.
int DeterminantSign(double a1, double a2, double b1, double b2, double c1, double c2, double d1,
                    double d2) {
    constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;  // 2⁻⁵³
    constexpr double kErrorBound = (3.0 + 16.0 * kUnitRoundoff) * kUnitRoundoff;
    const double left = (a1 - a2) * (b1 - b2);
    const double right = (c1 - c2) * (d1 - d2);
    const double det = left - right;
    // With left and right of opposite signs (or one of them zero) no cancellation is possible and
    // the rounded sign is already exact.
    double magnitude;
    if (left > 0) {
        if (right <= 0) return Sign(det);
        magnitude = left + right;
    } else if (left < 0) {
        if (right >= 0) return Sign(det);
        magnitude = -left - right;
    } else {
        return Sign(det);
    }
    const double errorBound = kErrorBound * magnitude;
    if (det >= errorBound || -det >= errorBound) return Sign(det);
    return ExactDeterminantSign(a1, a2, b1, b2, c1, c2, d1, d2);
}

bool LexicographicLess(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
}

}  // namespace

int CrossSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
              const Eigen::Vector2d& d) {
    // (bx - ax)(dy - cy) - (by - ay)(dx - cx)
    return DeterminantSign(b.x(), a.x(), d.y(), c.y(), b.y(), a.y(), d.x(), c.x());
}

int DotSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
            const Eigen::Vector2d& d) {
    // (bx - ax)(dx - cx) + (by - ay)(dy - cy) = (bx - ax)(dx - cx) - (ay - by)(dy - cy)
    return DeterminantSign(b.x(), a.x(), d.x(), c.x(), a.y(), b.y(), d.y(), c.y());
}

int OrientationSign(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return CrossSign(a, b, a, c);
}

std::vector<Eigen::Vector2d> ConvexHull(std::span<const Eigen::Vector2d> points) {
    // Checked first: a NaN would also break the strict weak ordering the sort relies on.
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw std::invalid_argument("convex hull: point " + std::to_string(k) +
                                        " is not finite");

    std::vector<Eigen::Vector2d> sorted(points.begin(), points.end());
    std::sort(sorted.begin(), sorted.end(), LexicographicLess);
    sorted.erase(std::unique(sorted.begin(), sorted.end(),
                             [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
                                 return p.x() == q.x() && p.y() == q.y();
                             }),
                 sorted.end());
    const std::size_t n = sorted.size();
    if (n <= 1) return sorted;

    // Both chains share one stack. A vertex is popped unless it makes a strict left turn, so
    // collinear boundary points never survive; with all points collinear the two chains reduce to
    // the two extremes and the result is {first, last}.
    std::vector<Eigen::Vector2d> hull(2 * n);
    std::size_t size = 0;
    for (std::size_t i = 0; i < n; ++i) {  // lower chain, left to right
        while (size >= 2 && OrientationSign(hull[size - 2], hull[size - 1], sorted[i]) <= 0) --size;
        hull[size++] = sorted[i];
    }
    const std::size_t lowerSize = size;
    for (std::size_t i = n - 1; i-- > 0;) {  // upper chain, right to left, back to sorted[0]
        while (size > lowerSize && OrientationSign(hull[size - 2], hull[size - 1], sorted[i]) <= 0)
            --size;
        hull[size++] = sorted[i];
    }
    // The upper chain ends on sorted[0] again, the closing vertex; drop it. Every turn of the
    // result, including the one at sorted[0], was tested strictly positive when its last vertex
    // was pushed, except the turn at sorted[0] itself, which is positive because sorted[0] is the
    // lexicographic minimum and hence a vertex of the exact hull.
    hull.resize(size - 1);
    return hull;
}

std::vector<glm::dvec2> ConvexHull(std::span<const glm::dvec2> points) {
    std::vector<Eigen::Vector2d> pts(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) pts[i] = {points[i].x, points[i].y};
    const std::vector<Eigen::Vector2d> hull = ConvexHull(pts);
    std::vector<glm::dvec2> out(hull.size());
    for (std::size_t i = 0; i < hull.size(); ++i) out[i] = {hull[i].x(), hull[i].y()};
    return out;
}

}  // namespace lexel
