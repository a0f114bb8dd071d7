// RayCaster throughput: shadow rays per second for a frame's worth of floor points towards one
// point light, as the ground-truth pass shoots them (one ray per camera pixel per light), batch
// (rtcOccluded16 packets over TBB chunks) against single rays (rtcOccluded1), plus the BVH build.
//
// Scene: 40 UV spheres (16 × 8 segments, 256 triangles each) standing on a 40 × 40 floor split
// into 70 × 70 quads: 20,040 triangles. Rays: 750² = 562,500 floor points on a regular grid,
// towards a light at distance 100 from the floor's centre, with the offsets recommended in
// ray_caster.h.
//
//   ./build/bench/spatial_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "spatial/ray_caster.h"

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
        const double polar = M_PI * s / kSphereStacks;
        for (int l = 0; l <= kSphereSlices; ++l) {
            const double azimuth = 2 * M_PI * l / kSphereSlices;
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

// One shadow ray per pixel of a 750² grid over the floor, towards the light.
const std::vector<ShadowRay>& Rays() {
    static const std::vector<ShadowRay> rays = [] {
        const double sceneRadius = Scene().ComputeBounds().Radius();
        const double originOffset = 1e-5 * sceneRadius;  // along the floor normal, world units
        const double tNear = 1e-4 * sceneRadius;         // along the unit direction, world units
        const glm::dvec3 wsLight = 100.0 * glm::normalize(glm::dvec3(0.3, 0.9, 0.3));
        std::vector<ShadowRay> out;
        out.reserve(static_cast<std::size_t>(kFrameSide) * kFrameSide);
        for (int j = 0; j < kFrameSide; ++j)
            for (int i = 0; i < kFrameSide; ++i) {
                const glm::dvec3 wsPoint(
                    -kFloorHalfSize + 2 * kFloorHalfSize * (i + 0.5) / kFrameSide, 0.0,
                    -kFloorHalfSize + 2 * kFloorHalfSize * (j + 0.5) / kFrameSide);
                const glm::dvec3 wsOrigin = wsPoint + glm::dvec3(0.0, originOffset, 0.0);
                const glm::dvec3 toLight = wsLight - wsOrigin;
                const double distance = glm::length(toLight);
                out.push_back({glm::vec3(wsOrigin), glm::vec3(toLight / distance),
                               static_cast<float>(tNear), static_cast<float>(distance - tNear)});
            }
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
    const std::vector<ShadowRay>& rays = Rays();
    for (auto _ : state) {
        std::size_t shadowed = 0;
        for (const ShadowRay& r : rays)
            shadowed +=
                caster.Occluded(glm::dvec3(r.wsOrigin), glm::dvec3(r.wsDirection), r.tNear, r.tFar);
        benchmark::DoNotOptimize(shadowed);
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedSingleOneThread)->Unit(benchmark::kMillisecond)->UseRealTime();

// rtcOccluded1 over all TBB workers: the fair comparison with the batch form.
void BM_OccludedSingleParallel(benchmark::State& state) {
    const RayCaster& caster = Caster();
    const std::vector<ShadowRay>& rays = Rays();
    std::vector<std::uint8_t> occluded(rays.size());
    for (auto _ : state) {
        tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
            const ShadowRay& r = rays[i];
            occluded[i] =
                caster.Occluded(glm::dvec3(r.wsOrigin), glm::dvec3(r.wsDirection), r.tNear, r.tFar);
        });
        benchmark::DoNotOptimize(occluded.data());
    }
    state.SetItemsProcessed(state.iterations() * rays.size());
}
BENCHMARK(BM_OccludedSingleParallel)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
