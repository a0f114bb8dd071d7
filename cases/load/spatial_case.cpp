// 3D case files (see spatial_case.h and cases/README.md).
#include "lexel/cases/load/spatial_case.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "lexel/cases/load/case_methods.h"
#include "lexel/cases/load/case_name.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/memory_budget.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/containment.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/memory_estimate.h"
#include "lexel/spatial/harness/mesh_frame.h"
#include "lexel/spatial/harness/mesh_loader.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/light_space.h"

namespace lexel::cases {
namespace {

glm::dvec3 ReadVec3(const JsonField& field) {
    const Eigen::Vector3d v = field.Vec3();
    return {v.x(), v.y(), v.z()};
}

std::string FormatVec(const glm::dvec3& v) {
    return std::string("[") + FormatNumber(v.x) + ", " + FormatNumber(v.y) + ", " +
           FormatNumber(v.z) + "]";
}

double LargestMagnitude(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Refuses a point with a coordinate beyond kMaxCoordinate (see spatial_case.h).
glm::dvec3 CheckCoordinates(const JsonField& field, const glm::dvec3& v) {
    const double largest = LargestMagnitude(v);
    if (!(largest <= kMaxCoordinate))
        field.Fail("coordinate too large: |x| = " + FormatNumber(largest) + ", must be at most " +
                   FormatNumber(kMaxCoordinate));
    return v;
}

// v / its largest |component| when v's squared length overflows or underflows (normalizing
// [1e200, 0, 0] directly gives 0), else v as given; zero stays zero.
glm::dvec3 ScaledDirection(const glm::dvec3& v) {
    const double squared = glm::dot(v, v);
    if (std::isfinite(squared) && squared >= std::numeric_limits<double>::min()) return v;
    const double largest = LargestMagnitude(v);
    return largest > 0.0 && std::isfinite(largest) ? v / largest : v;
}

// Refuses a far plane more than kMaxFarOverNear times the near plane (see spatial_case.h); the
// product, unlike the ratio, cannot overflow (near and far are at least the smallest double).
void CheckDepthRange(const JsonField& field, const spatial::Camera& camera) {
    if (camera.farPlane <= kMaxFarOverNear * camera.nearPlane) return;
    field[field.Has("far") ? "far" : "near"].Fail(
        "far (" + FormatNumber(camera.farPlane) + ") must be at most " +
        FormatNumber(kMaxFarOverNear) + " × near (" + FormatNumber(camera.nearPlane) +
        "): beyond that a depth buffer's step at far exceeds 0.6% of the distance");
}

// Refuses a geometry entry whose transformed vertices reach beyond kMaxCoordinate (a scale or
// translate too large) or collapse to one point (a scale so small that every vertex coincides).
void CheckEntryExtent(const JsonField& entry, const spatial::TriangleMesh& osMesh,
                      const spatial::Transform& transform, const spatial::TriangleMesh& wsMesh) {
    const JsonField field = entry.Has("transform") ? entry["transform"] : entry;
    const glm::dmat4 wsFromOs = transform.Matrix();
    double largest = 0.0;
    for (const glm::dvec3& osPoint : osMesh.positions)
        largest =
            std::max(largest, LargestMagnitude(glm::dvec3(wsFromOs * glm::dvec4(osPoint, 1.0))));
    if (!(largest <= kMaxCoordinate))
        field.Fail("the transformed geometry reaches |x| = " + FormatNumber(largest) +
                   ", coordinates must be at most " + FormatNumber(kMaxCoordinate));
    const spatial::Bounds wsBounds = wsMesh.ComputeBounds();
    if (!wsBounds.Empty() && !(wsBounds.Radius() > 0.0))
        field.Fail("the transformed geometry collapses to the point " +
                   FormatVec(wsBounds.Center()) + " (its extent rounds to zero)");
}

spatial::Resolution ReadResolution(const JsonField& field) {
    field.ExpectObject({"width", "height"});
    return {static_cast<int>(field["width"].Integer(1, kMaxSide)),
            static_cast<int>(field["height"].Integer(1, kMaxSide))};
}

// Checks the pose of a camera whose position, target and up were read from `field`.
void CheckPose(const spatial::Camera& camera, const JsonField& field) {
    const glm::dvec3 view = camera.target - camera.position;
    if (!(glm::length(view) > 0.0))
        field["target"].Fail("must differ from position " + FormatVec(camera.position));
    if (!(glm::length(camera.up) > 0.0)) field["up"].Fail("must be a non-zero vector");
    // |sin| of the angle between up and the view direction; lookAt needs it well away from 0.
    const double sine = glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up)));
    if (!(sine > 1e-6)) {
        const std::string reason =
            "must not be parallel to the view direction (target - position = " + FormatVec(view) +
            ")";
        if (field.Has("up")) field["up"].Fail(reason);
        // An up the file does not give here (the default, or the camera's in a camera_path pose)
        // has no pointer of its own: name the pose.
        field.Fail("up " + FormatVec(camera.up) + " (default or inherited) " + reason);
    }
}

