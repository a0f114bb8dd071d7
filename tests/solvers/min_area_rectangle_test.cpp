#include "lexel/solvers/min_area_rectangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

using Points = std::vector<Eigen::Vector2d>;
constexpr double kPi = std::numbers::pi;

std::string Describe(const Points& points) {
    std::ostringstream out;
    out << std::setprecision(17) << points.size() << " points:";
    for (const Eigen::Vector2d& p : points) out << " (" << p.x() << ", " << p.y() << ")";
    return out.str();
}

Eigen::Vector2d Rotated(const Eigen::Vector2d& p, double angle) {
    return {std::cos(angle) * p.x() - std::sin(angle) * p.y(),
            std::sin(angle) * p.x() + std::cos(angle) * p.y()};
}

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Area of the bounding box of the points in the frame rotated by `angle`. Projections are taken
// relative to the first point so that clouds far from the origin keep their low digits.
double BoxAreaAt(const Points& points, double angle) {
    const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
    double uMin = std::numeric_limits<double>::infinity(), uMax = -uMin, vMin = uMin, vMax = -uMin;
    for (const Eigen::Vector2d& p : points) {
        const Eigen::Vector2d d = p - points[0];
        uMin = std::min(uMin, d.dot(u));
        uMax = std::max(uMax, d.dot(u));
        vMin = std::min(vMin, d.dot(v));
        vMax = std::max(vMax, d.dot(v));
    }
    return (uMax - uMin) * (vMax - vMin);
}

// Brute-force reference: the least bounding-box area over 20000 frame angles in [0, π/2) (a box
// repeats every quarter turn). It can only overestimate the true minimum.
double BruteForceMinArea(const Points& points) {
    constexpr int kAngles = 20000;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < kAngles; ++k)
        best = std::min(best, BoxAreaAt(points, k * (kPi / 2) / kAngles));
    return best;
}

// Exact-theorem reference (Freeman & Shapira): the least bounding-box area over the directions of
// all hull edges, each box measured over all input points. O(n h), no calipers.
double EdgeDirectionMinArea(const Points& points) {
    const Points hull = ConvexHull(points);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
        best = std::min(best, BoxAreaAt(points, std::atan2(e.y(), e.x())));
    }
    return best;
}

// Checks that hold for every result: orthonormal right-handed axes, non-negative extents, and
// every input point inside within `tolerance`.
void ExpectValidRectangle(const Parallelogram2& r, const Points& points, double tolerance) {
    EXPECT_NEAR(r.axisU.norm(), 1.0, 1e-15);
    EXPECT_EQ(r.axisV.x(), -r.axisU.y());
    EXPECT_EQ(r.axisV.y(), r.axisU.x());
    EXPECT_GE(r.halfU, 0.0);
    EXPECT_GE(r.halfV, 0.0);
    for (std::size_t k = 0; k < points.size(); ++k)
        EXPECT_TRUE(r.Contains(points[k], tolerance)) << "point " << k << " outside";
}

// Points of a rectangle (corners, edge points at t ∈ [0.1, 0.9], interior) given its center,
// rotation and half sides.
Points SampleRectangle(const Eigen::Vector2d& center, double angle, double halfU, double halfV,
                       std::mt19937_64& rng) {
    std::uniform_real_distribution<double> s(-1, 1), t(0.1, 0.9);
    Points local = {{-halfU, -halfV}, {halfU, -halfV}, {halfU, halfV}, {-halfU, halfV}};
    for (int k = 0; k < 4; ++k)
        local.push_back(local[k] + t(rng) * (local[(k + 1) % 4] - local[k]));
    for (int k = 0; k < 30; ++k) local.emplace_back(0.99 * halfU * s(rng), 0.99 * halfV * s(rng));
    Points points;
    for (const Eigen::Vector2d& p : local) points.push_back(center + Rotated(p, angle));
    std::shuffle(points.begin(), points.end(), rng);
    return points;
}

