// The floor-objects scene and the light sweep of the report's experiment (§3).
#include "lexel/spatial/harness/generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "lexel/solvers/geometry.h"
#include "lexel/spatial/harness/primitives.h"

namespace lexel::spatial {
namespace {

constexpr double kPi = std::numbers::pi;

bool SameMesh(const TriangleMesh& a, const TriangleMesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles;
}

TEST(FloorObjects, IsDeterministicForASeed) {
    glm::dvec4 plane(0.0);
    const TriangleMesh a = FloorObjects(36, 1, &plane);
    const TriangleMesh b = FloorObjects(36, 1, nullptr);
    EXPECT_TRUE(SameMesh(a, b));
    EXPECT_FALSE(SameMesh(a, FloorObjects(36, 2, nullptr)));
    EXPECT_EQ(plane, glm::dvec4(0.0, 1.0, 0.0, 0.0));
}

TEST(FloorObjects, FloorOnlyForZeroObjects) {
    const TriangleMesh floor = FloorObjects(0, 5, nullptr);
    ASSERT_EQ(floor.triangles.size(), 2u);
    const Bounds b = floor.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-kFloorHalfSize, 0.0, -kFloorHalfSize));
    EXPECT_EQ(b.hi, glm::dvec3(kFloorHalfSize, 0.0, kFloorHalfSize));
    EXPECT_EQ(floor.FaceNormal(0), glm::dvec3(0, 1, 0));
    EXPECT_THROW(FloorObjects(-1, 5, nullptr), std::invalid_argument);
}

// Splits a scene into its connected components (each generated object is one closed, connected
// primitive; the floor is another), in order of their first triangle.
std::vector<TriangleMesh> Components(const TriangleMesh& scene) {
    std::vector<unsigned> parent(scene.positions.size());
    for (unsigned i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](unsigned v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const glm::uvec3& t : scene.triangles) {
        parent[find(t[1])] = find(t[0]);
        parent[find(t[2])] = find(t[0]);
    }
    std::map<unsigned, std::size_t> slot;
    std::vector<TriangleMesh> parts;
    std::vector<std::map<unsigned, unsigned>> remap;
    for (const glm::uvec3& t : scene.triangles) {
        const unsigned root = find(t[0]);
        if (!slot.count(root))
            slot[root] = parts.size(), parts.emplace_back(), remap.emplace_back();
        TriangleMesh& part = parts[slot[root]];
        auto& ids = remap[slot[root]];
        glm::uvec3 local;
        for (int k = 0; k < 3; ++k) {
            auto [it, added] = ids.try_emplace(t[k], static_cast<unsigned>(part.positions.size()));
            if (added) part.positions.push_back(scene.positions[t[k]]);
            local[k] = it->second;
        }
        part.triangles.push_back(local);
    }
    return parts;
}

TEST(FloorObjects, ObjectsAreClosedSizedAndOnTheFloor) {
    const std::size_t boxTris = MakeBox().triangles.size(),
                      sphereTris = MakeSphere().triangles.size(),
                      cylinderTris = MakeCylinder().triangles.size();
    for (std::uint64_t seed : {1u, 2u, 3u, 42u}) {
        SCOPED_TRACE(testing::Message() << "seed " << seed);
        const int count = 36;
        const auto parts = Components(FloorObjects(count, seed, nullptr));
        ASSERT_EQ(parts.size(), std::size_t(count + 1));
        EXPECT_EQ(parts[0].triangles.size(), 2u);  // the floor comes first
        int resting = 0, floating = 0, kinds[3] = {0, 0, 0};
        std::vector<std::pair<glm::dvec2, double>> footprints;
        for (std::size_t i = 1; i < parts.size(); ++i) {
            SCOPED_TRACE(testing::Message() << "object " << i);
            const TriangleMesh& object = parts[i];
            const std::size_t n = object.triangles.size();
            ASSERT_TRUE(n == boxTris || n == sphereTris || n == cylinderTris) << n;
            ++kinds[n == boxTris ? 0 : n == sphereTris ? 1 : 2];
            EXPECT_GT(SignedVolume(object), 0.0) << "faces inward";
            const Bounds b = object.ComputeBounds();
            // Inside the placement square, on or at most 1 unit above the floor.
            EXPECT_GE(b.lo.x, -18.0 - 1e-4);
            EXPECT_LE(b.hi.x, 18.0 + 1e-4);
            EXPECT_GE(b.lo.z, -18.0 - 1e-4);
            EXPECT_LE(b.hi.z, 18.0 + 1e-4);
            EXPECT_GE(b.lo.y, -1e-5);
            EXPECT_LE(b.lo.y, 1.0 + 1e-5);
            (b.lo.y < 1e-5 ? resting : floating)++;
            // Extents 0.3–2.5 before turning; a turn can stretch the bounds by at most √3.
            const glm::dvec3 size = b.hi - b.lo;
            EXPECT_GE(std::max({size.x, size.y, size.z}), 0.3 - 1e-4);
            EXPECT_LE(std::max({size.x, size.y, size.z}), 2.5 * std::sqrt(3.0));
            footprints.push_back({glm::dvec2(b.Center().x, b.Center().z),
                                  0.5 * glm::length(glm::dvec2(size.x, size.z))});
        }
        EXPECT_GT(resting, 0);
        EXPECT_GT(floating, 0);
        for (int k : kinds) EXPECT_GT(k, 0);
        // 36 objects on a 36 × 36 square leave room: no two footprint circles overlap.
        for (std::size_t i = 0; i < footprints.size(); ++i)
            for (std::size_t j = i + 1; j < footprints.size(); ++j)
                EXPECT_GE(glm::distance(footprints[i].first, footprints[j].first),
                          footprints[i].second + footprints[j].second - 1e-4)
                    << "objects " << i + 1 << " and " << j + 1 << " overlap";
    }
}

