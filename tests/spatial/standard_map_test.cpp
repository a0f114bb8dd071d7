// The renderer's side of Algorithm 1 step 1 (before: the embedding recipe never said what
// "your standard map" was, nor how deep to render it). StandardLightMatrix is the map
// OptimizeLightMatrix starts from; the recipe an embedder follows — a reversed-Z depth buffer of
// its camera pass, the standard map rendered through ClipFromWorld with LightDepthRange into a
// float depth buffer (depths outside [0, 1] clipped, as a rasterizer does), its own shadow test on
// the readback's points — finds the boundary samples of lexel's own CPU pipeline (ShadePoint with
// the same matrix on the exact pass at the same pixels) and the same optimized matrix.
#include "lexel/spatial/standard_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <iterator>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/depth_buffer.h"
#include "lexel/spatial/harness/raster.h"
#include "lexel/spatial/optimizer.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

constexpr Resolution kMap{512, 512};

std::vector<Light> Lights() {
    return {Light{Light::Type::kPoint, {10.0, 15.0, 6.0}, {}},
            Light{Light::Type::kDirectional, {}, {-0.4, -1.0, -0.3}}};
}

// The camera pass as an engine stores it today: reversed-Z, [0, 1] clip depth, infinite far
// plane; and the exact pass, for the renderer's normals.
struct EnginePass {
    CameraBuffer exact;
    std::vector<float> depth;
    DepthBuffer buffer;
};

EnginePass ReversedZPass(const testing::FloorAndBox& scene) {
    EnginePass pass;
    const Camera& camera = scene.camera;
    pass.exact = MakeCpuRenderer(scene.mesh)->RenderCamera(camera, camera.resolution);
    glm::dmat4 projection =
        glm::perspectiveRH_ZO(glm::radians(camera.fovYDeg), camera.AspectRatio(), 1.0, 2.0);
    projection[2][2] = 0.0;  // z_ndc = near / z_view
    projection[3][2] = camera.nearPlane;
    const glm::dmat4 clipFromWorld = projection * camera.ViewFromWorld();
    pass.depth.assign(camera.resolution.Count(), 0.0f);
    for (std::size_t i = 0; i < pass.depth.size(); ++i)
        if (pass.exact.Covered(i)) {
            const glm::dvec4 h = clipFromWorld * glm::dvec4(pass.exact.wsPosition[i], 1.0);
            pass.depth[i] = static_cast<float>(h.z / h.w);
        }
    pass.buffer = {camera.resolution,
                   pass.depth,
                   clipFromWorld,
                   {ClipDepth::kZeroToOne, DepthDirection::kReversed, FirstRow::kAtNdcYPlusOne}};
    return pass;
}

// The embedder's standard map: rasterized through the 4×4, the NDC depth kept as float where it
// lies in [0, 1] (+inf where nothing is drawn).
std::vector<float> RenderMapAsARenderer(const TriangleMesh& mesh, const LightSpace& ls,
                                        const LightMatrix& matrix, const glm::dmat4& clip) {
    RasterBuffer raster = MakeRasterBuffer(kMap);
    const auto ndcDepth = [&](const glm::dvec3& ws) {
        const glm::dvec4 h = clip * glm::dvec4(ws, 1.0);
        const double z = h.z / h.w;
        return z >= 0.0 && z <= 1.0 ? z : std::numeric_limits<double>::infinity();
    };
    RasterizeNearest(mesh, ImageRows(MapFromWorld(ls, matrix)), 1e-9, ndcDepth, &raster);
    return std::vector<float>(raster.depth.begin(), raster.depth.end());
}

