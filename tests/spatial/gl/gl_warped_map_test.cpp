// RTW on the GPU (warp_shaders.h): the map rendered by the vertex warp of tessellated geometry
// against the ray-cast map of the same warp (ray_cast_map.h), on the small CLI case's light and
// its four sweep lights (point and directional) for rtw and rtw-lagrange, and on the
// walkthrough's two lights for rtw: depths and coverage texel by texel, and the frame's decisions
// through each map. The tessellated triangles' straight edges approximate the warp's curve, so a
// texel near a triangle's edge may go to the triangle behind it; and with an identity warp the
// pass must give the linear shadow pass's map, on the walkthrough too, whose floor tessellates
// into more triangles than llvmpipe renders in one draw (WarpDrawBatches).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string_view>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/gl/gl_backend.h"
#include "lexel/spatial/gl/warp_refinement.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/ray_cast_map.h"
#include "lexel/spatial/harness/ray_caster.h"
#include "lexel/spatial/methods/registry.h"
#include "spatial/gl/gl_test_support.h"

namespace lexel::spatial {
namespace {

using testing::GlTest;

const Scene& SmallScene() {
    static const Scene scene =
        cases::LoadSpatialScene(std::string(LEXEL_CLI_DATA_DIR) + "/spatial_small.json");
    return scene;
}

struct Difference {
    std::int64_t texels = 0, depthDiffers = 0, coverageDiffers = 0;
    std::int64_t counted = 0, decisionsDiffer = 0;
};

Difference Compare(const ShadowMap& gl, const ShadowMap& cast, const CameraBuffer& frame,
                   const LightSpace& lightSpace) {
    Difference d;
    for (std::size_t i = 0; i < gl.depth.size(); ++i) {
        const bool a = std::isfinite(gl.depth[i]), b = std::isfinite(cast.depth[i]);
        d.texels += a || b;
        d.coverageDiffers += a != b;
        if (a && b) d.depthDiffers += std::abs(gl.depth[i] - cast.depth[i]) > 1e-6 * cast.depth[i];
    }
    const std::vector<Shade> sg = ShadeWarpedPixels(frame, lightSpace, gl);
    const std::vector<Shade> sc = ShadeWarpedPixels(frame, lightSpace, cast);
    for (std::size_t i = 0; i < sc.size(); ++i) {
        if (sc[i] != Shade::kLit && sc[i] != Shade::kShadowed) continue;
        ++d.counted;
        d.decisionsDiffer += sg[i] != sc[i];
    }
    return d;
}

// Per map: decisions within 0.1%, texels (depth or coverage) within 0.5%.
void ExpectGpuWarpedMapsMatchTheRayCastMaps(const Scene& scene, const std::vector<Light>& lights,
                                            const std::vector<const char*>& methods) {
    const auto cpu = MakeCpuRenderer(scene.geometry);
    const auto gl = gl::MakeGlBackend(scene.geometry);
    const RayCaster caster(scene.geometry);
    const RayCastMapper mapper(scene.geometry, caster);
    const Bounds bounds = scene.geometry.ComputeBounds();
    const CameraBuffer frame = cpu->RenderCamera(scene.camera, scene.camera.resolution);
    const Readback readback = RenderReadback(*cpu, scene.camera, scene.readback);
    Difference total;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightSpace lightSpace(lights[l], bounds);
        MethodContext context;
        context.baseline = MakeBaselineContext(scene, lightSpace, bounds, readback.wsRelevant,
                                               readback.wsRelevantHull);
        const ShadowMap standard =
            cpu->RenderShadowMap(lightSpace, FocusedLightMatrix(context.baseline), scene.shadowMap);
        const LightSamples samples = cpu->BoundarySamples(readback, lightSpace, standard);
        context.samples = &samples;
        context.baseline.samples = &samples;
        context.readback = &readback;
        context.frame = scene.camera.resolution;
        for (const char* method : methods) {
            const MethodMatrix m = ComputeLightMatrix(method, context);
            ASSERT_TRUE(m.warp);
            const std::optional<ShadowMap> onGpu =
                gl->RenderWarpedShadowMap(lightSpace, *m.warp, scene.shadowMap);
            ASSERT_TRUE(onGpu);
            ASSERT_TRUE(onGpu->warp);
            const ShadowMap cast = mapper.Render(lightSpace, *m.warp, scene.shadowMap);
            const Difference d = Compare(*onGpu, cast, frame, lightSpace);
            std::cout << "[   INFO   ] light " << l << ", " << method << ": texels " << d.texels
                      << ", depth differs " << d.depthDiffers << ", coverage " << d.coverageDiffers
                      << "; decisions differ on " << d.decisionsDiffer << " of " << d.counted
                      << " pixels\n";
            EXPECT_LE(d.depthDiffers + d.coverageDiffers, d.texels / 200)
                << "light " << l << ", " << method;
            EXPECT_LE(d.decisionsDiffer, d.counted / 1000) << "light " << l << ", " << method;
            total.texels += d.texels, total.depthDiffers += d.depthDiffers;
            total.coverageDiffers += d.coverageDiffers, total.counted += d.counted;
            total.decisionsDiffer += d.decisionsDiffer;
        }
    }
    std::cout << "[   INFO   ] all: texels " << total.texels << ", depth differs "
              << total.depthDiffers << ", coverage " << total.coverageDiffers
              << "; decisions differ on " << total.decisionsDiffer << " of " << total.counted
              << " pixels\n";
}

// Measured: over the 10 maps at most 12 texels and 3 decisions differ on one map (rtw-lagrange,
// sweep light 4), 31 texels and 3 of 112,570 decisions in all. (Drawn in one call, llvmpipe lost
// most of the tessellated output of large triangles: rtw-lagrange's map of sweep light 4 then
// differed on 1,932 texels.)
TEST_F(GlTest, RtwMapByTheVertexWarpOfTessellatedGeometryMatchesTheRayCastMap) {
    const Scene& scene = SmallScene();
    std::vector<Light> lights = scene.lights;
    for (const Light& l : cases::SweepLightsOf(scene, 4)) lights.push_back(l);
    ExpectGpuWarpedMapsMatchTheRayCastMaps(scene, lights, {"rtw", "rtw-lagrange"});
}

// The walkthrough's 400² maps, whose 40 × 40 floor reaches far beyond the focused map. Measured:
// 22 of 307,848 texels and 7 of 573,979 decisions differ over the two maps; before
// WarpDrawBatches the first light's GPU map missed 107,929 of its 156,645 texels.
TEST_F(GlTest, RtwOnTheWalkthroughMatchesTheRayCastMap) {
    const Scene scene =
        cases::LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/spatial/walkthrough.json");
    ExpectGpuWarpedMapsMatchTheRayCastMaps(scene, scene.lights, {"rtw"});
}

TEST_F(GlTest, WarpedPassWithTheIdentityWarpIsTheLinearPass) {
    for (const Scene& scene :
         {SmallScene(),
          cases::LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/spatial/walkthrough.json")}) {
        const auto gl = gl::MakeGlBackend(scene.geometry);
        const Bounds bounds = scene.geometry.ComputeBounds();
        const auto cpu = MakeCpuRenderer(scene.geometry);
        const Readback readback = RenderReadback(*cpu, scene.camera, scene.readback);
        for (const Light& light : scene.lights) {
            const LightSpace lightSpace(light, bounds);
            const LightMatrix m = LispsmTightLightMatrix(MakeBaselineContext(
                scene, lightSpace, bounds, readback.wsRelevant, readback.wsRelevantHull));
            const ShadowMap linear = gl->RenderShadowMap(lightSpace, m, scene.shadowMap);
            MapWarp identity = MapWarp::Linear(m);
            identity.x = AxisWarp::Affine(1.0, 0.0);  // not IsLinear, the same map
            const std::optional<ShadowMap> warped =
                gl->RenderWarpedShadowMap(lightSpace, identity, scene.shadowMap);
            ASSERT_TRUE(warped);
            std::int64_t differ = 0;
            for (std::size_t i = 0; i < linear.depth.size(); ++i)
                differ += !(linear.depth[i] == warped->depth[i] ||
                            std::abs(linear.depth[i] - warped->depth[i]) <= 1e-6 * linear.depth[i]);
            EXPECT_LE(differ, static_cast<std::int64_t>(linear.depth.size() / 10000));
        }
        // A logarithmic axis is not rendered on the GPU.
        MapWarp log = MapWarp::Linear(LightMatrix{});
        log.y = AxisWarp::Logarithmic(-1.0, 1.0, 10.0, 0.0);
        EXPECT_FALSE(
            gl->RenderWarpedShadowMap(LightSpace(scene.lights[0], bounds), log, scene.shadowMap));
    }
}

// The batches of the warped pass: pieces at level 64 (a 128-texel edge in 2-texel segments) are
// 4,096 triangles each, 16 to a batch of 65,536; 1-texel and 3-texel edges are levels 1 and 2;
// a piece behind the light's plane (+inf) or NaN counts at the highest level.
TEST(WarpDrawBatches, CutsTheDrawAtTheTessellatedTriangleBudget) {
    EXPECT_EQ(gl::WarpDrawBatches(std::vector<double>(20, 128.0), 2.0, 64.0),
              (std::vector<std::size_t>{0, 16, 20}));
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(gl::WarpDrawBatches(std::vector<double>{1.0, inf, nan, 3.0}, 2.0, 64.0),
              (std::vector<std::size_t>{0, 4}));
    std::vector<double> mixed(15, 128.0);
    mixed.push_back(inf);  // the 16th, at level 64, fills the batch exactly; a 1-triangle 17th
                           // starts the next, which the 18th joins
    mixed.push_back(1.0);
    mixed.push_back(128.0);
    EXPECT_EQ(gl::WarpDrawBatches(mixed, 2.0, 64.0), (std::vector<std::size_t>{0, 16, 18}));
    EXPECT_EQ(gl::WarpDrawBatches({}, 2.0, 64.0), (std::vector<std::size_t>{0}));
}

}  // namespace
}  // namespace lexel::spatial
