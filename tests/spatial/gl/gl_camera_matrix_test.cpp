// The OpenGL backend against the CPU for every camera shape: cameras 1:1, 4:3, 16:9
// and 9:16, each with a square readback and one of its own aspect ratio, on every shipped scene
// (cases/spatial/*.json, at reduced resolutions so that llvmpipe runs the matrix in seconds) and
// the CLI's small case, each with a point and a directional light. Each backend renders its own
// frame, readback, maps and decisions; the bound on a count is RESULTS.md "The OpenGL backend"'s
// max(5, 5e-4 × counted). Per camera shape and readback:
//   - the readbacks: a pixel on a triangle edge may see the other triangle (at most 0.5% of the
//     pixels differ in coverage or triangle); where both see the same triangle they hold the same
//     point to 1e-9 scene radii (the visibility buffer recomputes it in double);
//   - per light, the counted pixels within the bound, and the same boundary samples up to one
//     readback decision flipped at a shadow edge by the maps' float rasterization (its 3 × 3
//     neighbourhood: 9 pixels) or 1%;
//   - per method built from the readback — focused-tight (its visible points), sdsm (its depths)
//     — and focused (the camera's frustum): misclassified and uncovered pixels within the bound;
//   - optimal-report: Algorithm 1's greedy search is discontinuous in the visible points' hull
//     (one silhouette pixel seeing the other triangle moves a hull vertex and can turn the search
//     to another local optimum: h 29.0 on the CPU, 21.0 on GL for meshes.json's directional light
//     at 200², and the CPU optimizer given the GL hull finds GL's 21.0 exactly), so its matrix is
//     held to the backends instead: the GL evaluation of GL's matrix and the CPU evaluation of the
//     same matrix misclassify and leave uncovered pixels within the bound.
//
// Before the fix of Camera::RayDirection the GL readback of a non-square camera with a square
// readback rebuilt its points over a square frustum: every non-square shape here failed the
// readback check, and spatial_small light 0 left uncovered CPU → GL focused-tight 169 → 1,381.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/gl/gl_backend.h"
#include "lexel/spatial/harness/evaluation.h"
#include "spatial/gl/gl_test_support.h"

