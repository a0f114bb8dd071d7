// Unit primitives: closed and outward (divergence-theorem volumes against closed forms), and
// transforms (order, round trips, winding under mirroring).
#include "lexel/spatial/harness/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <numbers>
#include <random>
#include <utility>

namespace lexel::spatial {
namespace {

constexpr double kPi = std::numbers::pi;

// Every undirected edge must be used by exactly two triangles, once in each direction (a closed,
// consistently oriented surface).
void ExpectWatertight(const TriangleMesh& mesh) {
    std::map<std::pair<unsigned, unsigned>, int> directed;
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, uses] : directed) {
        EXPECT_EQ(uses, 1) << "edge " << edge.first << "->" << edge.second;
        EXPECT_EQ(directed.count({edge.second, edge.first}), 1u)
            << "edge " << edge.first << "-" << edge.second << " has no opposite half";
    }
    EXPECT_EQ(directed.size(), 3 * mesh.triangles.size());
}

double Area(const TriangleMesh& mesh) {
    double area = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t[0]]), b(mesh.positions[t[1]]), c(mesh.positions[t[2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

// Every face points away from the centroid of the (convex) shape.
void ExpectFacesOutward(const TriangleMesh& mesh) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::dvec3 centroid =
            (glm::dvec3(mesh.positions[tri[0]]) + glm::dvec3(mesh.positions[tri[1]]) +
             glm::dvec3(mesh.positions[tri[2]])) /
            3.0;
        EXPECT_GT(glm::dot(mesh.FaceNormal(t), centroid), 0.0) << "triangle " << t;
    }
}

// The UV sphere is a stack of prismatoids whose cross-sections are regular n-gons with
// circumradius linear in y between rings, so Simpson's rule is exact:
// V = (n/2) sin(2π/n) Σ h/3 (r₁² + r₁r₂ + r₂²) over the bands.
double UvSphereVolume(int slices, int stacks) {
    double sum = 0.0;
    for (int i = 0; i < stacks; ++i) {
        const double t1 = kPi * i / stacks, t2 = kPi * (i + 1) / stacks;
        const double r1 = std::sin(t1), r2 = std::sin(t2), h = std::cos(t1) - std::cos(t2);
        sum += h / 3.0 * (r1 * r1 + r1 * r2 + r2 * r2);
    }
    return 0.5 * slices * std::sin(2.0 * kPi / slices) * sum;
}

TEST(Primitives, PlaneIsTheUnitSquareFacingUp) {
    const TriangleMesh plane = MakePlane();
    ASSERT_EQ(plane.triangles.size(), 2u);
    for (std::size_t t = 0; t < 2; ++t) EXPECT_EQ(plane.FaceNormal(t), glm::dvec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(Area(plane), 1.0);
    const Bounds b = plane.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-0.5, 0.0, -0.5));
    EXPECT_EQ(b.hi, glm::dvec3(0.5, 0.0, 0.5));
}

TEST(Primitives, BoxIsClosedOutwardWithUnitVolume) {
    const TriangleMesh box = MakeBox();
    EXPECT_EQ(box.positions.size(), 8u);
    EXPECT_EQ(box.triangles.size(), 12u);
    ExpectWatertight(box);
    ExpectFacesOutward(box);
    EXPECT_DOUBLE_EQ(SignedVolume(box), 1.0);
    EXPECT_DOUBLE_EQ(Area(box), 6.0);
    const Bounds b = box.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-0.5));
    EXPECT_EQ(b.hi, glm::dvec3(0.5));
}

TEST(Primitives, SphereVolumeMatchesThePolyhedronAndConvergesToFourThirdsPi) {
    for (auto [slices, stacks] : {std::pair{3, 2}, {8, 4}, {32, 16}, {128, 64}}) {
        SCOPED_TRACE(testing::Message() << slices << " slices, " << stacks << " stacks");
        const TriangleMesh sphere = MakeSphere(slices, stacks);
        EXPECT_EQ(sphere.triangles.size(), std::size_t(2 * slices * (stacks - 1)));
        ExpectWatertight(sphere);
        ExpectFacesOutward(sphere);
        const double volume = SignedVolume(sphere);
        // Positions are floats: relative error ~1e-7.
        EXPECT_NEAR(volume, UvSphereVolume(slices, stacks), 1e-6);
        // Inscribed: the polyhedron lies inside the ball and contains the ball of radius rMin, the
        // smallest distance from the centre to a face plane.
        double rMin = 1.0;
        for (std::size_t t = 0; t < sphere.triangles.size(); ++t)
            rMin = std::min(rMin, glm::dot(sphere.FaceNormal(t),
                                           glm::dvec3(sphere.positions[sphere.triangles[t][0]])));
        EXPECT_LE(volume, 4.0 / 3.0 * kPi + 1e-6);
        EXPECT_GE(volume, 4.0 / 3.0 * kPi * rMin * rMin * rMin - 1e-6);
    }
    // Faceting error by the closed form above: 1.6% at the default 32 × 16 (4.12194 against
    // 4.18879), 0.0042 at 128 × 64.
    EXPECT_NEAR(SignedVolume(MakeSphere()), 4.0 / 3.0 * kPi, 0.017 * 4.0 / 3.0 * kPi);
    EXPECT_NEAR(SignedVolume(MakeSphere(128, 64)), 4.0 / 3.0 * kPi, 5e-3);
    EXPECT_NEAR(Area(MakeSphere(256, 128)), 4.0 * kPi, 2e-3);  // faceting: 1.6e-3
}

