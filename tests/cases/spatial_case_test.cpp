// 3D case files: the shipped cases load as documented, and every kind of bad input is an
// InputError naming the JSON pointer.
#include "lexel/cases/load/spatial_case.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/primitives.h"

namespace lexel::cases {
namespace {

const char* kGood = R"({
  "name": "unit",
  "description": "every field",
  "camera": {"position": [0, 1.7, -10], "target": [0, 1, 0], "up": [0, 1, 0], "fov_y_deg": 50,
             "width": 640, "height": 480, "near": 0.5, "far": 80},
  "lights": [{"type": "point", "position": [3, 20, -4]},
             {"type": "directional", "direction": [0, -2, 0]}],
  "shadow_map": {"width": 512, "height": 256},
  "readback": {"width": 64, "height": 32},
  "geometry": [
    {"primitive": "plane", "transform": {"scale": [20, 1, 20], "translate": [0, -1, 0]}},
    {"primitive": "box", "transform": {"scale": [1, 2, 3], "translate": [1, 0, 1]}},
    {"primitive": "sphere", "transform": {"scale": 0.5, "translate": [-3, 0, 0]}},
    {"primitive": "cylinder", "transform": {"rotate_deg": [90, 0, 0], "translate": [3, 0, -3]}},
    {"primitive": "plane", "transform": {"translate": [0, 5, 0]}}
  ],
  "light_sweep": {"count": 12, "seed": 3, "radius": 40},
  "camera_path": [{"position": [0, 1.7, -9], "target": [0, 1, 1]},
                  {"position": [1, 1.7, -8], "target": [1, 1, 2], "up": [0, 0, 1]}]
})";

spatial::Scene FromPatch(const std::string& patch) {
    nlohmann::json doc = nlohmann::json::parse(kGood);
    doc = doc.patch(nlohmann::json::parse(patch));
    return SpatialSceneFromJson(doc, "fallback", ".");
}

std::string ErrorFor(const std::string& patch) {
    try {
        FromPatch(patch);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

std::string ErrorForText(const std::string& text) {
    try {
        SpatialSceneFromJson(nlohmann::json::parse(text), "x", ".");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(SpatialCase, LoadsEveryField) {
    const spatial::Scene scene = FromPatch("[]");
    EXPECT_EQ(scene.name, "unit");
    EXPECT_EQ(scene.camera.position, glm::dvec3(0, 1.7, -10));
    EXPECT_EQ(scene.camera.target, glm::dvec3(0, 1, 0));
    EXPECT_EQ(scene.camera.fovYDeg, 50.0);
    EXPECT_EQ(scene.camera.resolution.width, 640);
    EXPECT_EQ(scene.camera.resolution.height, 480);
    EXPECT_EQ(scene.camera.nearPlane, 0.5);
    EXPECT_EQ(scene.camera.farPlane, 80.0);
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].type, spatial::Light::Type::kPoint);
    EXPECT_EQ(scene.lights[0].position, glm::dvec3(3, 20, -4));
    EXPECT_EQ(scene.lights[1].type, spatial::Light::Type::kDirectional);
    EXPECT_EQ(scene.lights[1].direction, glm::dvec3(0, -1, 0));  // normalized
    EXPECT_EQ(scene.shadowMap.width, 512);
    EXPECT_EQ(scene.shadowMap.height, 256);
    EXPECT_EQ(scene.readback.width, 64);
    EXPECT_EQ(scene.readback.height, 32);
    // Triangles: 2 planes, a box, the default sphere and cylinder.
    EXPECT_EQ(scene.geometry.triangles.size(), 2 * 2 + 12 + spatial::MakeSphere().triangles.size() +
                                                   spatial::MakeCylinder().triangles.size());
    // The floor is the first plane (y = -1), not the second.
    ASSERT_TRUE(scene.floorPlane.has_value());
    EXPECT_EQ(*scene.floorPlane, glm::dvec4(0, 1, 0, 1));
    const spatial::Bounds b = scene.geometry.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-10, -1, -10));
    EXPECT_EQ(b.hi, glm::dvec3(10, 5, 10));
    ASSERT_TRUE(scene.lightSweep.has_value());
    EXPECT_EQ(scene.lightSweep->count, 12);
    EXPECT_EQ(scene.lightSweep->seed, 3u);
    EXPECT_EQ(scene.lightSweep->radius, 40.0);
    ASSERT_EQ(scene.cameraPath.size(), 2u);
    EXPECT_EQ(scene.cameraPath[0].position, glm::dvec3(0, 1.7, -9));
    EXPECT_EQ(scene.cameraPath[0].up, glm::dvec3(0, 1, 0));  // inherited
    EXPECT_EQ(scene.cameraPath[1].up, glm::dvec3(0, 0, 1));
    EXPECT_EQ(scene.cameraPath[1].fovYDeg, 50.0);  // inherited
    EXPECT_EQ(scene.cameraPath[1].resolution.width, 640);
}