// The embedder's shadow test at each readback pixel: the receiver's plane depth at the texel
// centre's ray (receiver-plane depth bias) against the stored depth, less 1e-6 in NDC.
std::vector<Shade> MaskAsARenderer(const Readback& readback, const CameraBuffer& exact,
                                   const LightSpace& ls, const glm::dmat4& clip,
                                   const std::vector<float>& map) {
    const glm::dmat4 worldFromClip = glm::inverse(clip);
    const auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 h = worldFromClip * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(h) / h.w;
    };
    std::vector<Shade> shades(readback.buffer.resolution.Count(), Shade::kEmpty);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!readback.buffer.Covered(i)) continue;
        const glm::dvec3& ws = readback.buffer.wsPosition[i];
        const glm::dvec3& n = exact.wsNormal[i];  // the renderer knows its normals
        if (!(glm::dot(n, ls.DirectionToLight(ws)) > 0.0)) {
            shades[i] = Shade::kFacingAway;
            continue;
        }
        shades[i] = Shade::kLit;
        const glm::dvec4 h = clip * glm::dvec4(ws, 1.0);
        if (!(h.w > 0.0)) continue;
        const int tx = static_cast<int>(std::floor((h.x / h.w + 1.0) * 0.5 * kMap.width));
        const int ty = static_cast<int>(std::floor((h.y / h.w + 1.0) * 0.5 * kMap.height));
        if (tx < 0 || ty < 0 || tx >= kMap.width || ty >= kMap.height) continue;
        const float stored = map[static_cast<std::size_t>(ty) * kMap.width + tx];
        if (std::isinf(stored)) continue;
        const double xc = 2.0 * (tx + 0.5) / kMap.width - 1.0;
        const double yc = 2.0 * (ty + 0.5) / kMap.height - 1.0;
        const glm::dvec3 a = unproject(xc, yc, 0.0), b = unproject(xc, yc, 1.0);
        const double t = glm::dot(n, ws - a) / glm::dot(n, b - a);
        const glm::dvec4 onPlane = clip * glm::dvec4(a + t * (b - a), 1.0);
        const double receiver = std::isfinite(t) ? onPlane.z / onPlane.w : h.z / h.w;
        if (stored < receiver - 1e-6) shades[i] = Shade::kShadowed;
    }
    return shades;
}

std::size_t SampleDifference(const LightSamples& a, const LightSamples& b) {
    std::vector<std::uint32_t> common;
    std::set_intersection(a.pixel.begin(), a.pixel.end(), b.pixel.begin(), b.pixel.end(),
                          std::back_inserter(common));
    return a.pixel.size() + b.pixel.size() - 2 * common.size();
}

TEST(StandardLightMatrix, IsTheMapAlgorithmOneStartsFromAndCoversTheVisiblePoints) {
    const testing::FloorAndBox scene = testing::EmbeddingScene();
    const auto cpu = MakeCpuRenderer(scene.mesh);
    const Readback readback = RenderReadback(*cpu, scene.camera, scene.camera.resolution);
    for (const Light& light : Lights()) {
        const LightSpace ls(light, scene.wsBounds);
        const LightMatrix standard = StandardLightMatrix(readback, ls, scene.wsBounds, kMap);
        for (const glm::dvec3& ws : readback.wsRelevant) {
            const glm::dvec3 lsX = ls.ToLight(ws);
            ASSERT_TRUE(InFront(standard.p4, lsX));
            const glm::dvec2 u = standard.Map(lsX);
            // Inside, with the 2% margin: at least ~1% of the map from each edge on one axis.
            ASSERT_TRUE(u.x > 0.0 && u.y > 0.0 && u.x < kMap.width && u.y < kMap.height);
        }
        const LightSamples samples =
            cpu->BoundarySamples(readback, ls, cpu->RenderShadowMap(ls, standard, kMap));
        ASSERT_GT(samples.lsX.size(), 20u);
        const OptimizerResult optimal = OptimizeLightMatrix(samples, standard.p4, kMap);
        EXPECT_NEAR(Energy(standard, samples) / optimal.hAfterIteration.front(), 1.0, 1e-9);
        EXPECT_EQ(standard.p4, InitialLightAxis(ls, scene.wsBounds, readback.wsRelevant));
        EXPECT_LT(optimal.h, optimal.hAfterIteration.front());
    }
    Readback empty = readback;
    empty.wsRelevant.clear();
    const LightSpace ls(Lights()[0], scene.wsBounds);
    EXPECT_THROW(StandardLightMatrix(empty, ls, scene.wsBounds, kMap), lexel::DomainError);
}

