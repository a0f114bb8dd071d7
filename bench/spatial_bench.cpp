// RayCaster throughput: shadow rays per second for a frame's worth of floor points towards one
// point light, as the ground-truth pass shoots them (one ray per camera pixel per light), batch
// (rtcOccluded16 packets over TBB chunks) against single rays (rtcOccluded1), plus the BVH build.
//
// Scene: 40 UV spheres (16 × 8 segments, 256 triangles each) standing on a 40 × 40 floor split
// into 70 × 70 quads: 20,040 triangles. Rays: 750² = 562,500 floor points on a regular grid,
// towards a light at distance 100 from the floor's centre, with the offsets recommended in
// ray_caster.h.
//
// The walkthrough benchmarks (BM_Walkthrough*) time the harness on the shipped
// cases/spatial/walkthrough.json (report §3's scene) at the report's 180² readback (the case ships
// 720² with a sample budget; BM_WalkthroughFineReadbackBudget times that), loaded once:
//   - the passes of report Algorithm 1 steps 1–2 and of the experiment, on all TBB workers:
//     camera pass at 750² (pixels/s), readback at 180² with its screen derivatives and its 3D
//     hull (pixels/s), the first light's shadow map at 400² through the focused matrix
//     (texels/s), and shading of the 750² frame against that map (pixels/s);
//   - BM_WalkthroughRelevantHull3D: the readback's per-frame 3D hull of the relevant points
//     alone (RelevantHullVertices: image pre-filter + Qhull), one core;
//   - the light matrix per light on ONE core (tbb::global_control, as the report's Table 3 is a
//     single-CPU profile), over the first kProfileLights lights of the case's light sweep with
//     their LightSamples precomputed: focused, optimal (Algorithm 1: 3 iterations × 9 angles,
//     per-light 2D hull of the frame's 3D hull vertices), optimal-refined, and optimal with
//     hullOnce = false (the naive reference that re-fits from every relevant point per
//     candidate). Counters are ms per light; hull3d_ms is the 3D hull per frame, and
//     ms_per_light_with_hull3d adds a quarter of it, the report's Table 3 having 4 lights;
//   - BM_WalkthroughProfile: all four in one run, light by light, so the ratios optimal/focused
//     and naive/optimal come from the same conditions, plus a Table 3-like split: readback_ms
//     (per frame, without its 3D hull), hull3d_ms (per frame) and hull3d_ms_per_light_of_4
//     (amortized over Table 3's 4 lights; timed once per 4 profiled lights), then per light
//     sampling ms (step 1: standard map + readback shading + samples), hull_ms (the 2D hull),
//     search_ms, refine_ms; optimal_with_hull3d_ms = optimal_ms + hull3d_ms_per_light_of_4;
//   - BM_WalkthroughFineReadbackBudget: `optimal` per light at a 720² readback, all samples and
//     with the sample budget (OptimizerOptions::maxSamples), against 180², in one run;
//   - BM_WalkthroughRunMemory: bytes per camera pixel that a run of the first light holds at
//     its peak (the flatland counterpart is flatland_bench's BM_RunMemory);
//   - BM_PlyHeader: the PLY reader's header at 25k to 200k properties, with its fitted
//     complexity (O(n); it was O(n^2): 200k properties took 67 s).
//
//   ./build/bench/spatial_bench --benchmark_counters_tabular=true
//   ./build/bench/spatial_bench --benchmark_filter=Walkthrough --benchmark_min_time=0.2
//   ./build/bench/spatial_bench --benchmark_filter=WalkthroughProfile
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/depth_buffer.h"
#include "lexel/spatial/harness/mesh_ply_reader.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/ray_caster.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/multi_start.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/samples.h"
#include "peak_rss.h"