TEST(SpatialCase, TransformsPlaceThePrimitives) {
    // A lone box: scale, then rotate 90° about y (x ↔ z), then translate.
    const spatial::Scene scene = FromPatch(R"([
        {"op": "replace", "path": "/geometry", "value": [
            {"primitive": "box",
             "transform": {"scale": [2, 4, 6], "rotate_deg": [0, 90, 0], "translate": [1, 2, 3]}}]},
        {"op": "replace", "path": "/light_sweep/radius", "value": 10}])");
    const spatial::Bounds b = scene.geometry.ComputeBounds();
    EXPECT_NEAR(glm::distance(b.lo, glm::dvec3(1 - 3, 2 - 2, 3 - 1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::distance(b.hi, glm::dvec3(1 + 3, 2 + 2, 3 + 1)), 0.0, 1e-6);
    EXPECT_NEAR(spatial::SignedVolume(scene.geometry), 48.0, 1e-4);
    EXPECT_FALSE(scene.floorPlane.has_value());
}

TEST(SpatialCase, TiltedPlaneGivesAUnitFloorNormal) {
    // A plane tilted 30° about x through (0, 2, 0): normal (0, cos 30°, sin 30°), d = -2 cos 30°.
    const spatial::Scene scene = FromPatch(R"([
        {"op": "replace", "path": "/geometry/0/transform",
         "value": {"scale": [20, 1, 20], "rotate_deg": [30, 0, 0], "translate": [0, 2, 0]}}])");
    ASSERT_TRUE(scene.floorPlane.has_value());
    const double c = std::cos(glm::radians(30.0)), s = std::sin(glm::radians(30.0));
    EXPECT_NEAR(glm::distance(*scene.floorPlane, glm::dvec4(0, c, s, -2 * c)), 0.0, 1e-12);
}

TEST(SpatialCase, GeneratorAppendsTheFloorObjects) {
    // Only the required fields, a generator and an all-default light sweep (no lights).
    const spatial::Scene scene = SpatialSceneFromJson(nlohmann::json::parse(R"({
        "camera": {"position": [0, 1.7, -19], "target": [0, 1, 0], "fov_y_deg": 60,
                   "width": 100, "height": 100},
        "generator": {"kind": "floor_objects", "count": 5, "seed": 11},
        "light_sweep": {}})"),
                                                      "gen", ".");
    EXPECT_EQ(scene.name, "gen");
    EXPECT_TRUE(scene.lights.empty());
    ASSERT_TRUE(scene.lightSweep.has_value());  // defaults: the report's 500 lights
    EXPECT_EQ(scene.lightSweep->count, 500);
    EXPECT_EQ(scene.lightSweep->seed, 7u);
    EXPECT_EQ(scene.lightSweep->radius, 100.0);
    const spatial::TriangleMesh expected = spatial::FloorObjects(5, 11, nullptr);
    EXPECT_EQ(scene.geometry.positions, expected.positions);
    EXPECT_EQ(scene.geometry.triangles, expected.triangles);
    ASSERT_TRUE(scene.floorPlane.has_value());
    EXPECT_EQ(*scene.floorPlane, glm::dvec4(0, 1, 0, 0));
    // Defaults of the optional fields.
    EXPECT_EQ(scene.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(scene.camera.nearPlane, 0.1);
    EXPECT_EQ(scene.camera.farPlane, 200.0);
    EXPECT_EQ(scene.shadowMap.width, 400);
    EXPECT_EQ(scene.shadowMap.height, 400);
    EXPECT_EQ(scene.readback.width, 180);
    EXPECT_EQ(scene.readback.height, 180);
    EXPECT_TRUE(IsSpatialCase(nlohmann::json::parse(R"({"light_sweep": {}})")));
}

