// `lexel error-model`'s study (cases/studies/error_model/error_model_study.h): where the
// misclassified pixels lie. A camera looks straight down at the floor, and a plate above it (out of
// view) casts one straight shadow edge across the frame: every misclassified pixel is on the floor,
// and over a uniform sub-texel phase a straight edge's band is shadowed on one side as often as lit
// on the other.
#include "lexel/cases/studies/error_model/error_model_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "spatial/spatial_test_scenes.h"

namespace lexel::cases {
namespace {

spatial::Scene StraightEdgeOnFloor() {
    spatial::Scene scene;
    scene.name = "edge-on-floor";
    scene.camera.position = {0.0, 10.0, 0.0};
    scene.camera.target = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, 0.0, -1.0};
    scene.camera.resolution = {200, 200};
    scene.readback = {60, 60};
    scene.shadowMap = {64, 64};
    scene.geometry = spatial::testing::FloorQuad(40.0);
    scene.floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    // The plate: the floor's half-plane z > 0.3 x (within 30 units) lifted to y = 12, above the
    // camera, so that its shadow's one edge crosses the frame at about 17° to a texel axis.
    const glm::dvec3 edge = glm::normalize(glm::dvec3(1.0, 0.0, 0.3));
    const glm::dvec3 side(-edge.z, 0.0, edge.x);
    const glm::dvec3 lift(0.0, 12.0, 0.0);
    spatial::TriangleMesh plate;
    for (const glm::dvec3& c :
         {-30.0 * edge, 30.0 * edge, 30.0 * edge + 30.0 * side, -30.0 * edge + 30.0 * side})
        plate.positions.push_back(c + lift);
    plate.triangles = {{0, 1, 2}, {0, 2, 3}};
    scene.geometry.Append(plate);
    return scene;
}

spatial::Light StraightDown() {
    spatial::Light light;
    light.type = spatial::Light::Type::kDirectional;
    light.direction = {0.05, -1.0, 0.02};
    return light;
}

TEST(ErrorModelStudy, AStraightEdgeOnTheFloorSplitsEvenlyIntoFalseShadowAndFalseLight) {
    const ErrorModelStudy study = RunErrorModelStudy(StraightEdgeOnFloor(), {"focused-tight"},
                                                     {StraightDown()}, 16, BackendKind::kCpu);
    ASSERT_EQ(study.totals.size(), 1u);
    const ErrorModelTotals& t = study.totals[0];
    std::cout << "misclassified " << t.misclassified << ", on the floor " << t.onFloor
              << ", false shadow " << t.falseShadow << ", uncovered " << t.uncovered << "\n";
    ASSERT_GT(t.misclassified, 20.0);  // a band of ~60 texels' staircase, one per phase at least
    EXPECT_DOUBLE_EQ(t.onFloor, t.misclassified);  // the camera sees nothing but the floor
    EXPECT_DOUBLE_EQ(t.falseShadowOffFloor, 0.0);
    // E[false shadow] = E[false light] for a straight edge (the band is symmetric in the phase);
    // 16 phases of a ~60-step staircase leave a few percent. The pixels a shifted tight map does
    // not cover are shaded lit: false light wherever the rays shadow them, so they are left out.
    EXPECT_NEAR(t.falseShadow / (t.misclassified - t.uncovered), 0.5, 0.08);
}

TEST(ErrorModelStudy, WithoutAFloorPlaneNothingCountsAsFloor) {
    spatial::Scene scene = StraightEdgeOnFloor();
    const ErrorModelStudy withFloor =
        RunErrorModelStudy(scene, {"focused-tight"}, {StraightDown()}, 4, BackendKind::kCpu);
    scene.floorPlane.reset();
    const ErrorModelStudy without =
        RunErrorModelStudy(scene, {"focused-tight"}, {StraightDown()}, 4, BackendKind::kCpu);
    EXPECT_DOUBLE_EQ(without.totals[0].misclassified, withFloor.totals[0].misclassified);
    EXPECT_DOUBLE_EQ(without.totals[0].onFloor, 0.0);
    EXPECT_DOUBLE_EQ(without.totals[0].falseShadowOffFloor, without.totals[0].falseShadow);
}

}  // namespace
}  // namespace lexel::cases