TEST(MinAreaRectangle, AxisAlignedRectangleIsExact) {
    const Points points = {{5, 3}, {1, 2},      {3, 2.5}, {5, 2}, {1, 3},
                           {2, 2}, {4.5, 2.75}, {1, 2.5}, {5, 3}, {1, 3}};
    const Parallelogram2 r = MinAreaRectangle(points);
    EXPECT_EQ(r.Area(), 4.0);
    EXPECT_EQ(r.halfU, 2.0);
    EXPECT_EQ(r.halfV, 0.5);
    EXPECT_TRUE(r.center == Eigen::Vector2d(3, 2.5));
    // Every edge of the hull gives area 4; the first edge in hull order, (1,2)→(5,2), wins.
    EXPECT_TRUE(r.axisU == Eigen::Vector2d(1, 0));
    EXPECT_TRUE(r.axisV == Eigen::Vector2d(0, 1));
    ExpectValidRectangle(r, points, 0.0);
    const auto corners = r.Corners();
    EXPECT_TRUE(corners[0] == Eigen::Vector2d(1, 2));
    EXPECT_TRUE(corners[1] == Eigen::Vector2d(5, 2));
    EXPECT_TRUE(corners[2] == Eigen::Vector2d(5, 3));
    EXPECT_TRUE(corners[3] == Eigen::Vector2d(1, 3));
    EXPECT_FALSE(r.Contains({5.001, 2.5}, 0.0));
    EXPECT_TRUE(r.Contains({5.001, 2.5}, 0.002));
}

TEST(MinAreaRectangle, RotatedRectangleAreaAndDirection) {
    std::mt19937_64 rng(30);
    const double angle = kPi / 6;  // 30°
    const Points points = SampleRectangle({0.7, -0.2}, angle, 1.5, 0.5, rng);
    SCOPED_TRACE(Describe(points));
    const Parallelogram2 r = MinAreaRectangle(points);
    EXPECT_NEAR(r.Area(), 3.0, 1e-12);
    EXPECT_NEAR(std::max(r.halfU, r.halfV), 1.5, 1e-12);
    EXPECT_NEAR(std::min(r.halfU, r.halfV), 0.5, 1e-12);
    EXPECT_NEAR(r.center.x(), 0.7, 1e-12);
    EXPECT_NEAR(r.center.y(), -0.2, 1e-12);
    // The axis is ±30° modulo 90°; fold its angle into [0°, 90°).
    const double degrees = std::atan2(r.axisU.y(), r.axisU.x()) * 180 / kPi;
    EXPECT_NEAR(std::fmod(degrees + 360, 90), 30.0, 1e-9);
    ExpectValidRectangle(r, points, 1e-9 * 3);
}

TEST(MinAreaRectangle, KnownRegularPolygons) {
    // Closed forms: a triangle's minimal rectangle has twice its area (base on the longest side);
    // a square's is itself; a regular hexagon of circumradius R sits in a 2R × √3R box; a regular
    // octagon of circumradius R in a square of side 2R cos(π/8), area (2 + √2) R².
    struct Case {
        int sides;
        double expectedOverRSquared;
    };
    const Case cases[] = {{3, 2 * 3 * std::sqrt(3.0) / 4},
                          {4, 2.0},
                          {6, 2 * std::sqrt(3.0)},
                          {8, 2 + std::sqrt(2.0)}};
    for (const Case& c : cases)
        for (double phase : {0.0, 0.1234, 1.0}) {
            const double radius = 2.5;
            Points points;
            for (int k = 0; k < c.sides; ++k)
                points.push_back(Eigen::Vector2d(-3, 8) +
                                 radius * Eigen::Vector2d(std::cos(phase + 2 * kPi * k / c.sides),
                                                          std::sin(phase + 2 * kPi * k / c.sides)));
            SCOPED_TRACE(std::to_string(c.sides) + "-gon, phase " + std::to_string(phase));
            const Parallelogram2 r = MinAreaRectangle(points);
            EXPECT_NEAR(r.Area() / (c.expectedOverRSquared * radius * radius), 1.0, 1e-12);
            ExpectValidRectangle(r, points, 1e-9 * radius);
        }
}

TEST(MinAreaRectangle, RegularPolygonsAndCirclesAgainstBruteForce) {
    const std::uint64_t seed = 1975;  // Freeman & Shapira
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int sides : {3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 17, 64, 1000}) {
        const double phase = 2 * kPi * uniform(rng), radius = 0.1 + 10 * uniform(rng);
        const Eigen::Vector2d center(100 * uniform(rng) - 50, 100 * uniform(rng) - 50);
        Points points;
        for (int k = 0; k < sides; ++k)
            points.push_back(center + Rotated({radius, 0.0}, phase + 2 * kPi * k / sides));
        SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(sides) + "-gon, " +
                     Describe(points));
        const Parallelogram2 r = MinAreaRectangle(points);
        const double brute = BruteForceMinArea(points);
        EXPECT_LE(r.Area(), brute * (1 + 1e-12));
        // A 20000-step grid misses the optimal angle by at most π/80000 ≈ 4e-5 rad, and the box
        // area changes by at most a few times that, relatively.
        EXPECT_GE(r.Area(), brute * (1 - 5e-4));
        EXPECT_NEAR(r.Area() / EdgeDirectionMinArea(points), 1.0, 1e-12);
        ExpectValidRectangle(r, points, 1e-9 * radius);
    }
}

