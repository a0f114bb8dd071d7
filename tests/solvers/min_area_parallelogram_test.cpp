// The minimum-area parallelogram against brute force: per hull edge, every vertex-pair tie and a
// fine sweep over the shear k; over all edges, every pair of hull-edge directions and a fine sweep
// over pairs of side directions; closed forms for the report's Fig. 3 configuration.
#include "lexel/solvers/min_area_parallelogram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/min_area_rectangle.h"

namespace lexel {
namespace {

using Points = std::vector<Eigen::Vector2d>;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string Describe(const Points& points) {
    std::ostringstream out;
    out << std::setprecision(17) << points.size() << " points:";
    for (const Eigen::Vector2d& p : points) out << " (" << p.x() << ", " << p.y() << ")";
    return out.str();
}

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Edge coordinates of every point for hull edge a → b: s along the edge, t along its inward
// normal, both relative to a.
struct EdgeFrame {
    Eigen::Vector2d a, u, v;
    double S(const Eigen::Vector2d& p) const { return (p - a).dot(u); }
    double T(const Eigen::Vector2d& p) const { return (p - a).dot(v); }
};
EdgeFrame FrameOf(const Points& hull, std::size_t i) {
    const Eigen::Vector2d a = hull[i], b = hull[(i + 1) % hull.size()];
    const Eigen::Vector2d u = (b - a).normalized();
    return {a, u, Eigen::Vector2d(-u.y(), u.x())};
}

// E(k) = max (s + k t) - min (s + k t) over all points, and H = max t.
double Extent(const Points& points, const EdgeFrame& f, double k) {
    double lo = kInf, hi = -kInf;
    for (const Eigen::Vector2d& p : points) {
        const double sk = f.S(p) + k * f.T(p);
        lo = std::min(lo, sk);
        hi = std::max(hi, sk);
    }
    return hi - lo;
}
double Height(const Points& points, const EdgeFrame& f) {
    double h = 0.0;
    for (const Eigen::Vector2d& p : points) h = std::max(h, f.T(p));
    return h;
}

// Exact reference: E is piecewise linear with breakpoints where two points tie, so its minimum is
// at k = 0 or at one of the O(n²) pairwise ties. O(n³), no convexity or chain argument used.
double PairTieMinExtent(const Points& points, const EdgeFrame& f) {
    double best = Extent(points, f, 0.0);
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            const double dt = f.T(points[j]) - f.T(points[i]);
            if (dt == 0.0) continue;
            const double k = (f.S(points[i]) - f.S(points[j])) / dt;
            if (std::isfinite(k)) best = std::min(best, Extent(points, f, k));
        }
    return best;
}

// Width of the points across direction θ (the strip between two lines at angle θ).
double Width(const Points& points, double theta) {
    const Eigen::Vector2d n(-std::sin(theta), std::cos(theta));
    double lo = kInf, hi = -kInf;
    for (const Eigen::Vector2d& p : points) {
        lo = std::min(lo, (p - points[0]).dot(n));
        hi = std::max(hi, (p - points[0]).dot(n));
    }
    return hi - lo;
}

// Exact reference over all edges (Schwarz et al.: some minimal enclosing parallelogram has both
// side pairs flush with hull edges): the least w(θi) w(θj) / |sin(θi - θj)| over ordered pairs of
// non-parallel hull-edge directions. O(h² n).
double EdgePairMinArea(const Points& points) {
    const Points hull = ConvexHull(points);
    double best = kInf;
    for (std::size_t i = 0; i < hull.size(); ++i)
        for (std::size_t j = 0; j < hull.size(); ++j) {
            const Eigen::Vector2d ei = hull[(i + 1) % hull.size()] - hull[i];
            const Eigen::Vector2d ej = hull[(j + 1) % hull.size()] - hull[j];
            const double sine = std::abs(Cross(ei.normalized(), ej.normalized()));
            if (sine < 1e-12) continue;
            const double ti = std::atan2(ei.y(), ei.x()), tj = std::atan2(ej.y(), ej.x());
            best = std::min(best, Width(points, ti) * Width(points, tj) / sine);
        }
    return best;
}

// Brute-force sweep over pairs of side directions on a grid of `n` angles in [0, π): only ever
// above the true minimum.
double DirectionSweepMinArea(const Points& points, int n) {
    std::vector<double> width(n);
    for (int k = 0; k < n; ++k) width[k] = Width(points, k * std::numbers::pi / n);
    double best = kInf;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            best = std::min(
                best, width[i] * width[j] / std::abs(std::sin((j - i) * std::numbers::pi / n)));
    return best;
}

// Every result: unit axes, positive orientation, non-negative half sides, finite, every point
// inside within `tolerance` (a distance along the axes).
void ExpectValid(const Parallelogram2& p, const Points& points, double tolerance) {
    ASSERT_TRUE(p.center.allFinite() && p.axisU.allFinite() && p.axisV.allFinite());
    ASSERT_TRUE(std::isfinite(p.halfU) && std::isfinite(p.halfV));
    EXPECT_NEAR(p.axisU.norm(), 1.0, 1e-12);
    EXPECT_NEAR(p.axisV.norm(), 1.0, 1e-12);
    EXPECT_GT(Cross(p.axisU, p.axisV), 0.0);
    EXPECT_GE(p.halfU, 0.0);
    EXPECT_GE(p.halfV, 0.0);
    for (const Eigen::Vector2d& q : points)
        EXPECT_TRUE(p.Contains(q, tolerance)) << "(" << q.x() << ", " << q.y() << ")";
}

Points RandomCloud(std::mt19937_64& rng, int count, int shape) {
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const double angle = 3.0 * uni(rng);
    const Eigen::Vector2d offset(10 * uni(rng), 10 * uni(rng));
    Points points;
    for (int k = 0; k < count; ++k) {
        Eigen::Vector2d p;
        switch (shape) {
            case 0:
                p = {uni(rng), uni(rng)};
                break;  // square
            case 1:
                p = {3 * gauss(rng), 0.4 * gauss(rng)};
                break;  // elongated
            case 2:
                p = {uni(rng), 0.05 * uni(rng) * (1 + uni(rng))};
                break;  // thin slab
            default: {  // disc, skewed
                const double r = std::sqrt(0.5 + 0.5 * uni(rng)), a = 3.2 * uni(rng);
                p = {r * std::cos(a) + 0.7 * r * std::sin(a), r * std::sin(a)};
            }
        }
        points.push_back(offset +
                         Eigen::Vector2d(std::cos(angle) * p.x() - std::sin(angle) * p.y(),
                                         std::sin(angle) * p.x() + std::cos(angle) * p.y()));
    }
    return points;
}

// Per edge: the solver's E(k*) equals the pairwise-tie minimum to rounding, no point of a fine
// sweep over k does better, k* is the structure's tie (or 0), a nonzero k* beats k = 0 by more than
// 1e-12 of E(0) (smaller gains are ties, kept at 0), and |k*| ≤ 2 E(0) / H.
TEST(MinAreaParallelogram, EveryEdgeShearIsTheExactMinimumOverK) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        std::mt19937_64 rng(seed);
        const Points points = RandomCloud(rng, 6 + static_cast<int>(seed % 30), seed % 4);
        SCOPED_TRACE("seed " + std::to_string(seed) + ": " + Describe(points));
        const Points hull = ConvexHull(points);
        ASSERT_GE(hull.size(), 3u);
        for (std::size_t i = 0; i < hull.size(); ++i) {
            SCOPED_TRACE("edge " + std::to_string(i));
            ParallelogramStructure st;
            const Parallelogram2 p = ParallelogramFlushWithEdge(hull, i, &st);
            const EdgeFrame f = FrameOf(hull, i);
            const double k = st.shear, e0 = Extent(points, f, 0.0), h = Height(points, f);
            const double ek = Extent(points, f, k);
            ExpectValid(p, points, 1e-12 * e0);
            EXPECT_EQ(st.edge, static_cast<int>(i));
            // The parallelogram is the one of the header: side along the edge 2 halfU = E(k*),
            // height H, area E(k*) H.
            EXPECT_NEAR(2 * p.halfU, ek, 1e-12 * e0);
            EXPECT_NEAR(p.Area(), ek * h, 1e-12 * e0 * h);
            EXPECT_NEAR(ek, PairTieMinExtent(points, f), 2e-12 * e0);
            EXPECT_LE(std::abs(k), 2 * e0 / h);
            // |E'| ≤ H, so the grid minimum can exceed the true one by at most H · step / 2.
            const double range = 2 * e0 / h, step = range / 20000;
            double grid = kInf;
            for (int q = -20000; q <= 20000; ++q)
                grid = std::min(grid, Extent(points, f, q * step));
            EXPECT_LE(ek, grid + 2e-12 * e0);
            EXPECT_GE(ek, grid - 0.5 * h * step - 1e-12 * e0);
            if (st.shearEdge < 0) {
                EXPECT_EQ(k, 0.0);
            } else {
                // k* is where the structure's two adjacent vertices tie, and it pays off.
                const Eigen::Vector2d& yi = hull[st.shearEdge];
                const Eigen::Vector2d& yj = hull[(st.shearEdge + 1) % hull.size()];
                EXPECT_NEAR(k, (f.S(yi) - f.S(yj)) / (f.T(yj) - f.T(yi)),
                            1e-12 * (1 + std::abs(k)));
                EXPECT_LT(ek, (1 - 1e-12) * e0);
            }
            // The structure's extremes attain the sheared extents and the height.
            EXPECT_NEAR(f.S(hull[st.maxS]) + k * f.T(hull[st.maxS]) -
                            (f.S(hull[st.minS]) + k * f.T(hull[st.minS])),
                        ek, 1e-12 * e0);
            EXPECT_NEAR(f.T(hull[st.top]), h, 1e-12 * h);
        }
    }
}