TEST(FloorObjects, CrowdedFloorsStillPlaceEveryObject) {
    // 1000 objects cannot all fit without overlap; they are still all placed, inside the floor.
    const TriangleMesh scene = FloorObjects(1000, 9, nullptr);
    const auto parts = Components(scene);
    EXPECT_EQ(parts.size(), 1001u);
    const Bounds b = scene.ComputeBounds();
    EXPECT_EQ(b.lo.x, -kFloorHalfSize);
    EXPECT_EQ(b.hi.z, kFloorHalfSize);
    EXPECT_GE(b.lo.y, -1e-5);
    EXPECT_LE(b.hi.y, 1.0 + 2.5 * std::sqrt(3.0));
}

TEST(SweepLights, CountRadiusElevationAndDeterminism) {
    LightSweep sweep;
    sweep.count = 500;
    sweep.seed = 7;
    sweep.radius = 100.0;
    const glm::dvec3 centre(1.0, 2.0, -3.0);
    const auto lights = SweepLights(sweep, centre);
    ASSERT_EQ(lights.size(), 500u);
    const double minY = std::sin(kSweepMinElevationDeg * kPi / 180.0);
    for (const Light& light : lights) {
        EXPECT_EQ(light.type, Light::Type::kPoint);
        EXPECT_NEAR(glm::distance(light.position, centre), 100.0, 1e-9);
        EXPECT_GE((light.position.y - centre.y) / 100.0, minY - 1e-12);
    }
    const auto again = SweepLights(sweep, centre);
    for (std::size_t i = 0; i < lights.size(); ++i)
        EXPECT_EQ(lights[i].position, again[i].position);
    sweep.seed = 8;
    EXPECT_NE(SweepLights(sweep, centre)[0].position, lights[0].position);
    sweep.count = 0;
    EXPECT_TRUE(SweepLights(sweep, centre).empty());
    sweep.radius = 0.0;
    EXPECT_THROW(SweepLights(sweep, centre), std::invalid_argument);
}

// Directional sweeps shine from the same hemisphere points toward the centre: for one seed the
// direction of light k is exactly minus the unit offset of point light k.
TEST(SweepLights, DirectionalLightsShineFromThePointSweepsPositions) {
    LightSweep sweep;
    sweep.count = 50;
    sweep.seed = 11;
    sweep.radius = 80.0;
    const glm::dvec3 centre(1.0, 0.0, -2.0);
    const auto points = SweepLights(sweep, centre);
    sweep.type = Light::Type::kDirectional;
    const auto suns = SweepLights(sweep, centre);
    ASSERT_EQ(suns.size(), points.size());
    for (std::size_t k = 0; k < suns.size(); ++k) {
        EXPECT_EQ(suns[k].type, Light::Type::kDirectional);
        const glm::dvec3 unit = (points[k].position - centre) / sweep.radius;
        EXPECT_NEAR(glm::length(suns[k].direction + unit), 0.0, 1e-12) << "light " << k;
        EXPECT_LT(suns[k].direction.y, -std::sin(Radians(kSweepMinElevationDeg)) + 1e-12);
    }
}

TEST(SweepLights, UniformInAreaOverTheHemisphere) {
    LightSweep sweep;
    sweep.count = 20000;
    sweep.seed = 12345;
    sweep.radius = 1.0;
    const auto lights = SweepLights(sweep, glm::dvec3(0.0));
    const double n = sweep.count;
    // y uniform on [sin 5°, 1]: mean (1 + sin 5°)/2 = 0.5436, standard deviation
    // (1 - sin 5°)/√12 = 0.2635, so the mean of 20000 has σ = 0.00186; allow 4σ.
    const double minY = std::sin(kSweepMinElevationDeg * kPi / 180.0);
    double sumY = 0.0;
    int quadrant[4] = {0, 0, 0, 0};
    int belowHalf = 0;
    for (const Light& light : lights) {
        const glm::dvec3 u = light.position;
        sumY += u.y;
        belowHalf += u.y < 0.5 * (1.0 + minY);
        ++quadrant[(u.x >= 0 ? 0 : 1) + (u.z >= 0 ? 0 : 2)];
    }
    const double sigmaMean = (1.0 - minY) / std::sqrt(12.0) / std::sqrt(n);
    EXPECT_NEAR(sumY / n, 0.5 * (1.0 + minY), 4.0 * sigmaMean) << "seed " << sweep.seed;
    // Each quadrant is binomial(n, 1/4): σ = √(n·3/16) = 61.2; allow 4σ. The median split of y
    // is binomial(n, 1/2): σ = 70.7.
    for (int q = 0; q < 4; ++q)
        EXPECT_NEAR(quadrant[q], n / 4, 4.0 * std::sqrt(n * 3.0 / 16.0))
            << "quadrant " << q << ", seed " << sweep.seed;
    EXPECT_NEAR(belowHalf, n / 2, 4.0 * std::sqrt(n / 4.0)) << "seed " << sweep.seed;
}

}  // namespace
}  // namespace lexel::spatial