// Reads position, target and optional up into `camera`.
void ReadPose(const JsonField& field, spatial::Camera* camera) {
    camera->position = CheckCoordinates(field["position"], ReadVec3(field["position"]));
    camera->target = CheckCoordinates(field["target"], ReadVec3(field["target"]));
    if (field.Has("up")) camera->up = ScaledDirection(ReadVec3(field["up"]));
}

// The raw JSON under a field, for the one place the schema allows two types (`scale`).
const nlohmann::json& Raw(const nlohmann::json& document, const JsonField& field) {
    return document.at(nlohmann::json::json_pointer(field.Pointer()));
}

spatial::Transform ReadTransform(const nlohmann::json& document, const JsonField& field) {
    field.ExpectObject({}, {"translate", "rotate_deg", "scale"});
    spatial::Transform t;
    if (field.Has("translate")) t.translate = ReadVec3(field["translate"]);
    if (field.Has("rotate_deg")) t.rotateDeg = ReadVec3(field["rotate_deg"]);
    if (field.Has("scale")) {
        // A number scales uniformly, [x, y, z] per axis. Zero or negative factors would flatten
        // or mirror the shape (a mirrored plane's floor normal would flip), so they are refused.
        const JsonField scale = field["scale"];
        const nlohmann::json& raw = Raw(document, scale);
        if (raw.is_number()) {
            t.scale = glm::dvec3(scale.Positive());
        } else if (raw.is_array()) {
            const auto items = scale.Array();
            if (items.size() != 3)
                scale.Fail("must be a number or an array of 3 numbers, got " +
                           std::to_string(items.size()) + " elements");
            for (int k = 0; k < 3; ++k) t.scale[k] = items[k].Positive();
        } else {
            scale.Fail("must be a positive number or an array [x, y, z] of positive numbers");
        }
    }
    return t;
}

// The axes and units of a mesh entry's file: `up` ("y" or "z") and `units` (a unit name or a
// positive number of scene units per file unit); both only in a mesh entry.
spatial::MeshFrame ReadMeshFrame(const nlohmann::json& document, const JsonField& entry) {
    spatial::MeshFrame frame;
    for (const char* key : {"up", "units"})
        if (entry.Has(key) && !entry.Has("mesh"))
            entry[key].Fail("only a mesh entry has a file whose axes and units it sets");
    if (entry.Has("up")) {
        const std::string up = entry["up"].String();
        if (up != "y" && up != "z") entry["up"].Fail("must be y or z, got '" + up + "'");
        frame.up = up == "z" ? spatial::UpAxis::kZ : spatial::UpAxis::kY;
    }
    if (entry.Has("units")) {
        const JsonField units = entry["units"];
        const nlohmann::json& raw = Raw(document, units);
        if (raw.is_number()) {
            frame.unitScale = units.Positive();
        } else if (raw.is_string()) {
            const std::string name = units.String();
            const std::optional<double> scale = spatial::UnitScaleByName(name);
            if (!scale)
                units.Fail("must be one of " + std::string(spatial::kUnitNames) +
                           " or a positive number, got '" + name + "'");
            frame.unitScale = *scale;
        } else {
            units.Fail("must be a unit (" + std::string(spatial::kUnitNames) +
                       ") or a positive number of scene units per file unit");
        }
    }
    return frame;
}