TEST(MinAreaRectangle, RandomCloudsAgainstReferences) {
    const std::uint64_t seed = 1983;  // Toussaint
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> uniform(0, 1);
    std::uniform_int_distribution<int> count(3, 60), grid(-2, 2);
    for (int trial = 0; trial < 200; ++trial) {
        Points points(count(rng));
        const bool onGrid = trial % 4 == 3;  // duplicates and collinear runs
        const double scale = std::pow(10.0, 4 * uniform(rng) - 2);
        const double angle = 2 * kPi * uniform(rng), aspect = 0.05 + uniform(rng);
        const Eigen::Vector2d offset = 1000 * scale * Eigen::Vector2d(gauss(rng), gauss(rng));
        for (Eigen::Vector2d& p : points)
            p = onGrid ? Eigen::Vector2d(grid(rng), grid(rng))
                       : Eigen::Vector2d(offset +
                                         scale * Rotated({gauss(rng), aspect * gauss(rng)}, angle));
        SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial) + ", " +
                     Describe(points));
        const Parallelogram2 r = MinAreaRectangle(points);
        const Points hull = ConvexHull(points);
        const double extent = onGrid ? 2.0 : scale * 10;
        ExpectValidRectangle(r, points, 1e-9 * extent);
        if (hull.size() < 3) continue;  // the collinear grid draws are covered elsewhere
        const double reference = EdgeDirectionMinArea(points);
        EXPECT_NEAR(r.Area() / reference, 1.0, 1e-12);
        if (trial % 4 == 0) {  // the 20000-angle sweep is the slow reference
            const double brute = BruteForceMinArea(points);
            EXPECT_LE(r.Area(), brute * (1 + 1e-12));
            EXPECT_GE(r.Area(), brute * (1 - 5e-4));
        }
        // One side is collinear with a hull edge (Freeman & Shapira): axisU is an edge direction.
        bool alongEdge = false;
        for (std::size_t i = 0; i < hull.size(); ++i) {
            const Eigen::Vector2d e = (hull[(i + 1) % hull.size()] - hull[i]).normalized();
            alongEdge |= std::abs(Cross(e, r.axisU)) <= 1e-15 && e.dot(r.axisU) > 0;
        }
        EXPECT_TRUE(alongEdge);
        // The hull entry point gives the very same rectangle.
        const Parallelogram2 fromHull = MinAreaRectangleOfHull(hull);
        EXPECT_TRUE(fromHull.center == r.center && fromHull.axisU == r.axisU &&
                    fromHull.axisV == r.axisV && fromHull.halfU == r.halfU &&
                    fromHull.halfV == r.halfV);
        if (HasFailure()) return;
    }
}

TEST(MinAreaRectangle, NeedleThinAndFinelySampledInputs) {
    // Near-collinear clouds (points on a line up to rounding, or 1e-12 off it) and a circle with
    // 100000 vertices, where consecutive hull edges are nearly parallel: the calipers' supporting
    // vertices are chosen by exact sign tests, so no point may end up outside the rectangle.
    const std::uint64_t seed = 399897;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int trial = 0; trial < 100; ++trial) {
        const double angle = 3.2 * uniform(rng), thickness = trial % 2 ? 1e-12 : 0.0;
        Points points(3 + trial);
        for (Eigen::Vector2d& p : points)
            p = Eigen::Vector2d(5, -7) + Rotated({uniform(rng), thickness * uniform(rng)}, angle);
        SCOPED_TRACE("seed " + std::to_string(seed) + ", trial " + std::to_string(trial) + ", " +
                     Describe(points));
        const Parallelogram2 r = MinAreaRectangle(points);
        ExpectValidRectangle(r, points, 1e-9);
        EXPECT_LE(r.halfV, 1e-11);  // the rectangle is as thin as the cloud
        // Areas here are ~1e-16 and both sides round at that level (length ≤ 2 times direction
        // and projection errors of a few 1e-16), so the agreement is absolute.
        if (ConvexHull(points).size() >= 3) {
            EXPECT_NEAR(r.Area(), EdgeDirectionMinArea(points), 1e-14);
        }
        if (HasFailure()) return;
    }
    Points circle(100000);
    for (std::size_t k = 0; k < circle.size(); ++k)
        circle[k] = Rotated({3.0, 0.0}, 2 * kPi * static_cast<double>(k) / circle.size());
    const Parallelogram2 r = MinAreaRectangle(circle);
    ExpectValidRectangle(r, circle, 1e-9 * 3);
    EXPECT_NEAR(r.Area(), 36.0, 36.0 * 1e-9);  // a fine polygon's box is the circle's square
}