// phases and max_phases: K, and the most a mean is raised to (0 when absent: exactly K).
TEST(SpatialCase, PhasesAndMaxPhases) {
    EXPECT_EQ(FromPatch("[]").phases, 1);
    EXPECT_EQ(FromPatch("[]").maxPhases, 0);
    const spatial::Scene scene = FromPatch(R"([{"op": "add", "path": "/phases", "value": 16},
                                               {"op": "add", "path": "/max_phases", "value": 64}])");
    EXPECT_EQ(scene.phases, 16);
    EXPECT_EQ(scene.maxPhases, 64);
}

TEST(SpatialCase, BadFieldsAreNamed) {
    auto replace = [](const std::string& path, const std::string& value) {
        return ErrorFor(R"([{"op": "replace", "path": ")" + path + R"(", "value": )" + value +
                        "}]");
    };
    auto add = [](const std::string& path, const std::string& value) {
        return ErrorFor(R"([{"op": "add", "path": ")" + path + R"(", "value": )" + value + "}]");
    };
    auto remove = [](const std::string& path) {
        return ErrorFor(R"([{"op": "remove", "path": ")" + path + R"("}])");
    };
    // The document, unknown keys, types, null for a number, ranges.
    EXPECT_EQ(ErrorForText("[]"), "/: must be an object, got an array");
    EXPECT_EQ(add("/colour", "1"),
              "/colour: unknown key (allowed here: camera, name, description, lights, shadow_map, "
              "readback, geometry, generator, light_sweep, camera_path, cascades, methods, "
              "phases, max_phases, optimizer)");
    EXPECT_EQ(add("/phases", "0"), "/phases: must be in [1, 256], got 0");
    EXPECT_EQ(add("/max_phases", "257"), "/max_phases: must be in [1, 256], got 257");
    EXPECT_EQ(ErrorFor(R"([{"op": "add", "path": "/phases", "value": 16},
                           {"op": "add", "path": "/max_phases", "value": 8}])"),
              "/max_phases: must be at least phases (16), got 8");
    EXPECT_EQ(add("/phases", "257"), "/phases: must be in [1, 256], got 257");
    EXPECT_EQ(add("/phases", "2.5"), "/phases: must be an integer, got 2.5");
    EXPECT_EQ(
        add("/camera/zoom", "2"),
        "/camera/zoom: unknown key (allowed here: position, target, fov_y_deg, width, height, "
        "up, near, far)");
    EXPECT_EQ(remove("/camera/fov_y_deg"), "/camera/fov_y_deg: required key is missing");
    EXPECT_EQ(replace("/camera/fov_y_deg", "180"),
              "/camera/fov_y_deg: must be in (0, 180), got 180");
    EXPECT_EQ(replace("/camera/fov_y_deg", "null"),
              "/camera/fov_y_deg: must be a number, got null");
    EXPECT_EQ(replace("/camera/width", "0"), "/camera/width: must be in [1, 16384], got 0");
    EXPECT_EQ(replace("/camera/height", "16385"),
              "/camera/height: must be in [1, 16384], got 16385");
    EXPECT_EQ(replace("/camera/width", "640.5"), "/camera/width: must be an integer, got 640.5");
    EXPECT_EQ(replace("/camera/near", "0"), "/camera/near: must be in (0, inf), got 0");
    EXPECT_EQ(replace("/camera/far", "0.5"),
              "/camera/far: far (0.5) must be greater than near (0.5)");
    EXPECT_EQ(replace("/camera/position", "[0, 1]"),
              "/camera/position: must be an array of 3 numbers, got 2 elements");
    EXPECT_EQ(replace("/camera/position/1", "\"up\""),
              "/camera/position/1: must be a number, got a string");
    EXPECT_EQ(replace("/camera/target", "[0, 1.7, -10]"),
              "/camera/target: must differ from position [0, 1.7, -10]");
    EXPECT_EQ(replace("/camera/up", "[0, -0.7, 10]"),
              "/camera/up: must not be parallel to the view direction (target - position = "
              "[0, -0.7, 10])");
    EXPECT_EQ(replace("/camera/up", "[0, 0, 0]"), "/camera/up: must be a non-zero vector");
    // Lights.
    EXPECT_EQ(replace("/lights/0/type", "\"spot\""),
              "/lights/0/type: must be one of point, directional, got 'spot'");
    EXPECT_EQ(add("/lights/1/position", "[0, 9, 0]"),
              "/lights/1/position: unknown key (allowed here: type, direction)");
    EXPECT_EQ(replace("/lights/1/direction", "[0, 0, 0]"),
              "/lights/1/direction: must be a non-zero vector");
    EXPECT_EQ(remove("/lights/0/type"), "/lights/0/type: required key is missing");
    EXPECT_EQ(replace("/lights/0/position", "[1, 0.5, 2]"),
              "/lights/0/position: point light [1, 0.5, 2] is inside the geometry's bounds "
              "[-10, -1, -10] .. [10, 5, 10]; no light matrix can see all of it");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/lights", "value": []},
                           {"op": "remove", "path": "/light_sweep"}])"),
              "/lights: must not be empty unless light_sweep is given");
    EXPECT_EQ(ErrorFor(R"([{"op": "remove", "path": "/lights"},
                           {"op": "remove", "path": "/light_sweep"}])"),
              "/lights: required key is missing (give lights, light_sweep or both)");
    EXPECT_EQ(replace("/lights", "{}"), "/lights: must be an array, got an object");
    // Resolutions.
    EXPECT_EQ(replace("/shadow_map/width", "0"), "/shadow_map/width: must be in [1, 16384], got 0");
    EXPECT_EQ(remove("/readback/height"), "/readback/height: required key is missing");
    // Geometry.
    EXPECT_EQ(replace("/geometry/1/primitive", "\"cone\""),
              "/geometry/1/primitive: must be one of plane, box, sphere, cylinder, got 'cone'");
    EXPECT_EQ(add("/geometry/1/mesh", "\"box.obj\""),
              "/geometry/1: must have exactly one of mesh, primitive");
    EXPECT_EQ(replace("/geometry/1", "{}"),
              "/geometry/1: must have exactly one of mesh, primitive");
    EXPECT_EQ(replace("/geometry/1/transform/scale", "0"),
              "/geometry/1/transform/scale: must be in (0, inf), got 0");
    EXPECT_EQ(replace("/geometry/1/transform/scale", "[1, -2, 3]"),
              "/geometry/1/transform/scale/1: must be in (0, inf), got -2");
    EXPECT_EQ(replace("/geometry/1/transform/scale", "[1, 2]"),
              "/geometry/1/transform/scale: must be a number or an array of 3 numbers, got 2 "
              "elements");
    EXPECT_EQ(replace("/geometry/1/transform/scale", "\"big\""),
              "/geometry/1/transform/scale: must be a positive number or an array [x, y, z] of "
              "positive numbers");
    EXPECT_EQ(add("/geometry/1/transform/skew", "1"),
              "/geometry/1/transform/skew: unknown key (allowed here: translate, rotate_deg, "
              "scale)");
    EXPECT_EQ(replace("/geometry", "[]"),
              "/geometry: the scene has no geometry (give geometry entries or a generator)");
    EXPECT_EQ(replace("/geometry/1", R"({"mesh": ""})"),
              "/geometry/1/mesh: must be a file path, got an empty string");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/geometry/1",
                            "value": {"mesh": "/nonexistent-dir/m.obj"}}])"),
              "/geometry/1/mesh: /nonexistent-dir/m.obj: mesh file not found");
    // Generator.
    EXPECT_EQ(add("/generator", R"({"kind": "city", "count": 3, "seed": 1})"),
              "/generator/kind: must be floor_objects, got 'city'");
    EXPECT_EQ(add("/generator", R"({"kind": "floor_objects", "count": 1001, "seed": 1})"),
              "/generator/count: must be in [1, 1000], got 1001");
    EXPECT_EQ(add("/generator", R"({"kind": "floor_objects", "count": 3, "seed": -1})"),
              "/generator/seed: must be in [0, 9223372036854775807], got -1");
    EXPECT_EQ(add("/generator", R"({"kind": "floor_objects", "count": 3})"),
              "/generator/seed: required key is missing");
    // Light sweep.
    EXPECT_EQ(replace("/light_sweep/count", "0"),
              "/light_sweep/count: must be in [1, 100000], got 0");
    EXPECT_EQ(replace("/light_sweep/radius", "-1"),
              "/light_sweep/radius: must be in (0, 1e+15], got -1");
    EXPECT_EQ(replace("/light_sweep/radius", "14"),  // √836 / 2 = 14.4568
              "/light_sweep/radius: must be larger than the geometry's bounding radius "
              "14.456832294801 (the sweep is centred on the bounds), got 14");
    EXPECT_EQ(add("/light_sweep/elevation", "5"),
              "/light_sweep/elevation: unknown key (allowed here: count, seed, radius, type)");
    // Camera path.
    EXPECT_EQ(replace("/camera_path", "[]"), "/camera_path: must have at least 1 elements, got 0");
    EXPECT_EQ(replace("/camera_path/1/target", "[1, 1.7, -8]"),
              "/camera_path/1/target: must differ from position [1, 1.7, -8]");
    EXPECT_EQ(add("/camera_path/0/fov_y_deg", "30"),
              "/camera_path/0/fov_y_deg: unknown key (allowed here: position, target, up)");
    EXPECT_EQ(replace("/camera_path/0/target", "[0, -5, -9]"),
              "/camera_path/0: up [0, 1, 0] (default or inherited) must not be parallel to the "
              "view direction (target - position = [0, -6.7, 0])");
    EXPECT_EQ(ErrorFor(R"([{"op": "remove", "path": "/camera/up"},
                           {"op": "replace", "path": "/camera/target", "value": [0, 5, -10]}])"),
              "/camera: up [0, 1, 0] (default or inherited) must not be parallel to the view "
              "direction (target - position = [0, 3.3, 0])");
    EXPECT_EQ(replace("/camera_path/1/up", "[0, -1.4, 20]"),
              "/camera_path/1/up: must not be parallel to the view direction (target - position "
              "= [0, -0.7, 10])");
}