// A mesh file's triangles in scene axes and units; `units` too large for the coordinates' bound
// (kMaxCoordinate, measured in double) or so small that the float vertices coincide is refused.
spatial::TriangleMesh MeshInSceneFrame(const JsonField& entry, const spatial::TriangleMesh& file,
                                       const spatial::MeshFrame& frame) {
    double largest = 0.0;
    for (const glm::dvec3& p : file.positions)
        largest = std::max(largest, LargestMagnitude(p) * frame.unitScale);
    const JsonField field = entry.Has("units") ? entry["units"] : entry["mesh"];
    if (!(largest <= kMaxCoordinate))
        field.Fail("the mesh in these units reaches |x| = " + FormatNumber(largest) +
                   ", coordinates must be at most " + FormatNumber(kMaxCoordinate));
    spatial::TriangleMesh scene = spatial::TransformMesh(file, spatial::SceneFromFile(frame));
    if (file.ComputeBounds().Radius() > 0.0 && !(scene.ComputeBounds().Radius() > 0.0))
        field.Fail("the mesh in these units collapses to one point (its float vertices coincide)");
    return scene;
}

// A geometry entry's keys and transform: exactly one of mesh and primitive.
spatial::Transform ReadEntryTransform(const nlohmann::json& document, const JsonField& entry) {
    entry.ExpectObject({}, {"mesh", "primitive", "transform", "up", "units"});
    if (entry.Has("mesh") == entry.Has("primitive"))
        entry.Fail("must have exactly one of mesh, primitive");
    ReadMeshFrame(document, entry);  // up and units belong to a mesh entry
    return entry.Has("transform") ? ReadTransform(document, entry["transform"])
                                  : spatial::Transform{};
}

// A mesh entry's file, a relative path resolved against the case file's directory.
std::filesystem::path ReadMeshPath(const JsonField& entry, const std::filesystem::path& baseDir) {
    const JsonField mesh = entry["mesh"];
    const std::filesystem::path file = mesh.String();
    if (file.empty()) mesh.Fail("must be a file path, got an empty string");
    return file.is_absolute() ? file : baseDir / file;
}

// The plane n·x + d = 0 of a transformed `plane` primitive, n unit on its +y side.
glm::dvec4 TransformedPlane(const glm::dmat4& wsFromOs) {
    // Normals transform by the inverse transpose of the linear part.
    const glm::dvec3 wsNormal =
        glm::normalize(glm::transpose(glm::inverse(glm::dmat3(wsFromOs))) * glm::dvec3(0, 1, 0));
    const glm::dvec3 wsPoint(wsFromOs[3]);
    return {wsNormal, -glm::dot(wsNormal, wsPoint)};
}

void ReadCamera(const JsonField& field, spatial::Camera* camera) {
    field.ExpectObject({"position", "target", "fov_y_deg", "width", "height"},
                       {"up", "near", "far"});
    ReadPose(field, camera);
    camera->fovYDeg = field["fov_y_deg"].NumberIn(0.0, 180.0, true, true);
    camera->resolution = {static_cast<int>(field["width"].Integer(1, kMaxSide)),
                          static_cast<int>(field["height"].Integer(1, kMaxSide))};
    if (field.Has("near")) camera->nearPlane = field["near"].Positive();
    if (field.Has("far")) camera->farPlane = field["far"].Positive();
    if (!(camera->farPlane > camera->nearPlane))
        field[field.Has("far") ? "far" : "near"].Fail("far (" + FormatNumber(camera->farPlane) +
                                                      ") must be greater than near (" +
                                                      FormatNumber(camera->nearPlane) + ")");
    CheckDepthRange(field, *camera);
    CheckPose(*camera, field);
}

