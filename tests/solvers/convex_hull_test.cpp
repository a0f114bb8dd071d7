#include "lexel/solvers/convex_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

using Points = std::vector<Eigen::Vector2d>;
__extension__ typedef __int128 Int128;  // exact reference arithmetic (GCC/Clang)

std::string Describe(const Points& points) {
    std::ostringstream out;
    out << std::setprecision(17) << points.size() << " points:";
    for (const Eigen::Vector2d& p : points) out << " (" << p.x() << ", " << p.y() << ")";
    return out.str();
}

void ExpectSamePoints(const Points& actual, const Points& expected) {
    ASSERT_EQ(actual.size(), expected.size()) << "got " << Describe(actual);
    for (std::size_t i = 0; i < actual.size(); ++i)
        EXPECT_TRUE(actual[i] == expected[i]) << "vertex " << i << ": got " << Describe(actual)
                                              << ", expected " << Describe(expected);
}

bool LexLess(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
}

double ShoelaceArea(const Points& polygon) {
    double twiceArea = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector2d& p = polygon[i];
        const Eigen::Vector2d& q = polygon[(i + 1) % polygon.size()];
        twiceArea += p.x() * q.y() - p.y() * q.x();
    }
    return 0.5 * twiceArea;
}

// Brute-force reference, O(n³): a directed pair p→q of distinct points is a counter-clockwise
// hull edge iff no point lies strictly right of it and every point on its line lies within the
// segment [p, q]. The hull is then read off by following the edges from the lexicographic
// minimum. For collinear input this gives the two extremes; for one distinct point, that point.
Points BruteForceHull(const Points& points) {
    if (points.empty()) return {};
    Eigen::Vector2d start = points[0];
    for (const Eigen::Vector2d& p : points)
        if (LexLess(p, start)) start = p;
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges;
    for (const Eigen::Vector2d& p : points)
        for (const Eigen::Vector2d& q : points) {
            if (p == q) continue;
            bool isEdge = true;
            for (const Eigen::Vector2d& r : points) {
                const int side = OrientationSign(p, q, r);
                // On the line: inside [p, q] iff (r - p)·(r - q) ≤ 0.
                if (side < 0 || (side == 0 && DotSign(p, r, q, r) > 0)) {
                    isEdge = false;
                    break;
                }
            }
            if (isEdge && std::none_of(edges.begin(), edges.end(),
                                       [&](const auto& e) { return e.first == p; }))
                edges.emplace_back(p, q);
        }
    Points hull = {start};
    for (std::size_t guard = 0; guard <= edges.size(); ++guard) {
        const auto it = std::find_if(edges.begin(), edges.end(),
                                     [&](const auto& e) { return e.first == hull.back(); });
        if (it == edges.end() || it->second == start) break;
        hull.push_back(it->second);
    }
    return hull;
}

// The hull invariants that hold for any input with at least three non-collinear points.
void ExpectValidHull(const Points& points, const Points& hull) {
    ASSERT_GE(hull.size(), 3u);
    const std::size_t h = hull.size();
    for (const Eigen::Vector2d& p : points) EXPECT_FALSE(LexLess(p, hull[0])) << "start vertex";
    for (std::size_t i = 0; i < h; ++i) {
        const Eigen::Vector2d& a = hull[i];
        const Eigen::Vector2d& b = hull[(i + 1) % h];
        const Eigen::Vector2d& c = hull[(i + 2) % h];
        EXPECT_GT(OrientationSign(a, b, c), 0) << "turn at hull vertex " << (i + 1) % h;
        EXPECT_TRUE(std::find(points.begin(), points.end(), a) != points.end())
            << "hull vertex " << i << " is not an input point";
        for (const Eigen::Vector2d& p : points)
            ASSERT_GE(OrientationSign(a, b, p), 0) << "point right of hull edge " << i;
    }
}