// Out-of-range scenes name the field and the real reason (spatial_case.h's bounds),
// where a scale of 1e300 reported "bounding radius inf" and near 1e-300, far 1e300 was accepted.
TEST(SpatialCase, OutOfRangeScenesGiveTheRealReason) {
    auto replace = [](const std::string& path, const std::string& value) {
        return ErrorFor(R"([{"op": "replace", "path": ")" + path + R"(", "value": )" + value +
                        "}]");
    };
    // Coordinates: the unit sphere's poles scaled by 1e300 (measured before the float vertices
    // overflow), a camera, a target, a point light, a sweep radius.
    EXPECT_EQ(replace("/geometry/2/transform/scale", "1e300"),
              "/geometry/2/transform: the transformed geometry reaches |x| = 1e+300, coordinates "
              "must be at most 1e+15");
    EXPECT_EQ(replace("/geometry/2/transform/translate", "[-3, 0, 2e15]"),
              "/geometry/2/transform: the transformed geometry reaches |x| = 2e+15, coordinates "
              "must be at most 1e+15");
    EXPECT_EQ(replace("/camera/position", "[0, 1e300, -10]"),
              "/camera/position: coordinate too large: |x| = 1e+300, must be at most 1e+15");
    EXPECT_EQ(replace("/camera_path/1/target", "[1e16, 1, 2]"),
              "/camera_path/1/target: coordinate too large: |x| = 1e+16, must be at most 1e+15");
    EXPECT_EQ(replace("/lights/0/position", "[3, -1e300, -4]"),
              "/lights/0/position: coordinate too large: |x| = 1e+300, must be at most 1e+15");
    EXPECT_EQ(replace("/light_sweep/radius", "1e300"),
              "/light_sweep/radius: must be in (0, 1e+15], got 1e+300");
    // A scale so small that the sphere's extent rounds to zero.
    EXPECT_EQ(replace("/geometry/2/transform/scale", "1e-300"),
              "/geometry/2/transform: the transformed geometry collapses to the point [-3, 0, 0] "
              "(its extent rounds to zero)");

    // far / near: the bound (1e5) is accepted, anything above it is refused without overflow.
    EXPECT_EQ(replace("/camera/far", "50000"), "no error");  // near 0.5
    EXPECT_EQ(replace("/camera/far", "50001"),
              "/camera/far: far (50001) must be at most 100000 × near (0.5): beyond that a depth "
              "buffer's step at far exceeds 0.6% of the distance");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/near", "value": 1e-300},
                           {"op": "replace", "path": "/camera/far", "value": 1e300}])"),
              "/camera/far: far (1e+300) must be at most 100000 × near (1e-300): beyond that a "
              "depth buffer's step at far exceeds 0.6% of the distance");

    // A camera shut in the box (centre [1, 0, 1]) or a camera_path pose in the sphere.
    EXPECT_EQ(replace("/camera/position", "[1, 0, 1]"),
              "/camera/position: the camera [1, 0, 1] is inside closed geometry (/geometry/1; "
              "rays from it cross that surface an odd number of times in every direction tried); "
              "no light outside can reach what it sees");
    EXPECT_EQ(replace("/camera_path/0/position", "[-3, 0.1, 0.1]"),
              "/camera_path/0/position: the camera [-3, 0.1, 0.1] is inside closed geometry "
              "(/geometry/2; rays from it cross that surface an odd number of times in every "
              "direction tried); no light outside can reach what it sees");
    // Between the floor (y = -1) and a ceiling plane as wide (y = 5), every ray crosses one sheet:
    // odd, but the floor is met from its front, so the camera is not inside.
    EXPECT_EQ(replace("/geometry/4/transform", R"({"scale": 20, "translate": [0, 5, 0]})"),
              "no error");

    // Directions of any finite size normalize.
    const spatial::Scene scene = FromPatch(
        R"([{"op": "replace", "path": "/lights/1/direction", "value": [0, -2e200, 0]},
            {"op": "replace", "path": "/camera/up", "value": [0, 1e-300, 0]}])");
    EXPECT_EQ(scene.lights[1].direction, glm::dvec3(0.0, -1.0, 0.0));
    EXPECT_EQ(scene.camera.up, glm::dvec3(0.0, 1.0, 0.0));
}