spatial::Light ReadLight(const JsonField& field) {
    const std::string type = field["type"].String();
    spatial::Light light;
    if (type == "point") {
        field.ExpectObject({"type", "position"});
        light.type = spatial::Light::Type::kPoint;
        light.position = CheckCoordinates(field["position"], ReadVec3(field["position"]));
    } else if (type == "directional") {
        field.ExpectObject({"type", "direction"});
        light.type = spatial::Light::Type::kDirectional;
        const glm::dvec3 direction = ScaledDirection(ReadVec3(field["direction"]));
        if (!(glm::length(direction) > 0.0)) field["direction"].Fail("must be a non-zero vector");
        light.direction = glm::normalize(direction);
    } else {
        field["type"].Fail("must be one of point, directional, got '" + type + "'");
    }
    return light;
}

// The partitioned methods' defaults: {"count", "lambda", "allocation", "energy"}.
spatial::PartitionOptions ReadPartitions(const JsonField& field) {
    field.ExpectObject({}, {"count", "lambda", "allocation", "energy"});
    spatial::PartitionOptions options;
    if (field.Has("count"))
        options.count = static_cast<int>(field["count"].Integer(1, spatial::kMaxCascades));
    if (field.Has("lambda")) options.lambda = field["lambda"].NumberIn(0.0, 1.0, false, false);
    if (field.Has("allocation")) {
        const std::string allocation = field["allocation"].String();
        if (allocation != "equal" && allocation != "lagrange")
            field["allocation"].Fail("must be equal or lagrange, got '" + allocation + "'");
        options.allocation = allocation == "equal" ? spatial::CascadeAllocation::kEqual
                                                   : spatial::CascadeAllocation::kLagrange;
    }
    if (field.Has("energy")) {
        const std::string energy = field["energy"].String();
        if (energy != "e" && energy != "h")
            field["energy"].Fail("must be e or h, got '" + energy + "'");
        options.energy = energy == "e" ? spatial::kEdgeEnergy : spatial::EnergyOptions{};
    }
    return options;
}

// The evaluation's memory for the scene's sizes so far (every method, images kept, the report's
// truth map: the most a run or sweep holds per light) against lexel's budget; the error names the
// field whose size needs the most.
void CheckEvaluationMemory(const spatial::Scene& scene) {
    spatial::EvaluationSizes sizes;
    sizes.frame = scene.camera.resolution;
    sizes.readback = scene.readback;
    sizes.shadowMap = scene.shadowMap;
    sizes.triangles = scene.geometry.triangles.size();
    sizes.methods = static_cast<int>(spatial::SpatialMethodNames().size());
    sizes.truthMapSize = spatial::EvaluationOptions{}.truthMapSize;
    const double bytes = spatial::EstimateEvaluationMemory(sizes).Total(1);
    auto size = [](const spatial::Resolution& r) {
        return std::to_string(r.width) + "x" + std::to_string(r.height);
    };
    std::string what = "camera " + size(sizes.frame) + ", readback " + size(sizes.readback) +
                       ", shadow map " + size(sizes.shadowMap);
    if (sizes.triangles > 0) what += ", " + std::to_string(sizes.triangles) + " triangles";
    const std::string excess = MemoryBudgetExcess(bytes, what);
    if (excess.empty()) return;
    // The field to change: the one whose share of the estimate is largest.
    const auto share = [&](spatial::EvaluationSizes only) {
        only.methods = sizes.methods;
        only.truthMapSize = 0;
        return spatial::EstimateEvaluationMemory(only).Total(1);
    };
    const std::pair<double, const char*> shares[] = {
        {share({sizes.frame, {}, {}, 0}), "/camera"},
        {share({{}, sizes.readback, {}, 0}), "/readback"},
        {share({{}, {}, sizes.shadowMap, 0}), "/shadow_map"},
        {share({{}, {}, {}, sizes.triangles}), "/geometry"}};
    const char* field = std::max_element(std::begin(shares), std::end(shares))->second;
    throw InputError(std::string(field) + ": the case " + excess);
}