TEST(ConvexHull, OrientationSignMatchesExactIntegerArithmetic) {
    // Kettner et al., "Classroom examples of robustness problems in geometric computations"
    // (2008): p = (0.5 + i u, 0.5 + j u), u = 2⁻⁵³, against q = (12, 12) and r = (24, 24). The
    // naive double cross product misclassifies many of these; all coordinates are integers times u,
    // so the exact sign is available in 128-bit integers.
    const double unit = std::ldexp(1.0, -53);
    const Eigen::Vector2d q(12, 12), r(24, 24);
    const auto scaled = [unit](double x) { return static_cast<Int128>(x / unit); };
    int naiveWrong = 0;
    for (int i = 0; i < 256; ++i)
        for (int j = 0; j < 256; ++j) {
            const Eigen::Vector2d p(0.5 + i * unit, 0.5 + j * unit);
            const Int128 det = (scaled(q.x()) - scaled(p.x())) * (scaled(r.y()) - scaled(p.y())) -
                               (scaled(q.y()) - scaled(p.y())) * (scaled(r.x()) - scaled(p.x()));
            const int exact = (det > 0) - (det < 0);
            ASSERT_EQ(OrientationSign(p, q, r), exact) << "i=" << i << " j=" << j;
            ASSERT_EQ(OrientationSign(q, r, p), exact);   // cyclic shifts keep the sign
            ASSERT_EQ(OrientationSign(q, p, r), -exact);  // a swap flips it
            const double naive = (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
            naiveWrong += ((naive > 0) - (naive < 0)) != exact;
        }
    EXPECT_GT(naiveWrong, 0) << "the example should defeat the naive cross product";
}

TEST(ConvexHull, CrossAndDotSignsMatchExactIntegerArithmetic) {
    // Coordinates k·2⁻⁴⁰ with |k| < 2⁵²; d is placed within a few grid steps of the line through
    // c parallel to b - a (or perpendicular for the dot), where the rounded products cancel.
    const std::uint64_t seed = 20240611;
    std::mt19937_64 rng(seed);
    const double unit = std::ldexp(1.0, -40);
    std::uniform_int_distribution<std::int64_t> coord(-(std::int64_t{1} << 51),
                                                      std::int64_t{1} << 51);
    std::uniform_int_distribution<std::int64_t> nudge(-3, 3);
    std::uniform_int_distribution<std::int64_t> factor(-4, 4);
    for (int trial = 0; trial < 20000; ++trial) {
        std::int64_t k[8];
        for (int m = 0; m < 6; ++m) k[m] = coord(rng) / 4;
        const std::int64_t dx = k[2] - k[0], dy = k[3] - k[1], f = factor(rng);
        const bool perpendicular = trial % 2 == 1;
        k[6] = k[4] + f * (perpendicular ? -dy : dx) / 2 + nudge(rng);
        k[7] = k[5] + f * (perpendicular ? dx : dy) / 2 + nudge(rng);
        Eigen::Vector2d v[4];
        for (int m = 0; m < 4; ++m) v[m] = {k[2 * m] * unit, k[2 * m + 1] * unit};
        const Int128 ex = k[2] - k[0], ey = k[3] - k[1], gx = k[6] - k[4], gy = k[7] - k[5];
        const Int128 cross = ex * gy - ey * gx, dot = ex * gx + ey * gy;
        SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial));
        ASSERT_EQ(CrossSign(v[0], v[1], v[2], v[3]), (cross > 0) - (cross < 0));
        ASSERT_EQ(DotSign(v[0], v[1], v[2], v[3]), (dot > 0) - (dot < 0));
    }
}

TEST(ConvexHull, SquareWithInteriorDuplicateAndEdgePoints) {
    Points points = {{2, 2}, {4, 4}, {0, 4}, {1, 3}, {4, 0}, {0, 0}, {2, 0}, {4, 2}, {0, 4},
                     {2, 4}, {0, 2}, {4, 4}, {3, 1}, {0, 0}, {0, 1}, {4, 0}, {2, 2}, {1, 4}};
    const Points expected = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    ExpectSamePoints(ConvexHull(points), expected);
    std::mt19937_64 rng(7);
    for (int shuffle = 0; shuffle < 20; ++shuffle) {  // the answer does not depend on input order
        std::shuffle(points.begin(), points.end(), rng);
        ExpectSamePoints(ConvexHull(points), expected);
    }
}

TEST(ConvexHull, StartsAtLowestXThenLowestY) {
    ExpectSamePoints(ConvexHull(Points{{0, 2}, {3, 0}, {0, -1}}), {{0, -1}, {3, 0}, {0, 2}});
    ExpectSamePoints(ConvexHull(Points{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}),
                     {{-1, 0}, {0, -1}, {1, 0}, {0, 1}});
}