TEST(SpatialCase, CascadesBlockSetsThePartitionDefaults) {
    const spatial::Scene defaults = FromPatch("[]");
    EXPECT_EQ(defaults.partitions.count, 4);
    EXPECT_EQ(defaults.partitions.lambda, 0.5);
    EXPECT_EQ(defaults.partitions.allocation, spatial::CascadeAllocation::kEqual);
    EXPECT_EQ(defaults.partitions.energy.kind, spatial::EnergyKind::kEdge);  // as optimal's
    EXPECT_EQ(defaults.partitions.energy.priorWeight, spatial::kDefaultPriorWeight);
    const spatial::Scene scene =
        FromPatch(R"([{"op": "add", "path": "/cascades", "value": )"
                  R"({"count": 8, "lambda": 0.75, "allocation": "lagrange", "energy": "h"}}])");
    EXPECT_EQ(scene.partitions.count, 8);
    EXPECT_EQ(scene.partitions.lambda, 0.75);
    EXPECT_EQ(scene.partitions.allocation, spatial::CascadeAllocation::kLagrange);
    EXPECT_TRUE(scene.partitions.energy.IsReport());
    auto add = [](const std::string& value) {
        return ErrorFor(R"([{"op": "add", "path": "/cascades", "value": )" + value + "}]");
    };
    EXPECT_EQ(add(R"({"count": 0})"), "/cascades/count: must be in [1, 16], got 0");
    EXPECT_EQ(add(R"({"count": 17})"), "/cascades/count: must be in [1, 16], got 17");
    EXPECT_EQ(add(R"({"lambda": 1.5})"), "/cascades/lambda: must be in [0, 1], got 1.5");
    EXPECT_EQ(add(R"({"allocation": "greedy"})"),
              "/cascades/allocation: must be equal or lagrange, got 'greedy'");
    EXPECT_EQ(add(R"({"energy": "L2"})"), "/cascades/energy: must be e or h, got 'L2'");
    EXPECT_EQ(add(R"({"splits": 2})"),
              "/cascades/splits: unknown key (allowed here: count, lambda, allocation, energy)");
    EXPECT_EQ(add("4"), "/cascades: must be an object, got an integer");
}