// Refuses a camera shut inside one closed geometry entry (containment.h), each entry tested on
// its own: `entryEnd[k]` ends entry k's triangles in wsGeometry (the generator's objects, which
// stand on their own floor, are not tested). Point lights inside the geometry's bounds are refused
// and directional lights come from outside them, so such a camera sees only the inside of walls
// that no light reaches: every counted pixel would be shadowed.
void CheckCameraOutside(const spatial::TriangleMesh& wsGeometry,
                        const std::vector<std::size_t>& entryEnd, const spatial::Camera& camera,
                        const JsonField& field) {
    const std::span<const glm::uvec3> all(wsGeometry.triangles);
    std::size_t begin = 0;
    for (std::size_t k = 0; k < entryEnd.size(); ++k) {
        const auto triangles = all.subspan(begin, entryEnd[k] - begin);
        begin = entryEnd[k];
        if (!spatial::InsideClosedGeometry(wsGeometry, triangles, camera.position)) continue;
        field["position"].Fail("the camera " + FormatVec(camera.position) +
                               " is inside closed geometry (/geometry/" + std::to_string(k) +
                               "; rays from it cross that surface an odd number of times in "
                               "every direction tried); no light outside can reach what it sees");
    }
}

// Refuses a scene outside the scale and offset range of spatial_case.h: smaller than
// kMinSceneSize across, or centred more than kMaxCentreRadii bounding radii from the origin.
void CheckSceneExtent(const std::string& field, const spatial::Bounds& wsBounds) {
    const auto threeDigits = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.3g", v);
        return std::string(buffer);
    };
    const double across = 2.0 * wsBounds.Radius();
    if (!(across >= kMinSceneSize))
        throw InputError(field + ": the scene is " + threeDigits(across) +
                         " across (its bounds' diagonal), must be at least " +
                         FormatNumber(kMinSceneSize));
    const double centreRadii = glm::length(wsBounds.Center()) / wsBounds.Radius();
    if (!(centreRadii <= kMaxCentreRadii))
        throw InputError(field + ": the scene's centre " + FormatVec(wsBounds.Center()) + " is " +
                         threeDigits(centreRadii) +
                         " bounding radii from the origin, must be at most " +
                         threeDigits(kMaxCentreRadii) +
                         " (farther, its coordinates keep under 8 digits within the scene); move "
                         "it nearer the origin");
}

}  // namespace

