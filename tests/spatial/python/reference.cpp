// The C++ side of the Python module's tests (test_lexel.py): the embedding guide's toy renderer
// scene (a floor and a box traced exactly, tests/install/consumer/main.cpp) run through the core's
// API, writing its inputs and every result to DIR so that the tests run the module on the same
// inputs and compare, bit for bit. Inputs: a 1280×720 reversed-Z depth buffer with Vulkan's
// conventions and an infinite far plane (depth.f32), and per light the readback's shadow mask from
// exact shadow rays (mask_<l>.u8). Results: reference.json, and the readback's per-pixel arrays
// (*.f64). Usage: python_reference DIR
#include <lexel/spatial.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

using namespace lexel::spatial;
using nlohmann::json;

namespace {

const glm::dvec3 kBoxLo(-1.0, 0.0, -1.0), kBoxHi(1.0, 2.0, 1.0);
constexpr double kFloorHalf = 20.0;

// The nearest hit parameter of o + t d, t ∈ (tMin, tMax), with the floor y = 0 or the box.
std::optional<double> Trace(glm::dvec3 o, glm::dvec3 d, double tMin, double tMax) {
    std::optional<double> hit;
    if (d.y != 0.0) {
        const double t = -o.y / d.y;
        const glm::dvec3 p = o + t * d;
        if (t > tMin && t < tMax && std::abs(p.x) <= kFloorHalf && std::abs(p.z) <= kFloorHalf)
            hit = t, tMax = t;
    }
    double t0 = tMin, t1 = tMax;
    bool entered = false;
    for (int k = 0; k < 3; ++k) {
        const double ta = (kBoxLo[k] - o[k]) / d[k], tb = (kBoxHi[k] - o[k]) / d[k];
        if (std::min(ta, tb) > t0) t0 = std::min(ta, tb), entered = true;
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (entered && t0 <= t1) hit = t0;
    return hit;
}

glm::dvec3 NormalAt(glm::dvec3 p) {
    const double eps = 1e-4;
    for (int k = 0; k < 3; ++k) {
        const bool inside = glm::all(glm::lessThanEqual(kBoxLo - eps, p)) &&
                            glm::all(glm::lessThanEqual(p, kBoxHi + eps));
        if (inside && (std::abs(p[k] - kBoxLo[k]) < eps || std::abs(p[k] - kBoxHi[k]) < eps) &&
            !(k == 1 && p.y < eps)) {
            glm::dvec3 n(0.0);
            n[k] = std::abs(p[k] - kBoxHi[k]) < eps ? 1.0 : -1.0;
            return n;
        }
    }
    return {0.0, 1.0, 0.0};
}

// The readback's shadow mask from exact shadow rays (what a perfect shadow map would give).
std::vector<Shade> ExactMask(const Readback& readback, const LightSpace& lightSpace) {
    std::vector<Shade> shades(readback.buffer.resolution.Count(), Shade::kEmpty);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!readback.buffer.Covered(i)) continue;
        const glm::dvec3 ws = readback.buffer.wsPosition[i];
        const glm::dvec3 toLight = lightSpace.DirectionToLight(ws);
        if (!(glm::dot(NormalAt(ws), toLight) > 0.0)) {
            shades[i] = Shade::kFacingAway;
            continue;
        }
        const double reach = lightSpace.IsPoint() ? lightSpace.DistanceToLight(ws) : 1e4;
        shades[i] = Trace(ws, toLight, 1e-6, reach - 1e-6) ? Shade::kShadowed : Shade::kLit;
    }
    return shades;
}

json Num(double v) {
    if (std::isfinite(v)) return v;
    return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}
json Vec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
json Mat(const glm::dmat4& m) {  // rows, as numpy indexes them
    json rows = json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}
json Matrix(const LightMatrix& l) {
    return {{"p1", Vec(l.p1)}, {"p2", Vec(l.p2)}, {"p4", Vec(l.p4)}};
}
json Points(std::span<const glm::dvec3> points) {
    json out = json::array();
    for (const glm::dvec3& p : points) out.push_back(Vec(p));
    return out;
}
json Nums(std::span<const double> values) {
    json out = json::array();
    for (double v : values) out.push_back(Num(v));
    return out;
}
json Result(const OptimizerResult& r) {
    return {{"matrix", Matrix(r.matrix)},
            {"h", Num(r.h)},
            {"h_after_iteration", Nums(r.hAfterIteration)},
            {"h_before_refine", Num(r.hBeforeRefine)},
            {"candidates_tried", r.candidatesTried},
            {"candidates_rejected", r.candidatesRejected},
            {"used_fallback", r.usedFallback}};
}

