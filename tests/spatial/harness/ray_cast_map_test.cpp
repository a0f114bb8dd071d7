// Ray-cast shadow maps (ray_cast_map.h): the map of a linear warp equals the CPU rasterizer's on
// every shipped scene (depths within 1e-6 relative wherever both maps pick the same surface, the
// same shadow decisions on at least 99.99% of the counted pixels), with and without a sub-texel
// phase, and the warped shading of a linear warp is ShadePoint's decision bit for bit.
#include "lexel/spatial/harness/ray_cast_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/ray_caster.h"

namespace lexel::spatial {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> ShippedScenes() {
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(fs::path(LEXEL_CASES_DIR) / "spatial"))
        if (entry.path().extension() == ".json") paths.push_back(entry.path());
    std::sort(paths.begin(), paths.end());
    return paths;
}

struct MapAgreement {
    std::int64_t both = 0;      // texels both maps cover
    std::int64_t equal = 0;     // ... with depths within 1e-6 relative
    std::int64_t coverage = 0;  // texels exactly one map covers
};

MapAgreement CompareMaps(const ShadowMap& raster, const ShadowMap& cast) {
    MapAgreement a;
    for (std::size_t i = 0; i < raster.depth.size(); ++i) {
        const bool r = std::isfinite(raster.depth[i]), c = std::isfinite(cast.depth[i]);
        a.coverage += r != c;
        if (!r || !c) continue;
        ++a.both;
        a.equal += std::abs(raster.depth[i] - cast.depth[i]) <= 1e-6 * std::abs(raster.depth[i]);
    }
    return a;
}

// Counted pixels (lit or shadowed under the raster map) and those decided alike.
std::pair<std::int64_t, std::int64_t> CompareShades(const std::vector<Shade>& a,
                                                    const std::vector<Shade>& b) {
    std::int64_t counted = 0, same = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] != Shade::kLit && a[i] != Shade::kShadowed) continue;
        ++counted;
        same += a[i] == b[i];
    }
    return {counted, same};
}

// The same map with its texel grid moved by `offset` texels (u' = u + offset).
LightMatrix Shifted(const LightMatrix& m, const glm::dvec2& offset) {
    glm::dmat3 a(1.0);
    a[2][0] = offset.x;
    a[2][1] = offset.y;
    return m.ThenAffine(a);
}

TEST(RayCastMap, EqualsTheRasterMapOnEveryShippedScene) {
    const std::vector<fs::path> scenes = ShippedScenes();
    ASSERT_GE(scenes.size(), 4u);
    for (const fs::path& path : scenes) {
        const Scene scene = cases::LoadSpatialScene(path);
        const auto backend = MakeCpuRenderer(scene.geometry);
        const RayCaster caster(scene.geometry);
        const RayCastMapper mapper(scene.geometry, caster);
        const Bounds bounds = scene.geometry.ComputeBounds();
        const CameraBuffer frame = backend->RenderCamera(scene.camera, scene.camera.resolution);
        const Readback readback = RenderReadback(*backend, scene.camera, scene.readback);
        for (const Light& light : scene.lights) {
            const LightSpace lightSpace(light, bounds);
            const BaselineContext context = MakeBaselineContext(
                scene, lightSpace, bounds, readback.wsRelevant, readback.wsRelevantHull);
            const struct {
                const char* name;
                LightMatrix matrix;
            } matrices[] = {{"focused-tight", FocusedTightLightMatrix(context)},
                            {"lispsm-tight", LispsmTightLightMatrix(context)},
                            {"lispsm-tight, phase (0.37, 0.81)",
                             Shifted(LispsmTightLightMatrix(context), {0.37, 0.81})}};
            for (const auto& [name, matrix] : matrices) {
                const std::string what = path.stem().string() + ", " +
                                         (lightSpace.IsPoint() ? "point" : "directional") + ", " +
                                         name;
                const ShadowMap raster =
                    backend->RenderShadowMap(lightSpace, matrix, scene.shadowMap);
                const ShadowMap cast =
                    mapper.Render(lightSpace, MapWarp::Linear(matrix), scene.shadowMap);
                EXPECT_FALSE(cast.warp) << what;
                const MapAgreement a = CompareMaps(raster, cast);
                // A texel whose centre lies on a triangle edge may go to another triangle: allow
                // 0.01% of the covered texels (measured: 1 texel of the 3.7 million here).
                EXPECT_GT(a.both, 10000) << what;
                EXPECT_GE(a.equal, a.both - a.both / 10000) << what;
                EXPECT_LE(a.coverage, a.both / 10000) << what;
                const auto [counted, same] =
                    CompareShades(backend->ShadePixels(frame, lightSpace, raster),
                                  backend->ShadePixels(frame, lightSpace, cast));
                EXPECT_GT(counted, 10000) << what;
                EXPECT_GE(static_cast<double>(same), 0.9999 * static_cast<double>(counted))
                    << what << ": " << counted - same << " of " << counted << " differ";
                std::cout << "[ ray cast ] " << what << ": depths equal on " << a.equal << " of "
                          << a.both << " texels, coverage differs on " << a.coverage
                          << ", decisions differ on " << counted - same << " of " << counted
                          << " pixels\n";
            }
        }
    }
}