namespace {

// /light_sweep: the hemisphere of lights `lexel sweep` draws.
spatial::LightSweep ReadLightSweep(const JsonField& sweep) {
    sweep.ExpectObject({}, {"count", "seed", "radius", "type"});
    spatial::LightSweep lightSweep;
    if (sweep.Has("count"))
        lightSweep.count = static_cast<int>(sweep["count"].Integer(1, kMaxSweepLights));
    if (sweep.Has("seed"))
        lightSweep.seed = static_cast<std::uint64_t>(
            sweep["seed"].Integer(0, std::numeric_limits<long long>::max()));
    if (sweep.Has("radius"))
        lightSweep.radius = sweep["radius"].NumberIn(0.0, kMaxCoordinate, true, false);
    if (sweep.Has("type")) {
        const std::string type = sweep["type"].String();
        if (type != "point" && type != "directional")
            sweep["type"].Fail("must be point or directional, got '" + type + "'");
        lightSweep.type =
            type == "point" ? spatial::Light::Type::kPoint : spatial::Light::Type::kDirectional;
    }
    return lightSweep;
}

// /optimizer, /phases and /max_phases into `scene`.
void ReadMeasurement(const JsonField& root, spatial::Scene* scene) {
    if (root.Has("optimizer")) {
        const JsonField optimizer = root["optimizer"];
        optimizer.ExpectObject({}, {"max_samples", "edge_exponent"});
        if (optimizer.Has("max_samples"))
            scene->optimizerMaxSamples =
                static_cast<std::size_t>(optimizer["max_samples"].Integer(1, kMaxOptimizerSamples));
        if (optimizer.Has("edge_exponent"))
            scene->edgeExponent =
                optimizer["edge_exponent"].NumberIn(0.0, kMaxEdgeExponent, true, false);
    }
    if (root.Has("phases"))
        scene->phases = static_cast<int>(root["phases"].Integer(1, spatial::kMaxPhases));
    if (root.Has("max_phases")) {
        scene->maxPhases = static_cast<int>(root["max_phases"].Integer(1, spatial::kMaxPhases));
        if (scene->maxPhases < scene->phases)
            root["max_phases"].Fail("must be at least phases (" + std::to_string(scene->phases) +
                                    "), got " + std::to_string(scene->maxPhases));
    }
}

// /lights into `scene` (after /light_sweep: without one, lights are required and not empty).
void ReadLights(const JsonField& root, spatial::Scene* scene) {
    if (root.Has("lights")) {
        const JsonField lights = root["lights"];
        const auto items = lights.Array();
        if (items.empty() && !scene->lightSweep)
            lights.Fail("must not be empty unless light_sweep is given");
        for (const JsonField& light : items) scene->lights.push_back(ReadLight(light));
    } else if (!scene->lightSweep) {
        throw InputError("/lights: required key is missing (give lights, light_sweep or both)");
    }
}

// One /geometry entry's primitive in its object space; a plane is the scene's floor when it is
// the first.
spatial::TriangleMesh ReadPrimitive(const JsonField& entry, const spatial::Transform& transform,
                                    spatial::Scene* scene) {
    const JsonField primitive = entry["primitive"];
    const std::string kind = primitive.String();
    if (kind == "plane") {
        if (!scene->floorPlane) scene->floorPlane = TransformedPlane(transform.Matrix());
        return spatial::MakePlane();
    }
    if (kind == "box") return spatial::MakeBox();
    if (kind == "sphere") return spatial::MakeSphere();
    if (kind == "cylinder") return spatial::MakeCylinder();
    primitive.Fail("must be one of plane, box, sphere, cylinder, got '" + kind + "'");
}

// /geometry into `scene`: each entry's mesh or primitive placed in the world; returns, per entry,
// the end of its triangles.
std::vector<std::size_t> ReadGeometry(const nlohmann::json& document, const JsonField& root,
                                      const std::filesystem::path& baseDir, spatial::Scene* scene) {
    std::vector<std::size_t> entryEnd;
    if (!root.Has("geometry")) return entryEnd;
    for (const JsonField& entry : root["geometry"].Array()) {
        const spatial::Transform transform = ReadEntryTransform(document, entry);
        spatial::TriangleMesh osMesh;
        if (entry.Has("mesh")) {
            const spatial::MeshFrame frame = ReadMeshFrame(document, entry);
            const std::filesystem::path file = ReadMeshPath(entry, baseDir);
            spatial::TriangleMesh fileMesh;
            try {
                fileMesh = spatial::LoadMesh(file);
            } catch (const DomainError& e) {
                entry["mesh"].Fail(e.what());
            }
            osMesh = MeshInSceneFrame(entry, fileMesh, frame);
        } else {
            osMesh = ReadPrimitive(entry, transform, scene);
        }
        spatial::TriangleMesh wsMesh = spatial::TransformMesh(osMesh, transform);
        CheckEntryExtent(entry, osMesh, transform, wsMesh);
        scene->geometry.Append(wsMesh);
        CheckEvaluationMemory(*scene);  // many entries of one large mesh add up
        entryEnd.push_back(scene->geometry.triangles.size());
    }
    return entryEnd;
}

// /generator's objects into `scene`; its floor is the scene's unless a plane primitive came first.
void ReadGenerator(const JsonField& generator, spatial::Scene* scene) {
    generator.ExpectObject({"kind", "count", "seed"});
    const std::string kind = generator["kind"].String();
    if (kind != "floor_objects")
        generator["kind"].Fail("must be floor_objects, got '" + kind + "'");
    const int count = static_cast<int>(generator["count"].Integer(1, 1000));
    const auto seed = static_cast<std::uint64_t>(
        generator["seed"].Integer(0, std::numeric_limits<long long>::max()));
    glm::dvec4 floor;
    scene->geometry.Append(spatial::FloorObjects(count, seed, &floor));
    CheckEvaluationMemory(*scene);
    // A plane primitive, when there is one, is the floor the case author chose.
    if (!scene->floorPlane) scene->floorPlane = floor;
}

// /camera_path's poses, each the case's camera moved.
std::vector<spatial::Camera> ReadCameraPath(const JsonField& path, const spatial::Camera& camera) {
    std::vector<spatial::Camera> poses;
    for (const JsonField& pose : path.Array(1)) {
        pose.ExpectObject({"position", "target"}, {"up"});
        spatial::Camera moved = camera;
        ReadPose(pose, &moved);
        CheckPose(moved, pose);
        poses.push_back(moved);
    }
    return poses;
}

// The checks that need the whole scene: geometry there and of a sane extent, every camera outside
// it, every fixed point light outside its bounds and with a light space, the sweep's radius
// beyond them.
void CheckWholeScene(const JsonField& root, const spatial::Scene& scene,
                     const std::vector<std::size_t>& entryEnd, const spatial::Bounds& wsBounds) {
    if (wsBounds.Empty())
        throw InputError(std::string(root.Has("geometry") ? "/geometry" : "/") +
                         ": the scene has no geometry (give geometry entries or a generator)");
    CheckSceneExtent(root.Has("geometry") ? "/geometry" : "/generator", wsBounds);
    CheckCameraOutside(scene.geometry, entryEnd, scene.camera, root["camera"]);
    if (root.Has("camera_path")) {
        const auto poses = root["camera_path"].Array(1);
        for (std::size_t k = 0; k < poses.size(); ++k)
            CheckCameraOutside(scene.geometry, entryEnd, scene.cameraPath[k], poses[k]);
    }
    for (std::size_t k = 0; k < scene.lights.size(); ++k) {
        const spatial::Light& light = scene.lights[k];
        const std::string pointer = "/lights/" + std::to_string(k);
        if (light.type == spatial::Light::Type::kPoint && wsBounds.Contains(light.position))
            throw InputError(pointer + "/position: point light " + FormatVec(light.position) +
                             " is inside the geometry's bounds " + FormatVec(wsBounds.lo) + " .. " +
                             FormatVec(wsBounds.hi) + "; no light matrix can see all of it");
        // Whatever else would stop the light space from being built (a light at the centre of
        // flat geometry) is a case error too, not a failure later in a run.
        try {
            spatial::LightSpace(light, wsBounds);
        } catch (const DomainError& e) {
            throw InputError(SpatialErrorField(e, pointer) + ": " + e.what());
        }
    }
    if (scene.lightSweep && !(scene.lightSweep->radius > wsBounds.Radius()))
        throw InputError(
            "/light_sweep/radius: must be larger than the geometry's bounding radius " +
            FormatNumber(wsBounds.Radius()) + " (the sweep is centred on the bounds), got " +
            FormatNumber(scene.lightSweep->radius));
}

}  // namespace