TEST(Primitives, CylinderIsAPrismOverARegularPolygon) {
    for (int slices : {3, 7, 32, 256}) {
        SCOPED_TRACE(testing::Message() << slices << " slices");
        const TriangleMesh cylinder = MakeCylinder(slices);
        EXPECT_EQ(cylinder.triangles.size(), std::size_t(4 * slices));
        ExpectWatertight(cylinder);
        ExpectFacesOutward(cylinder);
        // Height 1 times the inscribed regular n-gon's area (n/2) sin(2π/n).
        const double polygon = 0.5 * slices * std::sin(2.0 * kPi / slices);
        EXPECT_NEAR(SignedVolume(cylinder), polygon, 1e-6);
        const Bounds b = cylinder.ComputeBounds();
        EXPECT_FLOAT_EQ(b.lo.y, -0.5f);
        EXPECT_FLOAT_EQ(b.hi.y, 0.5f);
    }
    EXPECT_NEAR(SignedVolume(MakeCylinder(256)), kPi, 4e-4);
}

TEST(Primitives, RejectsTooFewSegments) {
    EXPECT_THROW(MakeSphere(2, 8), std::invalid_argument);
    EXPECT_THROW(MakeSphere(8, 1), std::invalid_argument);
    EXPECT_THROW(MakeCylinder(2), std::invalid_argument);
}

TEST(Transform, ScalesThenRotatesXYZThenTranslates) {
    Transform t;
    t.scale = {2.0, 3.0, 4.0};
    t.rotateDeg = {90.0, 90.0, 0.0};
    t.translate = {10.0, 20.0, 30.0};
    // x̂ → (2,0,0) → Rx: (2,0,0) → Ry(90°): (0,0,-2) → +T.
    const glm::dvec3 x = glm::dvec3(t.Matrix() * glm::dvec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(x, glm::dvec3(10, 20, 28)), 0.0, 1e-12);
    // ŷ → (0,3,0) → Rx(90°): (0,0,3) → Ry(90°): (3,0,0) → +T.
    const glm::dvec3 y = glm::dvec3(t.Matrix() * glm::dvec4(0, 1, 0, 1));
    EXPECT_NEAR(glm::distance(y, glm::dvec3(13, 20, 30)), 0.0, 1e-12);
    // Z last: ẑ → (0,0,1) → Rz(90°): (-1,0,0) with the others zero.
    Transform z;
    z.rotateDeg = {0.0, 0.0, 90.0};
    const glm::dvec3 zx = glm::dvec3(z.Matrix() * glm::dvec4(1, 0, 0, 1));
    EXPECT_NEAR(glm::distance(zx, glm::dvec3(0, 1, 0)), 0.0, 1e-12);
}

TEST(Transform, RandomRoundTripsAndVolumeScaling) {
    std::mt19937_64 rng(20240611);
    auto uniform = [&](double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    };
    const TriangleMesh box = MakeBox();
    for (int trial = 0; trial < 50; ++trial) {
        Transform t;
        t.translate = {uniform(-10, 10), uniform(-10, 10), uniform(-10, 10)};
        t.rotateDeg = {uniform(-180, 180), uniform(-180, 180), uniform(-180, 180)};
        t.scale = {uniform(0.1, 5), uniform(0.1, 5), uniform(0.1, 5)};
        SCOPED_TRACE(testing::Message()
                     << "trial " << trial << ": translate (" << t.translate.x << ", "
                     << t.translate.y << ", " << t.translate.z << "), rotate (" << t.rotateDeg.x
                     << ", " << t.rotateDeg.y << ", " << t.rotateDeg.z << "), scale (" << t.scale.x
                     << ", " << t.scale.y << ", " << t.scale.z << ")");
        const glm::dmat4 m = t.Matrix();
        const TriangleMesh moved = TransformMesh(box, t);
        const TriangleMesh back = TransformMesh(moved, glm::inverse(m));
        for (std::size_t i = 0; i < box.positions.size(); ++i)
            EXPECT_NEAR(glm::distance(glm::dvec3(back.positions[i]), glm::dvec3(box.positions[i])),
                        0.0, 1e-5);
        // Rotation preserves volume; the scale multiplies it.
        const double expected = t.scale.x * t.scale.y * t.scale.z;
        EXPECT_NEAR(SignedVolume(moved), expected,
                    1e-5 * (1.0 + expected + glm::length(t.translate)));
        // The box's centre goes where the translation says.
        EXPECT_NEAR(glm::distance(moved.ComputeBounds().Center(), t.translate), 0.0, 1e-4);
    }
}

TEST(Transform, MirroringKeepsFacesOutward) {
    Transform mirror;
    mirror.scale = {-1.0, 2.0, 1.0};
    const TriangleMesh sphere = TransformMesh(MakeSphere(16, 8), mirror);
    ExpectWatertight(sphere);
    EXPECT_NEAR(SignedVolume(sphere), 2.0 * UvSphereVolume(16, 8), 1e-5);
}

}  // namespace
}  // namespace lexel::spatial