// Over all edges: the minimum-area enclosing parallelogram, against every pair of hull-edge
// directions (exact) and a 1440² sweep over side directions; never larger than the rectangle.
TEST(MinAreaParallelogram, IsTheMinimumAreaEnclosingParallelogram) {
    int sheared = 0;  // clouds where the shear saves more than 1% of the rectangle's area
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        std::mt19937_64 rng(1000 + seed);
        const Points points = RandomCloud(rng, 5 + static_cast<int>(seed % 40), seed % 4);
        SCOPED_TRACE("seed " + std::to_string(seed) + ": " + Describe(points));
        const Parallelogram2 p = MinAreaParallelogram(points);
        const Parallelogram2 r = MinAreaRectangle(points);
        if (p.Area() < 0.99 * r.Area()) ++sheared;
        ExpectValid(p, points, 1e-12 * (p.halfU + p.halfV));
        const double area = p.Area();
        EXPECT_NEAR(area, EdgePairMinArea(points), 1e-11 * area);
        EXPECT_LE(area, DirectionSweepMinArea(points, 1440) * (1 + 1e-12));
        EXPECT_LE(area, r.Area() * (1 + 1e-12));
        // The sweep's grid is fine: its best is within 1% of the exact minimum.
        EXPECT_LE(DirectionSweepMinArea(points, 1440), 1.01 * area);
        // MinAreaParallelogramOfHull is the same computation on the hull, bit for bit.
        const Points hull = ConvexHull(points);
        const Parallelogram2 q = MinAreaParallelogramOfHull(hull);
        EXPECT_EQ(p.center, q.center);
        EXPECT_EQ(p.axisU, q.axisU);
        EXPECT_EQ(p.axisV, q.axisV);
        EXPECT_EQ(p.halfU, q.halfU);
        EXPECT_EQ(p.halfV, q.halfV);
    }
    std::cout << sheared << " of 40 clouds: the parallelogram is over 1% smaller\n";
    EXPECT_GE(sheared, 10);
}