TEST(SpatialCase, OptimizerBlockSetsTheSampleBudgetAndTheEdgeExponent) {
    EXPECT_EQ(FromPatch("[]").optimizerMaxSamples, 0u);  // every sample
    EXPECT_EQ(FromPatch("[]").edgeExponent, spatial::kDefaultEdgeExponent);
    const spatial::Scene scene = FromPatch(
        R"([{"op": "add", "path": "/optimizer", "value": {"max_samples": 1024, "edge_exponent": 1}}])");
    EXPECT_EQ(scene.optimizerMaxSamples, 1024u);
    EXPECT_EQ(scene.edgeExponent, 1.0);
    auto add = [](const std::string& value) {
        return ErrorFor(R"([{"op": "add", "path": "/optimizer", "value": )" + value + "}]");
    };
    EXPECT_EQ(add(R"({"max_samples": 0})"),
              "/optimizer/max_samples: must be in [1, 268435456], got 0");
    EXPECT_EQ(add(R"({"max_samples": 1.5})"),
              "/optimizer/max_samples: must be an integer, got 1.5");
    EXPECT_EQ(add(R"({"edge_exponent": 0})"), "/optimizer/edge_exponent: must be in (0, 4], got 0");
    EXPECT_EQ(add(R"({"edge_exponent": 4.5})"),
              "/optimizer/edge_exponent: must be in (0, 4], got 4.5");
    EXPECT_EQ(add(R"({"iterations": 2})"),
              "/optimizer/iterations: unknown key (allowed here: max_samples, edge_exponent)");
    EXPECT_EQ(add("[]"), "/optimizer: must be an object, got an array");
}

