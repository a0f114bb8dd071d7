// Flatland solver throughput (issue targets: optimal-l1 and exact optimal-l2 ≥ 100 M samples/s
// on one core; they are moment sums), Newton (thesis Algorithm 1) time and its ratio to the
// exact solver in the same run, and the sampling pass in pixels/s. BM_RunMemory: the memory a
// `lexel run` of the single-plane case holds per camera pixel at 10⁶ pixels (the target: ≤ 64).
//
//   ./build/bench/flatland_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <numbers>
#include <random>

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/memory.h"
#include "lexel/flatland/methods.h"
#include "lexel/flatland/sampling.h"
#include "peak_rss.h"

namespace {

using namespace lexel;
using namespace lexel::flatland;

// 10⁶ synthetic samples: light angles over a 60° sweep, footprints spread over two decades.
LexelSamples SyntheticSamples(std::size_t n) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> angle(n), g(n);
    for (std::size_t i = 0; i < n; ++i) {
        angle[i] = (-30.0 + 60.0 * u(rng)) * std::numbers::pi / 180.0;
        g[i] = std::pow(10.0, 2.0 * u(rng)) * 100.0;
    }
    return MakeLexelSamples(angle, g, 0.0, 1000.0);
}

const LexelSamples& Samples() {
    static const LexelSamples samples = SyntheticSamples(1'000'000);
    return samples;
}

void BM_OptimalL1(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(SolveL1Exact(Samples()).t);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_OptimalL1)->Unit(benchmark::kMillisecond);

void BM_OptimalL2Exact(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(SolveL2Exact(Samples()).t);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_OptimalL2Exact)->Unit(benchmark::kMillisecond);

// The moment sums alone (what the solvers spend their time on).
void BM_L1Moments(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(ComputeL1Moments(Samples()).s2);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_L1Moments)->Unit(benchmark::kMillisecond);

void BM_L2Moments(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(ComputeL2Moments(Samples()).m[4]);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_L2Moments)->Unit(benchmark::kMillisecond);

void BM_OptimalL2Newton(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(SolveL2Newton(Samples()).t);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_OptimalL2Newton)->Unit(benchmark::kMillisecond);

// Newton / exact, timed back to back in one run so the ratio is not skewed by machine state.
void BM_NewtonOverExactRatio(benchmark::State& state) {
    double newtonSeconds = 0, exactSeconds = 0;
    for (auto _ : state) {
        auto t0 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(SolveL2Newton(Samples()).t);
        auto t1 = std::chrono::steady_clock::now();
        benchmark::DoNotOptimize(SolveL2Exact(Samples()).t);
        auto t2 = std::chrono::steady_clock::now();
        newtonSeconds += std::chrono::duration<double>(t1 - t0).count();
        exactSeconds += std::chrono::duration<double>(t2 - t1).count();
    }
    state.counters["newton_over_exact"] = newtonSeconds / exactSeconds;
}
BENCHMARK(BM_NewtonOverExactRatio)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_LinfExact(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(SolveLinfExact(Samples()).t);
    state.SetItemsProcessed(state.iterations() * Samples().size());
}
BENCHMARK(BM_LinfExact)->Unit(benchmark::kMillisecond);

// The sampling pass: the example floor and polyline at 10⁶ pixels.
void BM_SamplingPass(benchmark::State& state) {
    FlatScene scene;
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(1, -0.25).normalized();
    scene.camera.fovDeg = 60;
    scene.wsLight = {-3, 10};
    scene.geometry = {{{-50, 0}, {200, 0}}, {{6, 0}, {6, 2}, {8, 2.5}}};
    const int pixels = static_cast<int>(state.range(0));
    scene.camera.pixels = pixels;
    for (auto _ : state) benchmark::DoNotOptimize(RunSamplingPass(scene, pixels).samples.size());
    state.SetItemsProcessed(state.iterations() * pixels);
}
BENCHMARK(BM_SamplingPass)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

// Every method on cases/flatland/single_plane.json's scene at 10⁶ camera pixels (94% visible),
// the decision pass being the full one, as `lexel run` does. Counters: bytes_per_pixel, the peak
// RSS increase over the run per camera pixel; estimate_per_pixel, FlatlandRunBytes per pixel.
void BM_RunMemory(benchmark::State& state) {
    FlatScene scene;
    scene.name = "single_plane";
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(-1, -0.55).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = static_cast<int>(state.range(0));
    scene.camera.near = 0.1;
    scene.camera.far = 100;
    scene.wsLight = {-0.484, 10};
    scene.lexels = 1000;
    scene.geometry = {{{-60, 0}, {20, 0}}};
    double peak = 0.0;
    for (auto _ : state) {
        const double bytes = lexel::bench::PeakRssIncrease([&] {
            benchmark::DoNotOptimize(
                RunFlatlandCase(scene, FlatlandMethodNames(), Metric::kL1).methods.size());
        });
        peak = std::max(peak, bytes);
    }
    if (peak > 0) state.counters["bytes_per_pixel"] = peak / scene.camera.pixels;
    state.counters["estimate_per_pixel"] = FlatlandRunBytes(SizesOf(scene)) / scene.camera.pixels;
}
BENCHMARK(BM_RunMemory)->Arg(1'000'000)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