namespace lexel::spatial {
namespace {

using testing::GlTest;

struct CameraShape {
    const char* name;
    Resolution frame;
    Resolution matchingReadback;  // the frame's aspect ratio
};

// Frames of about 40,000 pixels, readbacks of 3,900–5,200.
constexpr CameraShape kShapes[] = {{"1:1", {200, 200}, {64, 64}},
                                   {"4:3", {232, 174}, {72, 54}},
                                   {"16:9", {272, 153}, {96, 54}},
                                   {"9:16", {153, 272}, {54, 96}}};
constexpr Resolution kSquareReadback{64, 64};

struct MatrixScene {
    const char* file;  // under LEXEL_CASES_DIR, or (cliData) LEXEL_CLI_DATA_DIR
    bool cliData = false;
};

constexpr MatrixScene kScenes[] = {{"spatial/walkthrough.json"},
                                   {"spatial/courtyard.json"},
                                   {"spatial/street.json"},
                                   {"spatial/meshes.json"},
                                   {"spatial_small.json", true}};

void PrintTo(const MatrixScene& s, std::ostream* os) { *os << s.file; }

// The case at the matrix's map size with two lights: its first point light and its first
// directional one (or, without one, a directional light along the point light's direction).
Scene LoadMatrixScene(const MatrixScene& s) {
    Scene scene = cases::LoadSpatialScene(
        std::string(s.cliData ? LEXEL_CLI_DATA_DIR : LEXEL_CASES_DIR) + "/" + s.file);
    scene.shadowMap = {192, 192};
    std::vector<Light> lights;
    for (const Light::Type type : {Light::Type::kPoint, Light::Type::kDirectional})
        for (const Light& light : scene.lights)
            if (light.type == type) {
                lights.push_back(light);
                break;
            }
    if (lights.size() == 1)
        lights.push_back(Light{Light::Type::kDirectional, {}, -lights[0].position});
    scene.lights = lights;
    return scene;
}

std::int64_t Bound(std::int64_t counted) { return std::max<std::int64_t>(5, counted / 2000); }

// The largest CPU/GL differences over a scene's matrix, for the summary line.
struct Worst {
    std::size_t readbackPixels = 0, samples = 0, evaluations = 0;
    double point = 0.0;  // scene radii
    std::int64_t counted = 0, misclassified = 0, uncovered = 0;
};

void CompareReadbacks(const std::string& where, const Readback& c, const Readback& g,
                      double sceneRadius, Worst* worst) {
    std::size_t differ = 0;
    double point = 0.0;
    for (std::size_t i = 0; i < c.buffer.triangle.size(); ++i) {
        if (c.buffer.triangle[i] != g.buffer.triangle[i]) {
            ++differ;
        } else if (c.buffer.Covered(i)) {
            point = std::max(
                point, glm::length(c.buffer.wsPosition[i] - g.buffer.wsPosition[i]) / sceneRadius);
        }
    }
    EXPECT_LE(differ, c.buffer.resolution.Count() / 200) << where << ": readback pixels differ";
    EXPECT_LT(point, 1e-9) << where << ": readback points (scene radii)";
    worst->readbackPixels = std::max(worst->readbackPixels, differ);
    worst->point = std::max(worst->point, point);
}

std::size_t SampleDifference(const LightSamples& a, const LightSamples& b) {
    std::vector<std::uint32_t> common;
    std::set_intersection(a.pixel.begin(), a.pixel.end(), b.pixel.begin(), b.pixel.end(),
                          std::back_inserter(common));
    return a.pixel.size() + b.pixel.size() - 2 * common.size();
}

// Counted pixels of a shading that `matrix` leaves outside its map (MethodOutcome::uncovered).
std::int64_t Uncovered(const Evaluator& evaluator, const Light& light, const LightMatrix& matrix) {
    const std::vector<Shade> shades = evaluator.ShadeFrame(light, matrix);
    const LightSpace lightSpace(light, evaluator.bounds());
    const Resolution map = evaluator.scene().shadowMap;
    std::int64_t uncovered = 0;
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (shades[i] != Shade::kLit && shades[i] != Shade::kShadowed) continue;
        const glm::dvec3 lsX = lightSpace.ToLight(evaluator.frame().wsPosition[i]);
        const glm::dvec2 u = InFront(matrix.p4, lsX) ? matrix.Map(lsX) : glm::dvec2(-1.0);
        uncovered += !(u.x >= 0.0 && u.y >= 0.0 && u.x < map.width && u.y < map.height);
    }
    return uncovered;
}

void ExpectCounts(const std::string& where, const std::string& method, std::int64_t cpuWrong,
                  std::int64_t glWrong, std::int64_t cpuUncovered, std::int64_t glUncovered,
                  std::int64_t bound, Worst* worst) {
    EXPECT_LE(std::abs(glWrong - cpuWrong), bound) << where << ", " << method << ": misclassified "
                                                   << cpuWrong << " (cpu), " << glWrong << " (gl)";
    EXPECT_LE(std::abs(glUncovered - cpuUncovered), bound)
        << where << ", " << method << ": uncovered " << cpuUncovered << " (cpu), " << glUncovered
        << " (gl)";
    worst->misclassified = std::max(worst->misclassified, std::abs(glWrong - cpuWrong));
    worst->uncovered = std::max(worst->uncovered, std::abs(glUncovered - cpuUncovered));
    ++worst->evaluations;
}

void CompareLight(const std::string& where, const Evaluator& cpuEval, const LightOutcome& c,
                  const LightOutcome& g, Worst* worst) {
    const std::int64_t bound = Bound(c.receiverPixels);
    const std::int64_t countedDiff = std::abs(g.receiverPixels - c.receiverPixels);
    EXPECT_LE(countedDiff, bound) << where << ": counted " << c.receiverPixels << " (cpu), "
                                  << g.receiverPixels << " (gl)";
    const std::size_t sampleDiff = SampleDifference(c.samples, g.samples);
    EXPECT_LE(sampleDiff, std::max<std::size_t>(9, c.samples.pixel.size() / 100))
        << where << ": boundary samples " << c.samples.pixel.size() << " (cpu), "
        << g.samples.pixel.size() << " (gl), " << sampleDiff << " differ";
    worst->counted = std::max(worst->counted, countedDiff);
    worst->samples = std::max(worst->samples, sampleDiff);
    for (std::size_t m = 0; m < c.methods.size(); ++m) {
        const MethodOutcome &co = c.methods[m], &go = g.methods[m];
        if (co.method != "optimal-report") {
            ExpectCounts(where, co.method, co.metrics.misclassified, go.metrics.misclassified,
                         co.metrics.uncovered, go.metrics.uncovered, bound, worst);
            continue;
        }
        ExpectCounts(where, co.method + " (GL's matrix on both)",
                     cpuEval.Misclassified(c.light, go.matrix), go.metrics.misclassified,
                     Uncovered(cpuEval, c.light, go.matrix), go.metrics.uncovered, bound, worst);
    }
}

void RunScene(const MatrixScene& s) {
    const Scene base = LoadMatrixScene(s);
    const auto cpu = MakeCpuRenderer(base.geometry);
    const auto gpu = gl::MakeGlBackend(base.geometry);
    const double sceneRadius = base.geometry.ComputeBounds().Radius();
    EvaluationOptions options;
    options.methods = {"focused", "focused-tight", "sdsm", "optimal-report"};
    Worst worst;
    for (const CameraShape& shape : kShapes)
        for (const Resolution readback : {kSquareReadback, shape.matchingReadback}) {
            Scene scene = base;
            scene.camera.resolution = shape.frame;
            scene.readback = readback;
            const Evaluator cpuEval(scene, *cpu), gpuEval(scene, *gpu);
            const std::string camera = std::string(s.file) + ", camera " + shape.name + " " +
                                       std::to_string(shape.frame.width) + "×" +
                                       std::to_string(shape.frame.height) + ", readback " +
                                       std::to_string(readback.width) + "×" +
                                       std::to_string(readback.height);
            CompareReadbacks(camera, cpuEval.readback(), gpuEval.readback(), sceneRadius, &worst);
            for (std::size_t l = 0; l < scene.lights.size(); ++l)
                CompareLight(camera + ", light " + std::to_string(l), cpuEval,
                             cpuEval.Evaluate(scene.lights[l], options),
                             gpuEval.Evaluate(scene.lights[l], options), &worst);
        }
    std::cout << "[   INFO   ] " << s.file << ": " << worst.evaluations
              << " method evaluations; largest CPU/GL differences: readback pixels "
              << worst.readbackPixels << ", points " << worst.point << " scene radii, counted "
              << worst.counted << ", boundary samples " << worst.samples << ", misclassified "
              << worst.misclassified << ", uncovered " << worst.uncovered << '\n';
}

class GlCameraMatrix : public GlTest, public ::testing::WithParamInterface<MatrixScene> {};

TEST_P(GlCameraMatrix, AgreesWithTheCpuForEveryCameraShape) { RunScene(GetParam()); }

std::string SceneName(const ::testing::TestParamInfo<MatrixScene>& info) {
    std::string name = info.param.file;
    name = name.substr(name.find_last_of('/') + 1);
    return name.substr(0, name.find('.'));
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, GlCameraMatrix, ::testing::ValuesIn(kScenes), SceneName);

}  // namespace
}  // namespace lexel::spatial