spatial::Scene SpatialSceneFromJson(const nlohmann::json& document, const std::string& fallbackName,
                                    const std::filesystem::path& baseDir) {
    const JsonField root(document, "");
    root.ExpectObject({"camera"}, {"name", "description", "lights", "shadow_map", "readback",
                                   "geometry", "generator", "light_sweep", "camera_path",
                                   "cascades", "methods", "phases", "max_phases", "optimizer"});
    spatial::Scene scene;
    scene.name = CaseNameOf(root, fallbackName);
    if (root.Has("description")) root["description"].String();
    ReadCamera(root["camera"], &scene.camera);
    if (root.Has("light_sweep")) scene.lightSweep = ReadLightSweep(root["light_sweep"]);
    if (root.Has("cascades")) scene.partitions = ReadPartitions(root["cascades"]);
    ReadMeasurement(root, &scene);
    ReadLights(root, &scene);
    std::vector<CaseMethodEntry> methods;  // checked against the lights once the geometry is read
    if (root.Has("methods")) methods = ReadCaseMethods(root["methods"], scene, baseDir);
    if (root.Has("shadow_map")) scene.shadowMap = ReadResolution(root["shadow_map"]);
    if (root.Has("readback")) scene.readback = ReadResolution(root["readback"]);
    CheckEvaluationMemory(scene);
    const std::vector<std::size_t> entryEnd = ReadGeometry(document, root, baseDir, &scene);
    if (root.Has("generator")) ReadGenerator(root["generator"], &scene);
    if (root.Has("camera_path"))
        scene.cameraPath = ReadCameraPath(root["camera_path"], scene.camera);
    const spatial::Bounds wsBounds = scene.geometry.ComputeBounds();
    CheckWholeScene(root, scene, entryEnd, wsBounds);
    CheckCaseMethodMatrices(methods, scene, wsBounds);
    for (CaseMethodEntry& entry : methods) scene.methods.push_back(std::move(entry.method));
    return scene;
}

