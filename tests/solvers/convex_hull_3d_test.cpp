// ConvexHullVertices3D (Qhull) against brute force: exact vertex sets of solids and of random
// clouds in general position, containment of every input point, and the degenerate inputs
// Qhull itself rejects (too few, coplanar, collinear, repeated), all without a word on stdout or
// stderr.
#include "lexel/solvers/convex_hull_3d.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

using Points = std::vector<Eigen::Vector3d>;
using Indices = std::vector<std::size_t>;

// Calls ConvexHullVertices3D and fails the test if anything reached stdout or stderr.
Indices SilentHull(const Points& points) {
    ::testing::internal::CaptureStdout();
    ::testing::internal::CaptureStderr();
    Indices vertices = ConvexHullVertices3D(points);
    const std::string out = ::testing::internal::GetCapturedStdout();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(out, "");
    EXPECT_EQ(err, "");
    return vertices;
}

// The 3D hull's vertices by brute force, for points in general position: i is a vertex iff it
// lies on some plane through three points that has every other point strictly on one side.
Indices BruteForceVertices(const Points& p) {
    std::set<std::size_t> vertices;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k) {
                const Eigen::Vector3d normal = (p[j] - p[i]).cross(p[k] - p[i]);
                int above = 0, below = 0;
                for (std::size_t m = 0; m < n; ++m) {
                    if (m == i || m == j || m == k) continue;
                    const double d = normal.dot(p[m] - p[i]);
                    above += d > 0, below += d < 0;
                }
                if (above == 0 || below == 0) vertices.insert({i, j, k});
            }
    return {vertices.begin(), vertices.end()};
}

// Every point lies in the hull of `vertices` up to `tolerance`, tested through support functions:
// conv(V) ⊇ P iff max over V of d·v ≥ max over P of d·p for every direction d.
void ExpectContainsAll(const Points& points, const Indices& vertices, double tolerance) {
    std::mt19937_64 rng(99);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 2000; ++trial) {
        const Eigen::Vector3d d =
            Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
        double hullMax = -std::numeric_limits<double>::infinity();
        for (std::size_t v : vertices) hullMax = std::max(hullMax, d.dot(points[v]));
        double allMax = -std::numeric_limits<double>::infinity();
        for (const Eigen::Vector3d& p : points) allMax = std::max(allMax, d.dot(p));
        ASSERT_GE(hullMax, allMax - tolerance) << "direction " << d.transpose();
    }
}

Points CubeCorners(double half) {
    Points corners;
    for (int c = 0; c < 8; ++c)
        corners.emplace_back((c & 1) ? half : -half, (c & 2) ? half : -half,
                             (c & 4) ? half : -half);
    return corners;
}

TEST(ConvexHull3D, CubeWithInteriorFaceAndEdgePointsKeepsExactlyTheCorners) {
    Points points = CubeCorners(1.5);
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> inside(-1.5, 1.5);
    for (int i = 0; i < 500; ++i) points.emplace_back(inside(rng), inside(rng), inside(rng));
    for (int axis = 0; axis < 3; ++axis)  // face centres and points on faces
        for (double side : {-1.5, 1.5})
            for (int i = 0; i < 20; ++i) {
                Eigen::Vector3d p(inside(rng), inside(rng), inside(rng));
                p[axis] = side;
                points.push_back(p);
            }
    points.emplace_back(0.0, -1.5, -1.5);  // edge midpoints
    points.emplace_back(1.5, 0.0, 1.5);
    points.emplace_back(-1.5, 1.5, 0.25);
    std::shuffle(points.begin(), points.end(), rng);
    const Indices vertices = SilentHull(points);
    ASSERT_EQ(vertices.size(), 8u);
    std::set<std::vector<double>> got, expected;
    for (std::size_t v : vertices) got.insert({points[v].x(), points[v].y(), points[v].z()});
    for (const Eigen::Vector3d& c : CubeCorners(1.5)) expected.insert({c.x(), c.y(), c.z()});
    EXPECT_EQ(got, expected);
    EXPECT_TRUE(std::is_sorted(vertices.begin(), vertices.end()));
}

TEST(ConvexHull3D, TetrahedronWithInteriorPointsKeepsItsFourCorners) {
    const Points corners = {{0, 0, 0}, {4, 0, 0}, {0, 3, 0}, {0, 0, 5}};
    Points points;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {  // barycentric interior points
        double w[4], sum = 0.0;
        for (double& x : w) sum += (x = uni(rng) + 1e-3);
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) p += (w[k] / sum) * corners[k];
        points.push_back(p);
    }
    const std::size_t at[4] = {17, 0, 299, 150};  // the corners go in at these positions
    for (int k = 0; k < 4; ++k) points.insert(points.begin() + at[k], corners[k]);
    const Indices vertices = SilentHull(points);
    ASSERT_EQ(vertices.size(), 4u);
    for (std::size_t v : vertices)
        EXPECT_TRUE(std::find(corners.begin(), corners.end(), points[v]) != corners.end())
            << "vertex " << v << " = " << points[v].transpose();
}