TEST(MinAreaRectangle, DegenerateInputsAreExact) {
    try {
        MinAreaRectangle(Points{});
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "minimum-area rectangle: no points");
    }

    for (const Points& single : {Points{{2.5, -1}}, Points(40, Eigen::Vector2d(2.5, -1))}) {
        const Parallelogram2 r = MinAreaRectangle(single);
        EXPECT_TRUE(r.center == Eigen::Vector2d(2.5, -1));
        EXPECT_TRUE(r.axisU == Eigen::Vector2d(1, 0));
        EXPECT_TRUE(r.axisV == Eigen::Vector2d(0, 1));
        EXPECT_EQ(r.halfU, 0.0);
        EXPECT_EQ(r.halfV, 0.0);
        EXPECT_EQ(r.Area(), 0.0);
        EXPECT_TRUE(r.Contains({2.5, -1}, 0.0));
    }

    // Two points: axisU runs from the lowest-x point to the other, here (3, 4)/5.
    for (const Points& pair : {Points{{4, 5}, {1, 1}}, Points{{1, 1}, {4, 5}, {1, 1}, {4, 5}}}) {
        const Parallelogram2 r = MinAreaRectangle(pair);
        EXPECT_TRUE(r.center == Eigen::Vector2d(2.5, 3));
        EXPECT_TRUE(r.axisU == Eigen::Vector2d(0.6, 0.8));
        EXPECT_TRUE(r.axisV == Eigen::Vector2d(-0.8, 0.6));
        EXPECT_EQ(r.halfU, 2.5);
        EXPECT_EQ(r.halfV, 0.0);
        EXPECT_EQ(r.Area(), 0.0);
    }

    // Many collinear points with duplicates along y = 2x: the extremes (-3,-6) and (5,10).
    Points line;
    for (int t = -3; t <= 5; ++t) line.emplace_back(t, 2 * t);
    line.insert(line.end(), line.begin(), line.begin() + 4);
    std::shuffle(line.begin(), line.end(), std::mt19937_64(11));
    const Parallelogram2 r = MinAreaRectangle(line);
    EXPECT_TRUE(r.center == Eigen::Vector2d(1, 2));
    EXPECT_DOUBLE_EQ(r.axisU.x(), 1 / std::sqrt(5.0));
    EXPECT_DOUBLE_EQ(r.axisU.y(), 2 / std::sqrt(5.0));
    EXPECT_DOUBLE_EQ(r.halfU, 4 * std::sqrt(5.0));
    EXPECT_EQ(r.halfV, 0.0);
    EXPECT_EQ(r.Area(), 0.0);
    ExpectValidRectangle(r, line, 1e-9 * 10);

    const Parallelogram2 vertical = MinAreaRectangle(Points{{2, 5}, {2, 1}, {2, 2}});
    EXPECT_TRUE(vertical.center == Eigen::Vector2d(2, 3));
    EXPECT_TRUE(vertical.axisU == Eigen::Vector2d(0, 1));
    EXPECT_TRUE(vertical.axisV == Eigen::Vector2d(-1, 0));
    EXPECT_EQ(vertical.halfU, 2.0);
    EXPECT_EQ(vertical.halfV, 0.0);
}

TEST(MinAreaRectangle, NonFiniteInputThrows) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    try {
        MinAreaRectangle(Points{{0, 0}, {inf, 1}, {2, 0}});
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "minimum-area rectangle: point 1 is not finite");
    }
    EXPECT_THROW(MinAreaRectangle(Points{{nan, 0}}), std::invalid_argument);
    EXPECT_THROW(MinAreaRectangleOfHull(Points{{0, 0}, {1, 0}, {0, nan}}), std::invalid_argument);
}