// Report Fig. 3: off-edge vertices left of both edge extents. Here c - d = b - a, so shearing right
// until d lines up with a (k = 1) makes c line up with b: the hull is its own parallelogram.
TEST(MinAreaParallelogram, ReportFigure3ShearLinesUpTheLeftmostPoint) {
    const Points hull = {{0, 0}, {2, 0}, {1, 1}, {-1, 1}};
    Points points = hull;
    points.push_back({0.5, 0.5});
    ParallelogramStructure st;
    const Parallelogram2 p = ParallelogramFlushWithEdge(hull, 0, &st);
    EXPECT_DOUBLE_EQ(st.shear, 1.0);
    EXPECT_DOUBLE_EQ(p.Area(), 2.0);  // the rectangle flush with the same edge: 3 × 1
    EXPECT_DOUBLE_EQ(MinAreaRectangle(points).Area(), 3.0);
    EXPECT_DOUBLE_EQ(MinAreaParallelogram(points).Area(), 2.0);
    const auto corners = p.Corners();
    for (int k = 0; k < 4; ++k) EXPECT_NEAR((corners[k] - hull[k]).norm(), 0.0, 1e-15);
}

// Where lining up the leftmost point would push another one past the edge's right end, the exact
// shear stops where the overshoot starts: E(k) = 3 - k up to k = 1/4, then 2.5 + k.
TEST(MinAreaParallelogram, ExactShearStopsBeforeAnOvershoot) {
    const Points hull = {{0, 0}, {2, 0}, {1.5, 2}, {-1, 1}};
    ParallelogramStructure st;
    const Parallelogram2 p = ParallelogramFlushWithEdge(hull, 0, &st);
    EXPECT_DOUBLE_EQ(st.shear, 0.25);
    EXPECT_DOUBLE_EQ(2 * p.halfU, 2.75);  // the report's k = 1 would give 3.5 (k = 0: 3)
    EXPECT_DOUBLE_EQ(p.Area(), 5.5);
    EXPECT_EQ(st.shearEdge, 1);  // b and c tie: 2 = 1.5 + 2k
}