TEST(RayCastMap, PhaseInWarpedTexelsIsTheShiftedMatrixsMap) {
    // A phase δ of a linear warp is the matrix's map shifted by δ: the same texel centres' rays,
    // so the ray-cast map of (matrix, δ) equals the ray-cast map of the shifted matrix exactly.
    const Scene scene =
        cases::LoadSpatialScene(fs::path(LEXEL_CASES_DIR) / "spatial" / "walkthrough.json");
    const RayCaster caster(scene.geometry);
    const RayCastMapper mapper(scene.geometry, caster);
    const Bounds bounds = scene.geometry.ComputeBounds();
    const LightSpace lightSpace(scene.lights.front(), bounds);
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Readback readback = RenderReadback(*backend, scene.camera, scene.readback);
    const BaselineContext context = MakeBaselineContext(
        scene, lightSpace, bounds, readback.wsRelevant, readback.wsRelevantHull);
    const LightMatrix matrix = FocusedTightLightMatrix(context);
    const glm::dvec2 phase(0.25, 0.625);  // exact in binary: the two routes round alike
    MapWarp warp = MapWarp::Linear(matrix);
    warp.phase = phase;
    const ShadowMap withPhase = mapper.Render(lightSpace, warp, scene.shadowMap);
    ASSERT_TRUE(withPhase.warp);
    const ShadowMap shifted =
        mapper.Render(lightSpace, MapWarp::Linear(Shifted(matrix, phase)), scene.shadowMap);
    std::int64_t differ = 0;
    for (std::size_t i = 0; i < shifted.depth.size(); ++i)
        differ += !(withPhase.depth[i] == shifted.depth[i] ||
                    std::abs(withPhase.depth[i] - shifted.depth[i]) <= 1e-6 * shifted.depth[i]);
    EXPECT_LE(differ, static_cast<std::int64_t>(shifted.depth.size() / 10000));
    // Both shade every frame pixel alike but where a texel went to another triangle.
    const CameraBuffer frame = backend->RenderCamera(scene.camera, scene.camera.resolution);
    const auto [counted, same] = CompareShades(ShadeWarpedPixels(frame, lightSpace, withPhase),
                                               backend->ShadePixels(frame, lightSpace, shifted));
    EXPECT_GE(static_cast<double>(same), 0.9999 * static_cast<double>(counted));
}

TEST(RayCastMap, WarpedShadingOfALinearWarpIsShadePointBitForBit) {
    const Scene scene =
        cases::LoadSpatialScene(fs::path(LEXEL_CASES_DIR) / "spatial" / "courtyard.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Bounds bounds = scene.geometry.ComputeBounds();
    const CameraBuffer frame = backend->RenderCamera(scene.camera, {200, 200});
    for (const Light& light : scene.lights) {
        const LightSpace lightSpace(light, bounds);
        const Readback readback = RenderReadback(*backend, scene.camera, scene.readback);
        const BaselineContext context = MakeBaselineContext(
            scene, lightSpace, bounds, readback.wsRelevant, readback.wsRelevantHull);
        ShadowMap map =
            backend->RenderShadowMap(lightSpace, LispsmTightLightMatrix(context), scene.shadowMap);
        const std::vector<Shade> plain = backend->ShadePixels(frame, lightSpace, map);
        map.warp = MapWarp::Linear(map.matrix);
        EXPECT_EQ(ShadeWarpedPixels(frame, lightSpace, map), plain);
        EXPECT_EQ(backend->ShadePixels(frame, lightSpace, map), plain);
    }
}

TEST(RayCaster, IntersectBatchIsIntersectOfEachRay) {
    const Scene scene =
        cases::LoadSpatialScene(fs::path(LEXEL_CASES_DIR) / "spatial" / "meshes.json");
    const RayCaster caster(scene.geometry);
    const Bounds bounds = scene.geometry.ComputeBounds();
    std::vector<ShadowRay> rays;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> world;
    const glm::dvec3 c = bounds.Center();
    for (int i = 0; i < 1000; ++i) {
        const double a = 0.0061 * i, b = 0.37 * i;
        const glm::dvec3 origin =
            c + 2.0 * bounds.Radius() * glm::dvec3(std::cos(b), 0.8, std::sin(b));
        const glm::dvec3 target =
            c + 0.5 * bounds.Radius() * glm::dvec3(std::sin(a * 7), -0.3, std::cos(a * 5));
        const glm::dvec3 d = glm::normalize(target - origin);
        world.emplace_back(origin, d);
        rays.push_back(caster.ToShadowRay(origin, d, 0.0, std::numeric_limits<double>::infinity()));
    }
    std::vector<std::int32_t> hit(rays.size());
    caster.IntersectBatch(rays, hit);
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto h = caster.Intersect(world[i].first, world[i].second, 0.0,
                                        std::numeric_limits<double>::infinity());
        EXPECT_EQ(hit[i], h ? static_cast<std::int32_t>(h->triangle) : -1) << "ray " << i;
        hits += h.has_value();
    }
    EXPECT_GT(hits, 500);
    std::vector<std::int32_t> wrongSize(3);
    EXPECT_THROW(caster.IntersectBatch(rays, wrongSize), std::invalid_argument);
}

}  // namespace
}  // namespace lexel::spatial
