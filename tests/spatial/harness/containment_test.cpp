// Point-in-closed-geometry by ray parity (containment.h): crossing counts and distances against
// the unit primitives' closed forms, and the cases the loader relies on.
#include "lexel/spatial/harness/containment.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lexel/spatial/harness/primitives.h"

namespace lexel::spatial {
namespace {

std::span<const glm::uvec3> All(const TriangleMesh& mesh) { return mesh.triangles; }

TEST(Containment, RayFromInsideTheCubeLeavesThroughOneBackFace) {
    const TriangleMesh cube = MakeBox();  // [-0.5, 0.5]³, outward
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.5377, 0.8324, 0.1347));
    const RayCrossings crossings = CastThrough(cube, All(cube), glm::dvec3(0.0), direction);
    EXPECT_EQ(crossings.count, 1);
    EXPECT_TRUE(crossings.nearestIsBackFace);
    // It leaves through y = 0.5 (its largest component): t = 0.5 / d.y.
    EXPECT_NEAR(crossings.nearestT, 0.5 / direction.y, 1e-15);
}

TEST(Containment, RayFromOutsideCrossesTheCubeTwiceFrontFirst) {
    const TriangleMesh cube = MakeBox();
    // Off the faces' diagonals, so no shared edge is hit.
    const RayCrossings crossings =
        CastThrough(cube, All(cube), glm::dvec3(0.1, 0.2, -2.0), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(crossings.count, 2);
    EXPECT_FALSE(crossings.nearestIsBackFace);
    EXPECT_DOUBLE_EQ(crossings.nearestT, 1.5);
    // Pointing away: nothing.
    EXPECT_EQ(
        CastThrough(cube, All(cube), glm::dvec3(0.1, 0.2, -2.0), glm::dvec3(0.0, 0.0, -1.0)).count,
        0);
}

TEST(Containment, InsideTheSphereAndTheCubeOnly) {
    // The UV sphere's faces are at least cos(π/16) ≈ 0.98 from its centre.
    const TriangleMesh sphere = MakeSphere();
    EXPECT_TRUE(InsideClosedGeometry(sphere, All(sphere), glm::dvec3(0.0)));
    EXPECT_TRUE(InsideClosedGeometry(sphere, All(sphere), glm::dvec3(0.5, -0.3, 0.6)));  // |.| 0.84
    EXPECT_FALSE(InsideClosedGeometry(sphere, All(sphere), glm::dvec3(0.8, -0.6, 0.5)));  // 1.12
    const TriangleMesh cube = MakeBox();
    EXPECT_TRUE(InsideClosedGeometry(cube, All(cube), glm::dvec3(0.45, -0.45, 0.45)));
    EXPECT_FALSE(InsideClosedGeometry(cube, All(cube), glm::dvec3(0.55, 0.0, 0.0)));
}

TEST(Containment, OpenSheetsDoNotEnclose) {
    // Between a floor (y = 0) and a ceiling (y = 3), both 100 wide: every ray crosses one sheet,
    // an odd count, but the ones going down meet the floor's front.
    TriangleMesh sheets =
        TransformMesh(MakePlane(), Transform{{0, 0, 0}, {0, 0, 0}, {100, 1, 100}});
    sheets.Append(TransformMesh(MakePlane(), Transform{{0, 3, 0}, {0, 0, 0}, {100, 1, 100}}));
    EXPECT_FALSE(InsideClosedGeometry(sheets, All(sheets), glm::dvec3(0.0, 1.5, 0.0)));
    // Under a single floor, a ray going up crosses it once (a back face) and one going down
    // nothing.
    const TriangleMesh floor =
        TransformMesh(MakePlane(), Transform{{0, 0, 0}, {0, 0, 0}, {100, 1, 100}});
    EXPECT_FALSE(InsideClosedGeometry(floor, All(floor), glm::dvec3(0.0, -1.0, 0.0)));
}

TEST(Containment, ACubeOnTheFloorIsTestedOnItsOwn) {
    // The cube's bottom lies in the floor's plane: through both, a ray down counts 2 crossings.
    TriangleMesh scene = TransformMesh(MakePlane(), Transform{{0, 0, 0}, {0, 0, 0}, {20, 1, 20}});
    const std::size_t floorEnd = scene.triangles.size();
    scene.Append(TransformMesh(MakeBox(), Transform{{0, 3, 0}, {0, 0, 0}, {6, 6, 6}}));
    const glm::dvec3 wsCamera(0.0, 2.0, -1.0);
    EXPECT_FALSE(InsideClosedGeometry(scene, All(scene), wsCamera));
    EXPECT_TRUE(InsideClosedGeometry(scene, All(scene).subspan(floorEnd), wsCamera));
}

}  // namespace
}  // namespace lexel::spatial