TEST(MinAreaRectangle, HullEntryPointChecksItsInput) {
    const Points square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_EQ(MinAreaRectangleOfHull(square).Area(), 1.0);
    EXPECT_TRUE(MinAreaRectangleOfHull(Points{{3, 4}}).center == Eigen::Vector2d(3, 4));
    EXPECT_EQ(MinAreaRectangleOfHull(Points{{0, 0}, {0, 2}}).halfU, 1.0);
    EXPECT_THROW(MinAreaRectangleOfHull(Points{}), std::invalid_argument);
    EXPECT_THROW(MinAreaRectangleOfHull(Points{{1, 1}, {1, 1}}), std::invalid_argument);
    const Points clockwise(square.rbegin(), square.rend());
    EXPECT_THROW(MinAreaRectangleOfHull(clockwise), std::invalid_argument);
    EXPECT_THROW(MinAreaRectangleOfHull(Points{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}}),
                 std::invalid_argument);  // collinear vertex
    EXPECT_THROW(MinAreaRectangleOfHull(Points{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}),
                 std::invalid_argument);  // repeated vertex
    EXPECT_THROW(MinAreaRectangleOfHull(Points{{0, 0}, {2, 0}, {1, 1}, {1, -1}}),
                 std::invalid_argument);  // self-crossing
    // A pentagram: every turn is a strict left turn, but it winds around twice.
    Points pentagram;
    for (int k = 0; k < 5; ++k) pentagram.push_back(Rotated({1.0, 0.0}, 2 * kPi * (2 * k) / 5));
    for (std::size_t k = 0; k < pentagram.size(); ++k)
        ASSERT_GT(OrientationSign(pentagram[k], pentagram[(k + 1) % 5], pentagram[(k + 2) % 5]), 0);
    try {
        MinAreaRectangleOfHull(pentagram);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "minimum-area rectangle: hull winds around more than once");
    }
}

TEST(MinAreaRectangle, OrientLongSideAlong) {
    Parallelogram2 r;
    r.center = {1, -2};
    r.axisU = {std::cos(0.3), std::sin(0.3)};
    r.axisV = {-r.axisU.y(), r.axisU.x()};
    r.halfU = 0.5;
    r.halfV = 2.0;

    const Parallelogram2 longU = OrientLongSideAlong(r, true);
    EXPECT_EQ(longU.halfU, 2.0);
    EXPECT_EQ(longU.halfV, 0.5);
    EXPECT_TRUE(longU.axisU == r.axisV);
    EXPECT_TRUE(longU.axisV == -r.axisU);
    EXPECT_NEAR(Cross(longU.axisU, longU.axisV), 1.0, 1e-15);
    EXPECT_TRUE(longU.center == r.center);
    EXPECT_DOUBLE_EQ(longU.Area(), r.Area());
    // The same rectangle: its corners are the original corners, cyclically shifted by one.
    const auto before = r.Corners(), after = longU.Corners();
    for (int k = 0; k < 4; ++k) EXPECT_NEAR((after[k] - before[(k + 1) % 4]).norm(), 0.0, 1e-15);

    // Already oriented: unchanged, bit for bit.
    const Parallelogram2 same = OrientLongSideAlong(r, false);
    EXPECT_TRUE(same.axisU == r.axisU && same.axisV == r.axisV && same.halfU == r.halfU &&
                same.halfV == r.halfV && same.center == r.center);
    // And back: long side on V again, still right-handed.
    const Parallelogram2 longV = OrientLongSideAlong(longU, false);
    EXPECT_EQ(longV.halfU, 0.5);
    EXPECT_EQ(longV.halfV, 2.0);
    EXPECT_NEAR(Cross(longV.axisU, longV.axisV), 1.0, 1e-15);
    EXPECT_TRUE(longV.axisU == -r.axisU);  // two +90° turns: the frame is rotated by 180°

    // On fitted rectangles: long side on U, right-handed, still enclosing every point.
    std::mt19937_64 rng(2002);  // Brabec, Annen & Seidel
    for (int trial = 0; trial < 20; ++trial) {
        const Points points = SampleRectangle({0, 0}, 0.37 * trial, 0.2 + 0.1 * trial, 1.0, rng);
        SCOPED_TRACE("trial " + std::to_string(trial) + ", " + Describe(points));
        const Parallelogram2 fitted = OrientLongSideAlong(MinAreaRectangle(points), true);
        EXPECT_GE(fitted.halfU, fitted.halfV);
        EXPECT_NEAR(Cross(fitted.axisU, fitted.axisV), 1.0, 1e-15);
        ExpectValidRectangle(fitted, points, 1e-9 * 3);
    }
}

}  // namespace
}  // namespace lexel