TEST(StandardLightMatrix, TheRenderersRecipeFindsLexelsOwnSamplesAndMatrix) {
    const testing::FloorAndBox scene = testing::EmbeddingScene();
    const auto cpu = MakeCpuRenderer(scene.mesh);
    const EnginePass pass = ReversedZPass(scene);
    const Readback readback = MakeReadback(pass.buffer);
    // lexel's pipeline on the exact pass, which has the normals ShadePoint needs.
    const Readback exact =
        MakeReadback(pass.exact, scene.camera.ScreenFromWorld(scene.camera.resolution));
    for (const Light& light : Lights()) {
        const LightSpace ls(light, scene.wsBounds);
        const LightMatrix standard = StandardLightMatrix(readback, ls, scene.wsBounds, kMap);
        const glm::dmat4 clip =
            ClipFromWorld(ls, standard, kMap,
                          LightDepthRange(ls, standard, kMap, scene.wsBounds, readback.wsRelevant),
                          ClipDepth::kZeroToOne);
        const std::vector<float> map = RenderMapAsARenderer(scene.mesh, ls, standard, clip);
        const std::vector<Shade> mask = MaskAsARenderer(readback, pass.exact, ls, clip, map);
        const LightSamples recipe = MakeLightSamples(readback, ls, mask);
        const LightSamples lexel =
            cpu->BoundarySamples(exact, ls, cpu->RenderShadowMap(ls, standard, kMap));
        const std::size_t differ = SampleDifference(recipe, lexel);
        EXPECT_LE(differ, std::max<std::size_t>(9, lexel.pixel.size() / 100))
            << recipe.pixel.size() << " recipe samples, " << lexel.pixel.size() << " lexel's";
        const OptimizerResult a = OptimizeLightMatrix(recipe, standard.p4, kMap);
        const OptimizerResult b = OptimizeLightMatrix(lexel, standard.p4, kMap);
        EXPECT_LT(Energy(a.matrix, lexel), 1.01 * b.h);
        // The optimized map's tight depth range holds every visible point.
        const glm::dmat4 optimizedClip =
            ClipFromWorld(ls, a.matrix, kMap,
                          LightDepthRange(ls, a.matrix, kMap, scene.wsBounds, readback.wsRelevant),
                          ClipDepth::kZeroToOne);
        double worstNdc = 0.0, lo = 1.0, hi = 0.0;
        for (const glm::dvec3& ws : readback.wsRelevant) {
            const glm::dvec4 h = optimizedClip * glm::dvec4(ws, 1.0);
            ASSERT_GT(h.w, 0.0);
            worstNdc = std::max({worstNdc, std::abs(h.x / h.w), std::abs(h.y / h.w)});
            lo = std::min(lo, h.z / h.w);
            hi = std::max(hi, h.z / h.w);
        }
        EXPECT_LE(worstNdc, 1.0);
        EXPECT_GE(lo, 0.0);
        EXPECT_LE(hi, 1.0);
        std::cout << "[   INFO   ] " << (ls.IsPoint() ? "point" : "directional") << ": "
                  << recipe.pixel.size() << " recipe samples, " << lexel.pixel.size()
                  << " lexel's, " << differ << " differ; h " << b.hAfterIteration.front() << " -> "
                  << a.h << " (recipe), " << b.h << " (lexel); visible points at NDC z " << lo
                  << "–" << hi << '\n';
    }
}

}  // namespace
}  // namespace lexel::spatial