TEST(ConvexHull, DegenerateInputs) {
    EXPECT_TRUE(ConvexHull(Points{}).empty());
    ExpectSamePoints(ConvexHull(Points{{1.5, -2}}), {{1.5, -2}});
    ExpectSamePoints(ConvexHull(Points(50, Eigen::Vector2d(3, 7))), {{3, 7}});
    ExpectSamePoints(ConvexHull(Points{{4, 5}, {1, 1}}), {{1, 1}, {4, 5}});
    ExpectSamePoints(ConvexHull(Points{{1, 1}, {4, 5}, {4, 5}, {1, 1}}), {{1, 1}, {4, 5}});
    ExpectSamePoints(ConvexHull(Points{{2, 5}, {2, 1}}), {{2, 1}, {2, 5}});  // same x: lower y
    // Many exactly collinear points (y = -x/2 is exact in doubles), with duplicates, any order.
    Points line;
    for (int t = -6; t <= 10; ++t) line.emplace_back(t, -0.5 * t);
    line.insert(line.end(), line.begin() + 3, line.begin() + 9);
    std::shuffle(line.begin(), line.end(), std::mt19937_64(3));
    ExpectSamePoints(ConvexHull(line), {{-6, 3}, {10, -5}});
    Points vertical;
    for (int t = 0; t < 9; ++t) vertical.emplace_back(-1, (t * 5) % 9);
    ExpectSamePoints(ConvexHull(vertical), {{-1, 0}, {-1, 8}});
}

TEST(ConvexHull, NonFiniteInputThrows) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    try {
        ConvexHull(Points{{0, 0}, {1, 0}, {nan, 1}});
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "convex hull: point 2 is not finite");
    }
    EXPECT_THROW(ConvexHull(Points{{0, inf}}), std::invalid_argument);
    EXPECT_THROW(ConvexHull(Points{{0, 0}, {-inf, 0}, {1, 1}}), std::invalid_argument);
}

// Seeded sweeps over point-set families; on failure the trace names the seed, the family, the
// trial and the input points.
TEST(ConvexHull, RandomSetsMatchBruteForce) {
    const std::uint64_t seed = 1979;  // Andrew's year
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> grid(-3, 3), count(1, 40);
    const std::vector<std::pair<std::string, std::function<Eigen::Vector2d()>>> families = {
        {"uniform square", [&] { return Eigen::Vector2d(unit(rng), unit(rng)); }},
        {"integer grid (duplicates, collinear runs)",
         [&] { return Eigen::Vector2d(grid(rng), grid(rng)); }},
        {"on a circle",
         [&] {
             const double a = 4 * unit(rng);
             return Eigen::Vector2d(std::cos(a), std::sin(a));
         }},
        {"near a line (rounding breaks collinearity)",
         [&] {
             const double t = unit(rng);
             return Eigen::Vector2d(t, 0.3 * t + 0.1);
         }},
        {"far from the origin",
         [&] { return Eigen::Vector2d(1e6 + unit(rng), -3e5 + 1e-3 * unit(rng)); }},
    };
    for (const auto& [family, draw] : families)
        for (int trial = 0; trial < 150; ++trial) {
            Points points(count(rng));
            for (Eigen::Vector2d& p : points) p = draw();
            SCOPED_TRACE("seed " + std::to_string(seed) + ", " + family + ", trial " +
                         std::to_string(trial) + ", " + Describe(points));
            const Points hull = ConvexHull(points);
            const Points reference = BruteForceHull(points);
            ExpectSamePoints(hull, reference);
            EXPECT_EQ(ShoelaceArea(hull), ShoelaceArea(reference));
            // (No floating-point area sign check: on the near-line family the rounded shoelace
            // sum of a genuine but needle-thin triangle can come out zero or negative; the exact
            // strict turns in ExpectValidHull are the convexity check.)
            if (hull.size() >= 3) ExpectValidHull(points, hull);
            if (HasFatalFailure()) return;
        }
}

TEST(ConvexHull, LargeRandomSetsAreValidHulls) {
    const std::uint64_t seed = 42;
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss;
    for (int trial = 0; trial < 10; ++trial) {
        Points points(3000);
        for (Eigen::Vector2d& p : points) p = {3 * gauss(rng), gauss(rng) + 0.2 * trial};
        SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial));
        const Points hull = ConvexHull(points);
        ExpectValidHull(points, hull);
        if (HasFatalFailure()) return;
    }
}

}  // namespace
}  // namespace lexel