TEST(SpatialCase, FilesResolveMeshesAndPrefixErrors) {
    const auto dir = std::filesystem::temp_directory_path() / "lexel_spatial_case_test";
    std::filesystem::create_directories(dir / "models");
    // A tetrahedron, counter-clockwise outward, standing on y = 0.
    std::ofstream(dir / "models/tetra.obj")
        << "v 0 0 0\nv 1 0 0\nv 0 0 1\nv 0 1 0\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";
    const char* camera = R"("camera": {"position": [0, 1.7, -10], "target": [0, 0, 0],
                             "fov_y_deg": 60, "width": 8, "height": 8})";
    std::ofstream(dir / "tetra_case.json")
        << "{" << camera << R"(, "lights": [{"type": "point", "position": [0, 10, 0]}],
               "geometry": [{"mesh": "models/tetra.obj", "transform": {"scale": 2}}]})";
    const spatial::Scene scene = LoadSpatialScene(dir / "tetra_case.json");
    EXPECT_EQ(scene.name, "tetra_case");
    EXPECT_EQ(scene.geometry.triangles.size(), 4u);
    EXPECT_NEAR(spatial::SignedVolume(scene.geometry), 8.0 / 6.0, 1e-6);
    EXPECT_EQ(scene.geometry.ComputeBounds().hi, glm::dvec3(2, 2, 2));
    EXPECT_FALSE(scene.floorPlane.has_value());

    std::ofstream(dir / "missing_mesh.json")
        << "{" << camera << R"(, "lights": [{"type": "point", "position": [0, 10, 0]}],
               "geometry": [{"mesh": "models/none.obj"}]})";
    try {
        LoadSpatialScene(dir / "missing_mesh.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "missing_mesh.json").string() + ": /geometry/0/mesh: " +
                      (dir / "models/none.obj").string() + ": mesh file not found");
    }
    // A flatland file is not a 3D case.
    try {
        LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/flatland/single_plane.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected a 3D case"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

TEST(SpatialCase, ShippedWalkthroughIsTheReportScene) {
    const spatial::Scene scene =
        LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/spatial/walkthrough.json");
    EXPECT_EQ(scene.name, "walkthrough");
    const spatial::TriangleMesh expected = spatial::FloorObjects(36, 1, nullptr);
    EXPECT_EQ(scene.geometry.triangles.size(), expected.triangles.size());
    const spatial::Bounds b = scene.geometry.ComputeBounds();
    EXPECT_EQ(b.lo.x, -20.0);
    EXPECT_EQ(b.hi.z, 20.0);
    EXPECT_EQ(b.lo.y, 0.0);
    EXPECT_GT(b.hi.y, 1.0);
    EXPECT_LT(b.hi.y, 5.0);
    EXPECT_EQ(scene.camera.resolution.width, 750);
    EXPECT_EQ(scene.camera.position.y, 1.7);  // slightly above the floor
    EXPECT_EQ(scene.shadowMap.width, 400);
    // The report's 180² readback, four times finer each way, with the optimizer's sample budget
    // (RESULTS.md, "Re-measured at the shipped readback"); case_variant.py gives back the 180².
    EXPECT_EQ(scene.readback.width, 720);
    EXPECT_EQ(scene.readback.height, 720);
    EXPECT_EQ(scene.optimizerMaxSamples, 512u);
    ASSERT_TRUE(scene.lightSweep.has_value());
    EXPECT_EQ(scene.lightSweep->count, 500);
    EXPECT_EQ(scene.lightSweep->seed, 7u);
    EXPECT_EQ(scene.lightSweep->radius, 100.0);
    EXPECT_EQ(scene.lights.size(), 2u);
    ASSERT_TRUE(scene.floorPlane.has_value());
    EXPECT_EQ(*scene.floorPlane, glm::dvec4(0, 1, 0, 0));
    ASSERT_EQ(scene.cameraPath.size(), 8u);
    // The path walks forward and never enters an object's bounds (the lane x = 4.5 is clear
    // for seed 1): every object lies at least 1 unit from every eye.
    const auto objects = spatial::FloorObjects(36, 1, nullptr);
    for (const spatial::Camera& pose : scene.cameraPath) {
        EXPECT_GE(pose.position.z, scene.cameraPath.front().position.z);
        for (const glm::dvec3& p : objects.positions)
            if (p.y > 0.0) {  // not the floor
                EXPECT_GT(glm::distance(p, pose.position), 1.0);
            }
    }
}

TEST(SpatialCase, ShippedMeshesSitOnTheFloor) {
    const spatial::Scene scene =
        LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/spatial/meshes.json");
    ASSERT_TRUE(scene.floorPlane.has_value());
    EXPECT_EQ(*scene.floorPlane, glm::dvec4(0, 1, 0, 0));
    // The floor (2) plus spider OBJ and STL (1368 each), Wuson OBJ and STL (3732 each) and the
    // sphere with a hole (285), as Assimp 5.2 reads them.
    EXPECT_EQ(scene.geometry.triangles.size(), 2u + 1368 + 1368 + 3732 + 3732 + 285);
    const spatial::Bounds b = scene.geometry.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-20, 0, -20));
    EXPECT_EQ(b.hi.x, 20.0);
    EXPECT_EQ(b.hi.z, 20.0);
    EXPECT_NEAR(b.hi.y, 2.2739, 1e-4);  // Wuson, 1.5 times 1.51525 + 0.001
    // The models (every vertex after the floor's 4) rest on the floor: none below it, the lowest
    // within half a millimetre above.
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 4; i < scene.geometry.positions.size(); ++i)
        lowest = std::min(lowest, scene.geometry.positions[i].y);
    EXPECT_GE(lowest, 0.0);
    EXPECT_LE(lowest, 5e-4);
    EXPECT_GT(scene.lightSweep->radius, b.Radius());
}

}  // namespace
}  // namespace lexel::cases