TEST(ConvexHull3D, RandomCloudsMatchBruteForce) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> normal;
        std::uniform_real_distribution<double> uni(0.0, 1.0);
        Points points;
        // Half on a unit sphere (all vertices), half in the ball; a far offset tests scaling.
        const Eigen::Vector3d offset(100.0 * seed, -50.0, 7.0);
        for (int i = 0; i < 40; ++i) {
            const Eigen::Vector3d d = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
            const double r = (i % 2 == 0) ? 1.0 : 0.9 * std::cbrt(uni(rng));
            points.push_back(offset + r * d.normalized());
        }
        const Indices vertices = SilentHull(points);
        EXPECT_EQ(vertices, BruteForceVertices(points)) << "seed " << seed;
        ExpectContainsAll(points, vertices, 1e-12);
    }
}

TEST(ConvexHull3D, LargeCloudContainsEveryPointAndOnlyInputPoints) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    Points points;
    for (int i = 0; i < 20000; ++i) {
        // A box with a dome: many interior points, a curved top with many vertices.
        const double x = 10 * uni(rng), z = 6 * uni(rng);
        const double top = 2.0 + std::sqrt(std::max(0.0, 1.0 - (x * x / 100 + z * z / 36)));
        points.emplace_back(x, (0.5 + 0.5 * uni(rng)) * top, z);
    }
    const Indices vertices = SilentHull(points);
    ASSERT_GE(vertices.size(), 4u);
    EXPECT_LT(vertices.size(), points.size() / 10);
    EXPECT_TRUE(std::adjacent_find(vertices.begin(), vertices.end()) == vertices.end());
    for (std::size_t v : vertices) ASSERT_LT(v, points.size());
    ExpectContainsAll(points, vertices, 1e-12 * 10);
}

TEST(ConvexHull3D, CoplanarPointsGiveTheCornersOfTheirPlanarHull) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    // Exactly on y = 0 (a floor seen from above), and on a tilted plane through rounding.
    for (bool tilted : {false, true}) {
        Points points;
        std::vector<Eigen::Vector2d> planar;
        for (int i = 0; i < 3000; ++i) {
            const double x = 20 * uni(rng), z = 12 * uni(rng);
            if (x + z > 25) continue;  // a pentagon-ish region
            planar.emplace_back(x, z);
            points.emplace_back(x, tilted ? 0.3 * x - 0.7 * z + 2.0 : 0.0, z);
        }
        const Indices vertices = SilentHull(points);
        // The plane is a graph over (x, z), so its hull's corners are those of the (x, z) hull.
        std::set<std::pair<double, double>> got, expected;
        for (std::size_t v : vertices) got.insert({points[v].x(), points[v].z()});
        for (const Eigen::Vector2d& c : ConvexHull(planar)) expected.insert({c.x(), c.y()});
        EXPECT_EQ(got, expected) << (tilted ? "tilted" : "y = 0");
        ExpectContainsAll(points, vertices, 1e-12 * 25);
    }
}

TEST(ConvexHull3D, CollinearAndRepeatedPointsGiveTheExtremes) {
    Points line;
    for (int i = 0; i < 50; ++i) line.emplace_back(1.0 + 0.5 * (i % 17), 2.0, -3.0);
    line.push_back(line[3]);
    const Indices lineVertices = SilentHull(line);
    ASSERT_EQ(lineVertices.size(), 2u);
    EXPECT_EQ(line[lineVertices[0]].x() + line[lineVertices[1]].x(), 1.0 + 9.0);

    const Points same(7, Eigen::Vector3d(0.25, -1.0, 3.0));
    EXPECT_EQ(SilentHull(same).size(), 1u);

    Points repeatedCube;  // every corner three times, plus an interior point
    for (int copy = 0; copy < 3; ++copy)
        for (const Eigen::Vector3d& c : CubeCorners(2.0)) repeatedCube.push_back(c);
    repeatedCube.emplace_back(0.1, 0.2, 0.3);
    const Indices cubeVertices = SilentHull(repeatedCube);
    std::set<std::vector<double>> got;
    for (std::size_t v : cubeVertices)
        got.insert({repeatedCube[v].x(), repeatedCube[v].y(), repeatedCube[v].z()});
    EXPECT_EQ(got.size(), 8u);
    EXPECT_EQ(cubeVertices.size(), 8u);
}

TEST(ConvexHull3D, FewerThanFourPoints) {
    EXPECT_TRUE(SilentHull({}).empty());
    EXPECT_EQ(SilentHull({{1, 2, 3}}), Indices({0}));
    EXPECT_EQ(SilentHull({{1, 2, 3}, {1, 2, 3}}).size(), 1u);
    EXPECT_EQ(SilentHull({{1, 2, 3}, {4, 5, 6}}), Indices({0, 1}));
    EXPECT_EQ(SilentHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 1}}), Indices({0, 1, 2}));
    EXPECT_EQ(SilentHull({{0, 0, 0}, {2, 2, 2}, {1, 1, 1}}), Indices({0, 1}));
}

TEST(ConvexHull3D, NonFinitePointThrows) {
    Points points = CubeCorners(1.0);
    points[5].y() = std::numeric_limits<double>::quiet_NaN();
    try {
        ConvexHullVertices3D(points);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "convex hull 3d: point 5 is not finite");
    }
    points[5].y() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(ConvexHullVertices3D(points), std::invalid_argument);
}

}  // namespace
}  // namespace lexel