namespace {

using namespace lexel::spatial;

constexpr double kFloorHalfSize = 20.0;  // world units
constexpr int kFloorQuads = 70;
constexpr int kSphereCount = 40;
constexpr int kSphereSlices = 16, kSphereStacks = 8;
constexpr int kFrameSide = 750;

TriangleMesh Floor() {
    TriangleMesh mesh;
    for (int j = 0; j <= kFloorQuads; ++j)
        for (int i = 0; i <= kFloorQuads; ++i)
            mesh.positions.push_back(
                {static_cast<float>(-kFloorHalfSize + 2 * kFloorHalfSize * i / kFloorQuads), 0.0f,
                 static_cast<float>(-kFloorHalfSize + 2 * kFloorHalfSize * j / kFloorQuads)});
    const unsigned row = kFloorQuads + 1;
    for (unsigned j = 0; j < kFloorQuads; ++j)
        for (unsigned i = 0; i < kFloorQuads; ++i) {
            const unsigned v = j * row + i;
            mesh.triangles.push_back({v, v + row, v + 1});
            mesh.triangles.push_back({v + 1, v + row, v + row + 1});
        }
    return mesh;
}

// slices × stacks quads, each split in two (the pole quads are degenerate on one side).
TriangleMesh UvSphere(const glm::vec3& wsCentre, float radius) {
    TriangleMesh mesh;
    for (int s = 0; s <= kSphereStacks; ++s) {
        const double polar = std::numbers::pi * s / kSphereStacks;
        for (int l = 0; l <= kSphereSlices; ++l) {
            const double azimuth = 2 * std::numbers::pi * l / kSphereSlices;
            const glm::dvec3 unit(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                  std::sin(polar) * std::sin(azimuth));
            mesh.positions.push_back(wsCentre + radius * glm::vec3(unit));
        }
    }
    const unsigned row = kSphereSlices + 1;
    for (unsigned s = 0; s < kSphereStacks; ++s)
        for (unsigned l = 0; l < kSphereSlices; ++l) {
            const unsigned v = s * row + l;
            mesh.triangles.push_back({v, v + 1, v + row});
            mesh.triangles.push_back({v + 1, v + row + 1, v + row});
        }
    return mesh;
}

TriangleMesh BenchScene() {
    TriangleMesh mesh = Floor();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<float> position(-18.0f, 18.0f), radius(0.5f, 2.0f);
    for (int i = 0; i < kSphereCount; ++i) {
        const float r = radius(rng);
        mesh.Append(UvSphere({position(rng), r, position(rng)}, r));
    }
    return mesh;
}

const TriangleMesh& Scene() {
    static const TriangleMesh mesh = BenchScene();
    return mesh;
}

const RayCaster& Caster() {
    static const RayCaster caster(Scene());
    return caster;
}

struct WorldRay {
    glm::dvec3 origin, direction;
    double tNear, tFar;
};

// One shadow ray per pixel of a 750² grid over the floor, towards the light, in world units.
const std::vector<WorldRay>& WorldRays() {
    static const std::vector<WorldRay> rays = [] {
        const double sceneRadius = Scene().ComputeBounds().Radius();
        const double originOffset = 1e-5 * sceneRadius;  // along the floor normal, world units
        const double tNear = 1e-4 * sceneRadius;         // along the unit direction, world units
        const glm::dvec3 wsLight = 100.0 * glm::normalize(glm::dvec3(0.3, 0.9, 0.3));
        std::vector<WorldRay> out;
        out.reserve(static_cast<std::size_t>(kFrameSide) * kFrameSide);
        for (int j = 0; j < kFrameSide; ++j)
            for (int i = 0; i < kFrameSide; ++i) {
                const glm::dvec3 wsPoint(
                    -kFloorHalfSize + 2 * kFloorHalfSize * (i + 0.5) / kFrameSide, 0.0,
                    -kFloorHalfSize + 2 * kFloorHalfSize * (j + 0.5) / kFrameSide);
                const glm::dvec3 wsOrigin = wsPoint + glm::dvec3(0.0, originOffset, 0.0);
                const glm::dvec3 toLight = wsLight - wsOrigin;
                const double distance = glm::length(toLight);
                out.push_back({wsOrigin, toLight / distance, tNear, distance - tNear});
            }
        return out;
    }();
    return rays;
}

// The same rays as the batch form takes them (in the caster's unit frame, float).
const std::vector<ShadowRay>& Rays() {
    static const std::vector<ShadowRay> rays = [] {
        std::vector<ShadowRay> out;
        for (const WorldRay& r : WorldRays())
            out.push_back(Caster().ToShadowRay(r.origin, r.direction, r.tNear, r.tFar));
        return out;
    }();
    return rays;
}

void BM_BuildBvh(benchmark::State& state) {
    for (auto _ : state) {
        RayCaster caster(Scene());
        benchmark::DoNotOptimize(caster.TriangleCount());
    }
    state.counters["triangles"] = static_cast<double>(Scene().triangles.size());
}
BENCHMARK(BM_BuildBvh)->Unit(benchmark::kMillisecond);

// Frame order; state.range(0) selects the traversal hint (0: coherent, 1: incoherent).
void BM_OccludedBatch(benchmark::State& state) {
    const RayCaster& caster = Caster();
    const std::vector<ShadowRay>& rays = Rays();
    std::vector<std::uint8_t> occluded(rays.size());
    const auto order = static_cast<RayCaster::RayOrder>(state.range(0));
    for (auto _ : state) {
        caster.OccludedBatch(rays, occluded, order);
        benchmark::DoNotOptimize(occluded.data());
    }
    std::size_t shadowed = 0;
    for (std::uint8_t o : occluded) shadowed += o;
    state.counters["shadowed_fraction"] = static_cast<double>(shadowed) / rays.size();
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedBatch)
    ->ArgName("incoherent_hint")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same rays in random order: packets of unrelated rays (the batch form's worst case), with
// either traversal hint.
void BM_OccludedBatchShuffled(benchmark::State& state) {
    const RayCaster& caster = Caster();
    std::vector<ShadowRay> rays = Rays();
    std::shuffle(rays.begin(), rays.end(), std::mt19937_64(5));
    std::vector<std::uint8_t> occluded(rays.size());
    const auto order = static_cast<RayCaster::RayOrder>(state.range(0));
    for (auto _ : state) {
        caster.OccludedBatch(rays, occluded, order);
        benchmark::DoNotOptimize(occluded.data());
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedBatchShuffled)
    ->ArgName("incoherent_hint")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// rtcOccluded1 from one thread.
void BM_OccludedSingleOneThread(benchmark::State& state) {
    const RayCaster& caster = Caster();
    const std::vector<WorldRay>& rays = WorldRays();
    for (auto _ : state) {
        std::size_t shadowed = 0;
        for (const WorldRay& r : rays)
            shadowed += caster.Occluded(r.origin, r.direction, r.tNear, r.tFar);
        benchmark::DoNotOptimize(shadowed);
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedSingleOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();

// rtcOccluded1 over all TBB workers: the fair comparison with the batch form.
void BM_OccludedSingleParallel(benchmark::State& state) {
    const RayCaster& caster = Caster();
    const std::vector<WorldRay>& rays = WorldRays();
    std::vector<std::uint8_t> occluded(rays.size());
    for (auto _ : state) {
        tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
            const WorldRay& r = rays[i];
            occluded[i] = caster.Occluded(r.origin, r.direction, r.tNear, r.tFar);
        });
        benchmark::DoNotOptimize(occluded.data());
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedSingleParallel)->Unit(benchmark::kMillisecond)->UseRealTime();

// ---------------------------------------------------------------------------------------------
// The shipped walkthrough case.

constexpr int kProfileLights = 16;  // the first lights of the case's light sweep
constexpr int kTable3Lights = 4;    // the report's Table 3 profiles a frame with 4 lights

struct PerLight {
    LightSpace lightSpace;
    LightMatrix focused;
    LightSamples samples;
};

struct Walkthrough {
    lexel::spatial::Scene scene;  // (Scene() above is the ray benchmarks' mesh)
    std::unique_ptr<RenderBackend> backend;
    Bounds bounds;
    CameraBuffer frame;  // scene.camera.resolution (750²)
    Readback readback;   // scene.readback
    std::vector<PerLight> lights;

    BaselineContext Context(const LightSpace& lightSpace) const {
        return MakeBaselineContext(scene, lightSpace, bounds, readback.wsRelevant,
                                   readback.wsRelevantHull);
    }
};

// The walkthrough with its readback at `readback`.
Walkthrough LoadWalkthrough(Resolution readback) {
    Walkthrough w;
    w.scene = lexel::cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
    w.scene.readback = readback;
    w.backend = MakeCpuRenderer(w.scene.geometry);
    w.bounds = w.scene.geometry.ComputeBounds();
    w.frame = w.backend->RenderCamera(w.scene.camera, w.scene.camera.resolution);
    w.readback = RenderReadback(*w.backend, w.scene.camera, w.scene.readback);
    // As Evaluator::Evaluate does (Algorithm 1 step 1): boundary samples from the focused map.
    for (const Light& light : lexel::cases::SweepLightsOf(w.scene, kProfileLights)) {
        const LightSpace lightSpace(light, w.bounds);
        const LightMatrix focused = FocusedLightMatrix(w.Context(lightSpace));
        const ShadowMap map = w.backend->RenderShadowMap(lightSpace, focused, w.scene.shadowMap);
        LightSamples samples = MakeLightSamples(
            w.readback, lightSpace, w.backend->ShadePixels(w.readback.buffer, lightSpace, map));
        w.lights.push_back({lightSpace, focused, std::move(samples)});
    }
    return w;
}

const Walkthrough& Case() {
    static const Walkthrough w = LoadWalkthrough(kReportReadback);
    return w;
}

// The case's first light (scene.lights[0]), its focused matrix and map.
struct FirstLight {
    LightSpace lightSpace;
    LightMatrix focused;
    ShadowMap map;
};

const FirstLight& First() {
    static const FirstLight f = [] {
        const Walkthrough& w = Case();
        const LightSpace lightSpace(w.scene.lights.at(0), w.bounds);
        const LightMatrix focused = FocusedLightMatrix(w.Context(lightSpace));
        return FirstLight{lightSpace, focused,
                          w.backend->RenderShadowMap(lightSpace, focused, w.scene.shadowMap)};
    }();
    return f;
}

double MsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// --- the passes (all TBB workers) ---

void BM_WalkthroughCameraPass(benchmark::State& state) {
    const Walkthrough& w = Case();
    const Resolution at = w.scene.camera.resolution;
    for (auto _ : state) {
        CameraBuffer buffer = w.backend->RenderCamera(w.scene.camera, at);
        benchmark::DoNotOptimize(buffer.triangle.data());
    }
    state.counters["side"] = at.width;
    state.SetItemsProcessed(state.iterations() * at.Count());
}
BENCHMARK(BM_WalkthroughCameraPass)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WalkthroughReadback(benchmark::State& state) {
    const Walkthrough& w = Case();
    const Resolution at = w.scene.readback;
    for (auto _ : state) {
        Readback r = RenderReadback(*w.backend, w.scene.camera, at);
        benchmark::DoNotOptimize(r.wsRelevant.data());
    }
    state.counters["side"] = at.width;
    state.counters["relevant"] = static_cast<double>(w.readback.wsRelevant.size());
    state.SetItemsProcessed(state.iterations() * at.Count());
}
BENCHMARK(BM_WalkthroughReadback)->Unit(benchmark::kMillisecond)->UseRealTime();

// A renderer's full-size depth buffer as the readback (depth_buffer.h): the walkthrough's camera
// at 1280×720, its float depth; arg 0 MakeReadback of all of it (every covered pixel a hull
// candidate), arg 1 after DownsampleDepth to kReadbackSide (160×90; the downsampling timed too).
void BM_ReadbackFromDepth(benchmark::State& state) {
    const Walkthrough& w = Case();
    Camera camera = w.scene.camera;
    camera.resolution = {1280, 720};
    const CameraBuffer pass = w.backend->RenderCamera(camera, camera.resolution);
    const std::vector<float> depth(pass.windowDepth.begin(), pass.windowDepth.end());
    const DepthBuffer buffer{.resolution = camera.resolution,
                             .depth = depth,
                             .clipFromWorld = camera.ClipFromView() * camera.ViewFromWorld(),
                             .convention = {}};
    const bool downsample = state.range(0) == 1;
    for (auto _ : state) {
        const Readback r =
            downsample ? MakeReadback(DownsampleDepth(buffer).View()) : MakeReadback(buffer);
        benchmark::DoNotOptimize(r.wsRelevantHull.data());
        state.counters["pixels"] = static_cast<double>(r.buffer.resolution.Count());
        state.counters["hull_ms"] = r.relevantHullMs;
    }
}
BENCHMARK(BM_ReadbackFromDepth)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WalkthroughShadowMapPass(benchmark::State& state) {
    const Walkthrough& w = Case();
    const FirstLight& f = First();
    const Resolution at = w.scene.shadowMap;
    for (auto _ : state) {
        ShadowMap map = w.backend->RenderShadowMap(f.lightSpace, f.focused, at);
        benchmark::DoNotOptimize(map.depth.data());
    }
    state.counters["side"] = at.width;
    state.SetItemsProcessed(state.iterations() * at.Count());
}
BENCHMARK(BM_WalkthroughShadowMapPass)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WalkthroughShadePass(benchmark::State& state) {
    const Walkthrough& w = Case();
    const FirstLight& f = First();
    for (auto _ : state) {
        std::vector<Shade> shades = w.backend->ShadePixels(w.frame, f.lightSpace, f.map);
        benchmark::DoNotOptimize(shades.data());
    }
    state.counters["side"] = w.frame.resolution.width;
    state.SetItemsProcessed(state.iterations() * w.frame.resolution.Count());
}
BENCHMARK(BM_WalkthroughShadePass)->Unit(benchmark::kMillisecond)->UseRealTime();

// The per-frame 3D hull alone (MakeReadback's share of Algorithm 1), one core.
void BM_WalkthroughRelevantHull3D(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    std::size_t vertices = 0;
    for (auto _ : state) {
        std::vector<glm::dvec3> hull = RelevantHullVertices(w.readback.buffer);
        vertices = hull.size();
        benchmark::DoNotOptimize(hull.data());
    }
    state.counters["relevant"] = static_cast<double>(w.readback.wsRelevant.size());
    state.counters["hull3d_vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_WalkthroughRelevantHull3D)->Unit(benchmark::kMillisecond)->UseRealTime();

enum Variant { kFocused = 0, kOptimal = 1, kRefined = 2, kNaive = 3 };

OptimizerOptions OptionsFor(int variant) {
    OptimizerOptions o;  // Algorithm 1: 3 iterations × 9 angles, hull once
    if (variant == kRefined) o.refine = true;
    if (variant == kNaive) o.hullOnce = false;
    return o;
}

// One iteration = one frame: the readback's 3D hull once (hull3d_ms, per frame), then every
// profiled light once; ms_per_light is the mean over lights without the 3D hull, and
// ms_per_light_with_hull3d adds a quarter of it (report Table 3: 4 lights share a frame).
void BM_WalkthroughLightMatrix(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    const int variant = static_cast<int>(state.range(0));
    const OptimizerOptions options = OptionsFor(variant);
    double wallMs = 0.0, hullMs = 0.0, searchMs = 0.0, refineMs = 0.0, hullVertices = 0.0;
    double hull3dMs = 0.0;
    for (auto _ : state) {
        if (variant != kFocused && options.hullOnce) {
            const auto hullStart = std::chrono::steady_clock::now();
            std::vector<glm::dvec3> vertices = RelevantHullVertices(w.readback.buffer);
            benchmark::DoNotOptimize(vertices.data());
            hull3dMs += MsSince(hullStart);
        }
        const auto start = std::chrono::steady_clock::now();
        for (const PerLight& l : w.lights) {
            if (variant == kFocused) {
                LightMatrix m = FocusedLightMatrix(w.Context(l.lightSpace));
                benchmark::DoNotOptimize(m);
            } else {
                OptimizerResult r =
                    OptimizeLightMatrix(l.samples, l.focused.p4, w.scene.shadowMap, options);
                hullMs += r.hullMs;
                searchMs += r.searchMs;
                refineMs += r.refineMs;
                hullVertices += static_cast<double>(r.hullVertices);
                benchmark::DoNotOptimize(r);
            }
        }
        wallMs += MsSince(start);
    }
    const double frames = static_cast<double>(state.iterations());
    const double calls = frames * w.lights.size();
    state.counters["lights"] = static_cast<double>(w.lights.size());
    state.counters["ms_per_light"] = wallMs / calls;  // wall clock
    if (variant != kFocused) {
        state.counters["hull3d_ms"] = hull3dMs / frames;
        state.counters["ms_per_light_with_hull3d"] =
            wallMs / calls + hull3dMs / frames / kTable3Lights;
        state.counters["hull_ms"] = hullMs / calls;
        state.counters["search_ms"] = searchMs / calls;
        state.counters["refine_ms"] = refineMs / calls;
        state.counters["hull_vertices"] = hullVertices / calls;
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(calls));
}
BENCHMARK(BM_WalkthroughLightMatrix)
    ->ArgName("focused0_optimal1_refined2_naive3")
    ->DenseRange(kFocused, kNaive)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The fair comparison's cost: per light, focused-tight alone against `optimal`, which
// builds every start (focused-tight, lispsm-tight, lispsm-engine, psm-tight, normal,
// plane-optimal) and runs Algorithm 1 from each, in one run and on one core; ratio = optimal /
// focused-tight.
void BM_WalkthroughMultiStart(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    double tightMs = 0.0, optimalMs = 0.0, startsMs = 0.0;
    for (auto _ : state) {
        for (const PerLight& l : w.lights) {
            BaselineContext context = w.Context(l.lightSpace);
            context.samples = &l.samples;
            auto start = std::chrono::steady_clock::now();
            LightMatrix tight = FocusedTightLightMatrix(context);
            benchmark::DoNotOptimize(tight);
            tightMs += MsSince(start);
            start = std::chrono::steady_clock::now();
            const std::vector<OptimizerStart> starts = StandardStarts(context);
            startsMs += MsSince(start);
            MultiStartResult r = OptimizeFromStarts(l.samples, starts, w.scene.shadowMap);
            benchmark::DoNotOptimize(r);
            optimalMs += MsSince(start);
        }
    }
    const double calls = static_cast<double>(state.iterations()) * w.lights.size();
    state.counters["focused_tight_ms_per_light"] = tightMs / calls;
    state.counters["optimal_ms_per_light"] = optimalMs / calls;
    state.counters["starts_ms_per_light"] = startsMs / calls;
    state.counters["ratio_optimal_to_focused_tight"] = optimalMs / tightMs;
}
BENCHMARK(BM_WalkthroughMultiStart)->Unit(benchmark::kMillisecond)->UseRealTime();

// `optimal` (on the edge energy with its prior, energy.h) against `optimal-h` (on h, the
// MultiStart benchmark's search) and against the same search on e₁ (exponent 1, the band
// unpowered), per light in one run on one core, from the same starts: ratio_e_to_h = optimal /
// optimal-h, ratio_e_to_e1 = optimal / e₁'s.
void BM_WalkthroughMultiStartEdge(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    const OptimizerOptions edge = EdgeOptimizerOptions();
    OptimizerOptions edge1 = edge;
    edge1.energy.exponent = 1.0;
    double reportMs = 0.0, edgeMs = 0.0, edge1Ms = 0.0;
    for (auto _ : state) {
        for (const PerLight& l : w.lights) {
            BaselineContext context = w.Context(l.lightSpace);
            context.samples = &l.samples;
            const std::vector<OptimizerStart> starts = StandardStarts(context);
            auto start = std::chrono::steady_clock::now();
            MultiStartResult h = OptimizeFromStarts(l.samples, starts, w.scene.shadowMap);
            benchmark::DoNotOptimize(h);
            reportMs += MsSince(start);
            start = std::chrono::steady_clock::now();
            MultiStartResult e = OptimizeFromStarts(l.samples, starts, w.scene.shadowMap, edge);
            benchmark::DoNotOptimize(e);
            edgeMs += MsSince(start);
            start = std::chrono::steady_clock::now();
            MultiStartResult e1 = OptimizeFromStarts(l.samples, starts, w.scene.shadowMap, edge1);
            benchmark::DoNotOptimize(e1);
            edge1Ms += MsSince(start);
        }
    }
    const double calls = static_cast<double>(state.iterations()) * w.lights.size();
    state.counters["optimal_search_ms_per_light"] = reportMs / calls;
    state.counters["optimal_e_search_ms_per_light"] = edgeMs / calls;
    state.counters["optimal_e1_search_ms_per_light"] = edge1Ms / calls;
    state.counters["ratio_e_to_h"] = edgeMs / reportMs;
    state.counters["ratio_e_to_e1"] = edgeMs / edge1Ms;
}
BENCHMARK(BM_WalkthroughMultiStartEdge)->Unit(benchmark::kMillisecond)->UseRealTime();

// `optimal` at a finer readback with the sample budget (OptimizerOptions::maxSamples),
// per light in one run on one core against `optimal` at the case's 180²: the same lights, the
// same starts' kinds, the boundary samples of a 720² readback (about one frame pixel per readback
// pixel, against 17 at 180²) all searched, or thinned to 1024 or 512. Counters: ms per light of
// each and ratio_* to 180²'s; samples_* the mean samples per light; hull3d_ms_* the readback's
// per-frame 3D hull at each size, which grows with the readback's pixels, not with the budget.
// And the cost rule (at most 2×): `optimal` as shipped (720², 512 samples, e) against `optimal` as
// it was before the edge energy (the multi-start on h at 180², today's `optimal-h`),
// ratio_shipped_to_h180, and the same with e's exponent 1 (e₁, the edge energy before the
// exponent), ratio_e1_to_h180.
void BM_WalkthroughFineReadbackBudget(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& coarse = Case();
    static const Walkthrough fine = LoadWalkthrough(Resolution{720, 720});
    OptimizerOptions options = EdgeOptimizerOptions();
    const auto msPerLight = [&](const Walkthrough& w, std::size_t budget) {
        options.maxSamples = budget;
        double ms = 0.0;
        for (const PerLight& l : w.lights) {
            BaselineContext context = w.Context(l.lightSpace);
            context.samples = &l.samples;
            const std::vector<OptimizerStart> starts = StandardStarts(context);
            const auto start = std::chrono::steady_clock::now();
            MultiStartResult r = OptimizeFromStarts(l.samples, starts, w.scene.shadowMap, options);
            benchmark::DoNotOptimize(r);
            ms += MsSince(start);
        }
        return ms / static_cast<double>(w.lights.size());
    };
    double coarseMs = 0.0, fineMs = 0.0, fine1024Ms = 0.0, fine512Ms = 0.0, h180Ms = 0.0;
    double e1Ms = 0.0;
    for (auto _ : state) {
        options = OptimizerOptions{};
        h180Ms += msPerLight(coarse, 0);
        options = EdgeOptimizerOptions();
        coarseMs += msPerLight(coarse, 0);
        fineMs += msPerLight(fine, 0);
        fine1024Ms += msPerLight(fine, 1024);
        fine512Ms += msPerLight(fine, 512);
        options.energy.exponent = 1.0;
        e1Ms += msPerLight(fine, 512);
    }
    const double n = static_cast<double>(state.iterations());
    state.counters["optimal_180_ms"] = coarseMs / n;
    state.counters["optimal_720_ms"] = fineMs / n;
    state.counters["optimal_720_budget1024_ms"] = fine1024Ms / n;
    state.counters["optimal_720_budget512_ms"] = fine512Ms / n;
    state.counters["ratio_720"] = fineMs / coarseMs;
    state.counters["ratio_720_budget1024"] = fine1024Ms / coarseMs;
    state.counters["ratio_720_budget512"] = fine512Ms / coarseMs;
    state.counters["optimal_h_180_ms"] = h180Ms / n;
    state.counters["ratio_shipped_to_h180"] = fine512Ms / h180Ms;
    state.counters["optimal_e1_720_budget512_ms"] = e1Ms / n;
    state.counters["ratio_e1_to_h180"] = e1Ms / h180Ms;
    const auto meanSamples = [](const Walkthrough& w) {
        double total = 0.0;
        for (const PerLight& l : w.lights) total += static_cast<double>(l.samples.lsX.size());
        return total / static_cast<double>(w.lights.size());
    };
    state.counters["samples_180"] = meanSamples(coarse);
    state.counters["samples_720"] = meanSamples(fine);
    state.counters["hull3d_ms_180"] = coarse.readback.relevantHullMs;
    state.counters["hull3d_ms_720"] = fine.readback.relevantHullMs;
}
BENCHMARK(BM_WalkthroughFineReadbackBudget)->Unit(benchmark::kMillisecond)->UseRealTime();

// The partitioned methods: per light, the cascades of one scheme at the default k = 4
// against `optimal` (every start, Algorithm 1 from each) in the same run on one core; ratio =
// scheme / optimal. Argument: the index into MethodNamesOf(MethodFamily::kPartitioned).
void BM_WalkthroughPartitioned(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    const std::string name =
        MethodNamesOf(MethodFamily::kPartitioned).at(static_cast<std::size_t>(state.range(0)));
    state.SetLabel(name);
    double optimalMs = 0.0, partitionedMs = 0.0;
    for (auto _ : state) {
        for (const PerLight& l : w.lights) {
            MethodContext context;
            context.baseline = w.Context(l.lightSpace);
            context.baseline.samples = &l.samples;
            context.samples = &l.samples;
            context.partitions = w.scene.partitions;
            auto start = std::chrono::steady_clock::now();
            MethodMatrix optimal = ComputeLightMatrix("optimal", context);
            benchmark::DoNotOptimize(optimal);
            optimalMs += MsSince(start);
            start = std::chrono::steady_clock::now();
            MethodMatrix partitioned = ComputeLightMatrix(name, context);
            benchmark::DoNotOptimize(partitioned);
            partitionedMs += MsSince(start);
        }
    }
    const double calls = static_cast<double>(state.iterations()) * w.lights.size();
    state.counters["optimal_ms_per_light"] = optimalMs / calls;
    state.counters["ms_per_light"] = partitionedMs / calls;
    state.counters["ratio_to_optimal"] = partitionedMs / optimalMs;
}
BENCHMARK(BM_WalkthroughPartitioned)
    ->DenseRange(0, 6)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// All four methods light by light in one run (ratios under the same conditions), plus the
// Table 3-like split on one core.
void BM_WalkthroughProfile(benchmark::State& state) {
    tbb::global_control oneCore(tbb::global_control::max_allowed_parallelism, 1);
    const Walkthrough& w = Case();
    double readbackMs = 0.0, hull3dMs = 0.0, samplingMs = 0.0, focusedMs = 0.0;
    double ms[4] = {0.0, 0.0, 0.0, 0.0};
    double hullMs = 0.0, searchMs = 0.0, refineMs = 0.0, naiveSearchMs = 0.0;
    double hullVertices = 0.0, samples = 0.0, boundaryPixels = 0.0, relevant = 0.0;
    double rejected = 0.0, tried = 0.0, hull3dVertices = 0.0, hull3dFrames = 0.0;
    for (auto _ : state) {
        auto start = std::chrono::steady_clock::now();
        Readback r = RenderReadback(*w.backend, w.scene.camera, w.scene.readback);
        benchmark::DoNotOptimize(r.wsRelevant.data());
        // MakeReadback includes the per-frame 3D hull; it is reported on its own, timed once
        // for every kTable3Lights profiled lights (the frames they would take at Table 3's 4
        // lights per frame).
        readbackMs += MsSince(start) - r.relevantHullMs;
        for (int frame = 0; frame < kProfileLights / kTable3Lights; ++frame) {
            start = std::chrono::steady_clock::now();
            std::vector<glm::dvec3> vertices = RelevantHullVertices(r.buffer);
            benchmark::DoNotOptimize(vertices.data());
            hull3dMs += MsSince(start);
            hull3dFrames += 1.0;
            hull3dVertices = static_cast<double>(vertices.size());
        }
        for (const PerLight& l : w.lights) {
            // Step 1: standard (focused) map, readback shading, boundary samples.
            start = std::chrono::steady_clock::now();
            const ShadowMap map =
                w.backend->RenderShadowMap(l.lightSpace, l.focused, w.scene.shadowMap);
            LightSamples s =
                MakeLightSamples(w.readback, l.lightSpace,
                                 w.backend->ShadePixels(w.readback.buffer, l.lightSpace, map));
            benchmark::DoNotOptimize(s.lsX.data());
            samplingMs += MsSince(start);

            start = std::chrono::steady_clock::now();
            LightMatrix focused = FocusedLightMatrix(w.Context(l.lightSpace));
            benchmark::DoNotOptimize(focused);
            focusedMs += MsSince(start);
            for (int variant : {kOptimal, kRefined, kNaive}) {
                start = std::chrono::steady_clock::now();
                OptimizerResult o = OptimizeLightMatrix(l.samples, l.focused.p4, w.scene.shadowMap,
                                                        OptionsFor(variant));
                ms[variant] += MsSince(start);
                benchmark::DoNotOptimize(o);
                if (variant == kOptimal) {
                    hullMs += o.hullMs;
                    searchMs += o.searchMs;
                    hullVertices += static_cast<double>(o.hullVertices);
                    tried += o.candidatesTried;
                    rejected += o.candidatesRejected;
                } else if (variant == kRefined) {
                    refineMs += o.refineMs;
                } else {
                    naiveSearchMs += o.searchMs;
                }
            }
            samples += static_cast<double>(l.samples.lsX.size());
            boundaryPixels += static_cast<double>(l.samples.boundaryPixels);
            relevant += static_cast<double>(l.samples.lsRelevant.size());
        }
    }
    ms[kFocused] = focusedMs;
    const double frames = static_cast<double>(state.iterations());
    const double calls = frames * w.lights.size();
    const double hull3dPerLight = hull3dMs / hull3dFrames / kTable3Lights;
    state.counters["readback_ms"] = readbackMs / frames;
    state.counters["hull3d_ms"] = hull3dMs / hull3dFrames;
    state.counters["hull3d_ms_per_light_of_4"] = hull3dPerLight;
    state.counters["hull3d_vertices"] = hull3dVertices;
    state.counters["sampling_ms"] = samplingMs / calls;
    state.counters["focused_ms"] = ms[kFocused] / calls;
    state.counters["optimal_ms"] = ms[kOptimal] / calls;
    state.counters["optimal_with_hull3d_ms"] = ms[kOptimal] / calls + hull3dPerLight;
    state.counters["refined_ms"] = ms[kRefined] / calls;
    state.counters["naive_ms"] = ms[kNaive] / calls;
    state.counters["optimal_over_focused"] = ms[kOptimal] / ms[kFocused];
    state.counters["optimal_with_hull3d_over_focused"] =
        (ms[kOptimal] / calls + hull3dPerLight) / (ms[kFocused] / calls);
    state.counters["refined_over_focused"] = ms[kRefined] / ms[kFocused];
    state.counters["naive_over_optimal"] = ms[kNaive] / ms[kOptimal];
    state.counters["hull_ms"] = hullMs / calls;
    state.counters["search_ms"] = searchMs / calls;
    state.counters["refine_ms"] = refineMs / calls;
    state.counters["naive_search_ms"] = naiveSearchMs / calls;
    state.counters["hull_vertices"] = hullVertices / calls;
    state.counters["boundary_samples"] = samples / calls;
    state.counters["boundary_pixels"] = boundaryPixels / calls;
    state.counters["relevant_points"] = relevant / calls;
    state.counters["candidates_tried"] = tried / calls;
    state.counters["candidates_rejected"] = rejected / calls;
}
BENCHMARK(BM_WalkthroughProfile)->Unit(benchmark::kMillisecond)->UseRealTime();

// Memory: a `lexel run` of walkthrough.json's first light (every method, the focused
// truth map, no camera path) on the CPU backend, at the case's camera resolution. Counter
// bytes_per_pixel: the peak RSS increase over the run per camera pixel (the 4000² truth map and
// the shadow maps are counted in it, since they are what a run at this resolution holds).
void BM_WalkthroughRunMemory(benchmark::State& state) {
    lexel::spatial::Scene scene =
        lexel::cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json");
    scene.lights.resize(1);
    scene.cameraPath.clear();
    lexel::cases::SpatialRunOptions options;
    options.methods = SpatialMethodNames();
    double peak = 0.0;
    for (auto _ : state) {
        const double bytes = lexel::bench::PeakRssIncrease([&] {
            benchmark::DoNotOptimize(lexel::cases::RunSpatialCase(scene, options).outcomes.size());
        });
        peak = std::max(peak, bytes);
    }
    const double pixels = static_cast<double>(scene.camera.resolution.Count());
    if (peak > 0) state.counters["bytes_per_pixel"] = peak / pixels;
    state.counters["camera_pixels"] = pixels;
}
BENCHMARK(BM_WalkthroughRunMemory)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// The PLY reader's header: a header of state.range(0) properties on one element, then a
// tetrahedron, read whole (ReadPlyEncoding reads the header alone). Complexity: O(n) (each
// property's name is checked against the element's earlier ones in a hash set).
void BM_PlyHeader(benchmark::State& state) {
    std::string text = "ply\nformat ascii 1.0\nelement extra 0\n";
    for (long long p = 0; p < state.range(0); ++p)
        text += "property float p" + std::to_string(p) + "\n";
    text +=
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face "
        "1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    for (auto _ : state) benchmark::DoNotOptimize(lexel::spatial::ReadPlyEncoding(text));
    state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_PlyHeader)
    ->RangeMultiplier(2)
    ->Range(25000, 200000)
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