// When k = 0 is already among the minimizers no shear is applied: a triangle whose apex projects
// inside its base (E = |b - a| for k ∈ [-1/2, 1/2]), and a rotated rectangle of points, whose
// result is MinAreaRectangle's rectangle (to rounding: which of the four equal edges wins is
// decided by the last bits of the areas).
TEST(MinAreaParallelogram, NoShearWhereTheRectangleIsOptimal) {
    ParallelogramStructure st;
    const Points triangle = {{0, 0}, {1, 0}, {0.5, 1}};
    ParallelogramFlushWithEdge(triangle, 0, &st);
    EXPECT_EQ(st.shear, 0.0);
    EXPECT_EQ(st.shearEdge, -1);

    Points box = {{-2, -1}, {3, -1}, {3, 0.5}, {-2, 0.5}, {0, 0}, {1, 0.2}, {2.9, -0.9}};
    for (Eigen::Vector2d& q : box)
        q = Eigen::Vector2d(0.6 * q.x() - 0.8 * q.y(), 0.8 * q.x() + 0.6 * q.y());
    const Points hull = ConvexHull(box);
    const Parallelogram2 p = MinAreaParallelogramOfHull(hull, &st);
    EXPECT_EQ(st.shear, 0.0);
    const Parallelogram2 r = MinAreaRectangle(box);
    EXPECT_NEAR(p.Area(), r.Area(), 1e-14 * r.Area());
    EXPECT_NEAR(std::abs(p.axisU.dot(p.axisV)), 0.0, 1e-15);
    for (const Eigen::Vector2d& c : p.Corners()) {
        double nearest = kInf;
        for (const Eigen::Vector2d& d : r.Corners()) nearest = std::min(nearest, (c - d).norm());
        EXPECT_NEAR(nearest, 0.0, 1e-14);
    }
}