template <typename T>
void WriteRaw(const std::string& path, const T* data, std::size_t count) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
    if (!out) throw std::runtime_error("cannot write " + path);
}

// Everything the module binds, for one light, into `out`; the mask into DIR/mask_<l>.u8.
json OneLight(const Light& light, std::size_t l, const Readback& readback, const Camera& camera,
              const Bounds& bounds, Resolution map, const std::string& dir) {
    const LightSpace lightSpace(light, bounds);
    json out;
    const LightMatrix standard = StandardLightMatrix(readback, lightSpace, bounds, map);
    const DepthRange range =
        LightDepthRange(lightSpace, standard, map, bounds, readback.wsRelevant);
    out["standard"] = Matrix(standard);
    out["depth_range"] = {range.near, range.far};
    out["clip_zero_to_one"] =
        Mat(ClipFromWorld(lightSpace, standard, map, range, ClipDepth::kZeroToOne));
    out["clip_minus_one_to_one"] =
        Mat(ClipFromWorld(lightSpace, standard, map, range, ClipDepth::kMinusOneToOne));
    out["map_from_world"] = Mat(MapFromWorld(lightSpace, standard));
    out["initial_axis"] = Vec(InitialLightAxis(lightSpace, bounds, readback.wsRelevant));

    const std::vector<Shade> mask = ExactMask(readback, lightSpace);
    WriteRaw(dir + "/mask_" + std::to_string(l) + ".u8", mask.data(), mask.size());
    const LightSamples samples = MakeLightSamples(readback, lightSpace, mask);
    out["samples"] = {{"ls_x", Points(samples.lsX)},
                      {"dxdx1", Points(samples.dXdx1)},
                      {"dxdx2", Points(samples.dXdx2)},
                      {"pixel", samples.pixel},
                      {"boundary_pixels", samples.boundaryPixels}};
    out["h_standard"] = Num(Energy(standard, samples));
    out["gradient"] = Vec(EnergyGradientAnalytic(standard, samples));
    out["gradient_jets"] = Vec(EnergyGradientJets(standard, samples));
    std::vector<double> stretch;
    for (std::size_t s = 0; s < samples.lsX.size(); ++s)
        stretch.push_back(SampleBadness(standard, samples.lsX[s], samples.dXdx1[s],
                                        samples.dXdx2[s], lexel::Badness::kLargestSingularValue));
    out["largest_singular_value"] = Nums(stretch);
    out["optimize"] = Result(OptimizeLightMatrix(samples, standard.p4, map));

    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = camera;
    context.map = map;
    context.wsBounds = bounds;
    context.wsRelevant = readback.wsRelevant;
    context.wsRelevantHull = readback.wsRelevantHull;
    context.floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);
    context.samples = &samples;
    for (const std::string& name : MethodNamesOf(MethodFamily::kBaseline)) {
        MethodContext method;
        method.baseline = context;
        const MethodMatrix m = ComputeLightMatrix(name, method);
        out["baselines"][name] = {{"matrix", Matrix(m.matrix)},
                                  {"fallback", m.diagnostics.fallback},
                                  {"h", Num(Energy(m.matrix, samples))}};
    }
    const std::vector<OptimizerStart> starts = StandardStarts(context);
    for (const OptimizerStart& s : starts) out["start_names"].push_back(s.name);
    for (const bool refine : {false, true}) {
        OptimizerOptions options;
        options.refine = refine;
        const MultiStartResult r = OptimizeFromStarts(samples, starts, map, options);
        out[refine ? "optimal_refined" : "optimal"] = {{"result", Result(r.result)},
                                                       {"winner", r.winner},
                                                       {"start_map_won", r.startMapWon},
                                                       {"start_h", Nums(r.startH)},
                                                       {"search_h", Nums(r.searchH)}};
    }
    for (const std::string& name : MethodNamesOf(MethodFamily::kPartitioned)) {
        MethodContext method;
        method.baseline = context;
        method.samples = &samples;
        method.partitions.count = 3;
        method.partitions.allocation = CascadeAllocation::kLagrange;
        const std::vector<Cascade> cascades = ComputeLightMatrix(name, method).cascades;
        json c = json::array();
        for (const Cascade& cascade : cascades)
            c.push_back({{"matrix", Matrix(cascade.matrix)},
                         {"map", {cascade.map.width, cascade.map.height}},
                         {"z_near", Num(cascade.zNear)},
                         {"z_far", Num(cascade.zFar)},
                         {"visible_points", cascade.visiblePoints}});
        out["partitions"][name] = {
            {"cascades", c},
            {"h", Num(PartitionedEnergy(cascades, samples, readback.wsRelevant, camera))}};
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: python_reference DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    // The camera pass: 1280×720, reversed-Z with an infinite far plane, NDC y down (Vulkan).
    Camera camera;
    camera.position = {0.0, 1.7, 12.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.resolution = {1280, 720};
    glm::dmat4 projection = camera.ClipFromView();
    projection[1][1] = -projection[1][1];
    projection[2][2] = 0.0;
    projection[3][2] = camera.nearPlane;
    const glm::dmat4 clipFromWorld = projection * camera.ViewFromWorld();
    const Resolution res = camera.resolution;
    const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
    std::vector<float> depth(res.Count(), 0.0f);
    for (int row = 0; row < res.height; ++row)
        for (int x = 0; x < res.width; ++x) {
            const double ndcX = 2.0 * (x + 0.5) / res.width - 1.0,
                         ndcY = 2.0 * (row + 0.5) / res.height - 1.0;
            const glm::dvec4 h = worldFromClip * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
            const glm::dvec3 a = glm::dvec3(h) / h.w;
            if (const auto t = Trace(camera.position, a - camera.position, 0.0, 1e9)) {
                const glm::dvec4 c =
                    clipFromWorld * glm::dvec4(camera.position + *t * (a - camera.position), 1.0);
                depth[static_cast<std::size_t>(row) * res.width + x] =
                    static_cast<float>(c.z / c.w);
            }
        }
    WriteRaw(dir + "/depth.f32", depth.data(), depth.size());
    const DepthConvention convention{ClipDepth::kZeroToOne, DepthDirection::kReversed,
                                     FirstRow::kAtNdcYMinusOne};
    const DepthBuffer cameraDepth{res, depth, clipFromWorld, convention};
    const DepthImage lowRes = DownsampleDepth(cameraDepth);
    const Readback readback = MakeReadback(lowRes.View());
    const Resolution rb = readback.buffer.resolution;
    WriteRaw(dir + "/low_depth.f32", lowRes.depth.data(), lowRes.depth.size());
    WriteRaw(dir + "/ws_position.f64", &readback.buffer.wsPosition[0].x, 3 * rb.Count());
    WriteRaw(dir + "/dwdx1.f64", &readback.dWdx1[0].x, 3 * rb.Count());
    WriteRaw(dir + "/dwdx2.f64", &readback.dWdx2[0].x, 3 * rb.Count());
    WriteRaw(dir + "/smooth.u8", readback.smooth.data(), readback.smooth.size());

    Bounds bounds;
    bounds.Add({-kFloorHalf, 0.0, -kFloorHalf});
    bounds.Add({kFloorHalf, 0.0, kFloorHalf});
    bounds.Add(kBoxLo);
    bounds.Add(kBoxHi);
    const Resolution map{512, 512};
    json out;
    out["clip_from_world"] = Mat(clipFromWorld);
    out["low_res"] = {{"resolution", {lowRes.resolution.width, lowRes.resolution.height}},
                      {"clip_from_world", Mat(lowRes.clipFromWorld)},
                      {"step", lowRes.step},
                      {"offset", {lowRes.offset.x, lowRes.offset.y}}};
    out["readback"] = {{"relevant", readback.wsRelevant.size()},
                       {"hull", Points(readback.wsRelevantHull)}};
    const Light lights[] = {Light{Light::Type::kPoint, {10.0, 15.0, 6.0}, {}},
                            Light{Light::Type::kPoint, {-12.0, 9.0, -4.0}, {}},
                            Light{Light::Type::kDirectional, {}, {-0.4, -1.0, -0.3}}};
    out["inputs"] = {{"camera",
                      {{"position", Vec(camera.position)},
                       {"target", Vec(camera.target)},
                       {"resolution", {res.width, res.height}}}},
                     {"bounds", {Vec(bounds.lo), Vec(bounds.hi)}},
                     {"map", {map.width, map.height}},
                     {"floor_plane", {0.0, 1.0, 0.0, 0.0}},
                     {"partition_count", 3}};
    for (const Light& light : lights)
        out["inputs"]["lights"].push_back(
            {{"kind", light.type == Light::Type::kPoint ? "point" : "directional"},
             {"vector",
              Vec(light.type == Light::Type::kPoint ? light.position : light.direction)}});
    for (const MethodInfo& m : MethodInfos())
        out["methods"].push_back({{"name", m.name}, {"family", MethodFamilyName(m.family)}});
    for (std::size_t l = 0; l < std::size(lights); ++l)
        out["lights"].push_back(OneLight(lights[l], l, readback, camera, bounds, map, dir));
    std::ofstream(dir + "/reference.json") << out.dump(1) << "\n";
    std::printf("python_reference: %zu lights, readback %d×%d with %zu visible points\n",
                std::size(lights), rb.width, rb.height, readback.wsRelevant.size());
    return 0;
}