std::string LightField(std::size_t light) { return "/lights/" + std::to_string(light); }

std::string CameraPathField(std::size_t pose) { return "/camera_path/" + std::to_string(pose); }

std::string SpatialErrorField(const DomainError& e, const std::string& light,
                              const std::string& camera) {
    switch (e.subject()) {
        case Subject::kCamera:
            return camera;
        case Subject::kLight:
            return light;
        case Subject::kGeometry:
        case Subject::kSegment:
            return "/geometry";
        case Subject::kLexels:
            return "/shadow_map";
    }
    return "/";
}

spatial::Scene LoadSpatialScene(const std::filesystem::path& path) {
    return LoadSpatialScene(ReadCaseFile(path));
}

spatial::Scene LoadSpatialScene(const CaseFile& file) {
    const std::filesystem::path& path = file.path;
    const nlohmann::json& document = file.document;
    if (!IsSpatialCase(document))
        throw InputError(path.string() +
                         ": this is a flatland case (it has no \"lights\" or \"light_sweep\"); "
                         "expected a 3D case");
    try {
        return SpatialSceneFromJson(document, path.stem().string(), path.parent_path());
    } catch (const InputError& e) {
        throw InputError(path.string() + ": " + e.what());
    }
}

std::vector<SpatialMeshEntry> LoadSpatialMeshEntries(const std::filesystem::path& path) {
    const nlohmann::json document = ParseJsonFile(path);
    if (!IsSpatialCase(document))
        throw InputError(path.string() +
                         ": this is a flatland case (it has no \"lights\" or \"light_sweep\"); "
                         "expected a 3D case");
    std::vector<SpatialMeshEntry> entries;
    try {
        const JsonField root(document, "");
        if (!root.Has("geometry")) return entries;
        for (const JsonField& entry : root["geometry"].Array()) {
            const spatial::Transform transform = ReadEntryTransform(document, entry);
            if (!entry.Has("mesh")) continue;
            entries.push_back({entry.Pointer(), ReadMeshPath(entry, path.parent_path()),
                               ReadMeshFrame(document, entry), transform});
        }
    } catch (const InputError& e) {
        throw InputError(path.string() + ": " + e.what());
    }
    return entries;
}

}  // namespace lexel::cases