// Fewer than 3 hull vertices: the rectangle, finite. Slivers of height 1e-12 relative: finite
// shear, every point inside.
TEST(MinAreaParallelogram, DegenerateAndSliverInputStayFinite) {
    for (const Points& points : {Points{{1, 2}}, Points{{1, 2}, {1, 2}}, Points{{0, 0}, {3, 4}},
                                 Points{{0, 0}, {1, 1}, {3, 3}, {2, 2}}}) {
        SCOPED_TRACE(Describe(points));
        const Parallelogram2 p = MinAreaParallelogram(points);
        const Parallelogram2 r = MinAreaRectangle(points);
        EXPECT_EQ(p.center, r.center);
        EXPECT_EQ(p.axisU, r.axisU);
        EXPECT_EQ(p.halfU, r.halfU);
        EXPECT_EQ(p.halfV, 0.0);
        ExpectValid(p, points, 1e-12);
    }
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const double thin = std::pow(10.0, -3 - trial % 10);
        Points points;
        for (int k = 0; k < 8; ++k)
            points.push_back({uni(rng), thin * uni(rng) + 0.3 * uni(rng) * thin});
        SCOPED_TRACE("trial " + std::to_string(trial) + ": " + Describe(points));
        const Points hull = ConvexHull(points);
        if (hull.size() < 3) continue;
        for (std::size_t i = 0; i < hull.size(); ++i) {
            ParallelogramStructure st;
            const Parallelogram2 p = ParallelogramFlushWithEdge(hull, i, &st);
            const EdgeFrame f = FrameOf(hull, i);
            ASSERT_TRUE(std::isfinite(st.shear));
            EXPECT_LE(std::abs(st.shear),
                      2 * Extent(points, f, 0.0) / Height(points, f) * (1 + 1e-9));
            ExpectValid(p, points, 1e-9);
        }
        ExpectValid(MinAreaParallelogram(points), points, 1e-9);
    }
}

TEST(MinAreaParallelogram, OrientLongSideKeepsTheShapeAndOrientation) {
    const Points hull = {{0, 0}, {2, 0}, {1.5, 2}, {-1, 1}};
    const Parallelogram2 p = ParallelogramFlushWithEdge(hull, 0);
    ASSERT_GT(p.halfU, 0.0);
    // Side along the edge 2.75, the other 2 √(1 + 1/16) ≈ 2.06: already long on U.
    EXPECT_EQ(OrientLongSideAlong(p, true).axisU, p.axisU);
    const Parallelogram2 q = OrientLongSideAlong(p, false);
    EXPECT_EQ(q.axisU, p.axisV);
    EXPECT_EQ(q.axisV, -p.axisU);
    EXPECT_EQ(q.halfU, p.halfV);
    EXPECT_EQ(q.halfV, p.halfU);
    EXPECT_GT(Cross(q.axisU, q.axisV), 0.0);
    EXPECT_DOUBLE_EQ(q.Area(), p.Area());
    for (const Eigen::Vector2d& c : p.Corners()) EXPECT_TRUE(q.Contains(c, 1e-12));
    // The dual axes invert the frame: a corner's coordinates are (±halfU, ±halfV).
    const auto [dualU, dualV] = q.DualAxes();
    const Eigen::Vector2d corner = q.Corners()[2] - q.center;
    EXPECT_NEAR(dualU.dot(corner), q.halfU, 1e-12);
    EXPECT_NEAR(dualV.dot(corner), q.halfV, 1e-12);
}

TEST(MinAreaParallelogram, RejectsBadInput) {
    EXPECT_THROW(MinAreaParallelogram(Points{}), std::invalid_argument);
    EXPECT_THROW(MinAreaParallelogram(Points{{0, std::nan("")}}), std::invalid_argument);
    EXPECT_THROW(MinAreaParallelogramOfHull(Points{{0, 0}, {0, 1}, {1, 0}}),
                 std::invalid_argument);  // cw
    EXPECT_THROW(ParallelogramFlushWithEdge(Points{{0, 0}, {1, 0}}, 0), std::invalid_argument);
    EXPECT_THROW(ParallelogramFlushWithEdge(Points{{0, 0}, {1, 0}, {0, 1}}, 3),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lexel
