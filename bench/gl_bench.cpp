// The CPU reference and the OpenGL backend side by side on the shipped walkthrough (report §3's
// scene: 17,244 triangles, 750² frame, 400² maps) at the report's 180² readback, in one run:
//   - BM_Pass/<pass>/<backend>: the passes in pixels (texels) per second — the 750² camera pass,
//     the 180² readback (camera pass, transfer to the CPU, Appendix A derivatives and 3D hull),
//     a 400² shadow map through the focused matrix, and the 750² shading against it. GL passes
//     run on resident buffers (GlRenderer) and are timed to glFinish;
//   - BM_Step1/<backend>: Algorithm 1's step 1 per light — the standard (focused) map, the
//     readback's shading under it, the boundary samples on the CPU — over the 4 lights of
//     `lexel timing` (the case's two fixed lights, then its sweep's);
//   - BM_FrameRatio/<backend>/<schedule>: focused and optimal frames of FramePipeline for those 4
//     lights, alternating over 6 frames per iteration, the GPU passes untimed (their glFinish on
//     llvmpipe would serialize the frame); counters focused_ms, optimal_ms and ratio
//     (the report: 56.0 / 41.4 = 1.35). schedule 0: Algorithm 1 in full every frame; 1: the
//     report's (§2.4: P every 3rd frame, step 1 from a standard map every 2nd update).
// On a machine without a GPU the GL backend is Mesa's llvmpipe, a CPU rasterizer: its figures
// are llvmpipe's, not a GPU's. Without a context the GL benchmarks report an error and skip.
//
//   ./build/bench/gl_bench --benchmark_counters_tabular=true
//   ./build/bench/gl_bench --benchmark_filter=FrameRatio --benchmark_min_time=2
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <memory>
#include <optional>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/studies/timing/timing_study.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/gl/gl_frame_pipeline.h"
#include "lexel/spatial/gl/gl_renderer.h"
#include "lexel/spatial/gl/visibility.h"
#include "lexel/spatial/harness/frame_pipeline.h"
#include "lexel/spatial/harness/methods.h"

namespace {

using namespace lexel::spatial;

enum Backend { kCpu = 0, kGl = 1 };
enum Pass { kCamera = 0, kReadbackPass = 1, kShadow = 2, kShading = 3 };
constexpr int kLights = 4;

struct Walkthrough {
    Scene scene;
    Bounds bounds;
    std::unique_ptr<RenderBackend> cpu;
    CameraBuffer frame;
    Readback readback;
    std::vector<Light> lights;
    std::vector<LightSpace> lightSpaces;
    std::vector<LightMatrix> focused;
};

const Walkthrough& Case() {
    static const Walkthrough w = [] {
        Walkthrough w;
        w.scene = WithReportReadback(
            lexel::cases::LoadSpatialScene(LEXEL_CASES_DIR "/spatial/walkthrough.json"));
        w.bounds = w.scene.geometry.ComputeBounds();
        w.cpu = MakeCpuRenderer(w.scene.geometry);
        w.frame = w.cpu->RenderCamera(w.scene.camera, w.scene.camera.resolution);
        w.readback = RenderReadback(*w.cpu, w.scene.camera, w.scene.readback);
        w.lights = lexel::cases::TimingLightsOf(w.scene, kLights);
        for (const Light& light : w.lights) w.lightSpaces.emplace_back(light, w.bounds);
        for (const LightSpace& ls : w.lightSpaces)
            w.focused.push_back(FocusedLightMatrix(
                MakeBaselineContext(w.scene, ls, w.bounds, w.readback.wsRelevant)));
        return w;
    }();
    return w;
}

// The GL renderer of the case, or null (with the reason) when there is no context.
gl::GlRenderer* Gl(benchmark::State& state) {
    static std::string failure;
    static std::unique_ptr<gl::GlRenderer> renderer = []() -> std::unique_ptr<gl::GlRenderer> {
        try {
            return std::make_unique<gl::GlRenderer>(Case().scene.geometry);
        } catch (const gl::GlUnavailable& e) {
            failure = e.what();
            return nullptr;
        }
    }();
    if (!renderer) state.SkipWithError(failure.c_str());
    return renderer.get();
}

Resolution PassResolution(const Walkthrough& w, int pass) {
    if (pass == kReadbackPass) return w.scene.readback;
    if (pass == kShadow) return w.scene.shadowMap;
    return w.scene.camera.resolution;
}

void CpuPass(const Walkthrough& w, int pass) {
    const ShadowMap* map = nullptr;
    static std::optional<ShadowMap> firstMap;
    if (!firstMap)
        firstMap = w.cpu->RenderShadowMap(w.lightSpaces[0], w.focused[0], w.scene.shadowMap);
    map = &*firstMap;
    switch (pass) {
        case kCamera:
            benchmark::DoNotOptimize(
                w.cpu->RenderCamera(w.scene.camera, w.scene.camera.resolution));
            break;
        case kReadbackPass:
            benchmark::DoNotOptimize(RenderReadback(*w.cpu, w.scene.camera, w.scene.readback));
            break;
        case kShadow:
            benchmark::DoNotOptimize(
                w.cpu->RenderShadowMap(w.lightSpaces[0], w.focused[0], w.scene.shadowMap));
            break;
        case kShading:
            benchmark::DoNotOptimize(w.cpu->ShadePixels(w.frame, w.lightSpaces[0], *map));
            break;
    }
}

void GlPass(const Walkthrough& w, gl::GlRenderer& r, int pass) {
    switch (pass) {
        case kCamera:
            r.RenderCamera(gl::CameraSlot::kFrame, w.scene.camera, w.scene.camera.resolution);
            break;
        case kReadbackPass: {
            r.RenderCamera(gl::CameraSlot::kReadback, w.scene.camera, w.scene.readback);
            const std::vector<std::int32_t> ids = r.ReadTriangles(gl::CameraSlot::kReadback);
            benchmark::DoNotOptimize(
                MakeReadback(gl::CameraBufferFromTriangles(w.scene.geometry, w.scene.camera,
                                                           w.scene.readback, ids),
                             w.scene.camera.ScreenFromWorld(w.scene.readback)));
            break;
        }
        case kShadow:
            r.RenderShadowMap(0, w.lightSpaces[0], w.focused[0], w.scene.shadowMap);
            break;
        case kShading:
            r.ShadePass(gl::CameraSlot::kFrame, 0, w.lightSpaces[0]);
            break;
    }
    glFinish();
}

void BM_Pass(benchmark::State& state) {
    const Walkthrough& w = Case();
    const int pass = static_cast<int>(state.range(0));
    const auto backend = static_cast<Backend>(state.range(1));
    gl::GlRenderer* r = backend == kGl ? Gl(state) : nullptr;
    if (backend == kGl && !r) return;
    std::optional<gl::CurrentContext> current;
    if (r) {
        current.emplace(r->context());
        // The shading pass reads the frame's G-buffer and the first light's map.
        r->RenderCamera(gl::CameraSlot::kFrame, w.scene.camera, w.scene.camera.resolution);
        r->RenderShadowMap(0, w.lightSpaces[0], w.focused[0], w.scene.shadowMap);
        GlPass(w, *r, pass);  // warm-up: shader compilation
    }
    for (auto _ : state) {
        if (r)
            GlPass(w, *r, pass);
        else
            CpuPass(w, pass);
    }
    const Resolution at = PassResolution(w, pass);
    state.counters["side"] = at.width;
    state.counters["pixels_per_s"] = benchmark::Counter(
        static_cast<double>(state.iterations() * at.Count()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Pass)
    ->ArgNames({"pass", "gl"})
    ->ArgsProduct({{kCamera, kReadbackPass, kShadow, kShading}, {kCpu, kGl}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Step 1 for every light of the frame; ms_per_light is the wall time per light.
void BM_Step1(benchmark::State& state) {
    const Walkthrough& w = Case();
    const auto backend = static_cast<Backend>(state.range(0));
    gl::GlRenderer* r = backend == kGl ? Gl(state) : nullptr;
    if (backend == kGl && !r) return;
    std::optional<gl::CurrentContext> current;
    if (r) {
        current.emplace(r->context());
        r->RenderCamera(gl::CameraSlot::kReadback, w.scene.camera, w.scene.readback);
    }
    std::size_t samples = 0;
    double wallMs = 0.0;
    for (auto _ : state) {
        const lexel::Stopwatch clock;
        for (std::size_t l = 0; l < w.lights.size(); ++l) {
            const LightSpace& ls = w.lightSpaces[l];
            LightSamples s;
            if (r) {
                r->RenderShadowMap(0, ls, w.focused[l], w.scene.shadowMap);
                r->ShadePass(gl::CameraSlot::kReadback, 0, ls);
                s = LightSamplesAtPixels(w.readback, ls,
                                         r->BoundaryPixels(gl::CameraSlot::kReadback));
            } else {
                const ShadowMap map = w.cpu->RenderShadowMap(ls, w.focused[l], w.scene.shadowMap);
                s = w.cpu->BoundarySamples(w.readback, ls, map);
            }
            samples = s.lsX.size();
            benchmark::DoNotOptimize(s);
        }
        wallMs += clock.Ms();
    }
    state.counters["ms_per_light"] =
        wallMs / static_cast<double>(state.iterations() * w.lights.size());
    state.counters["last_samples"] = static_cast<double>(samples);
}
BENCHMARK(BM_Step1)
    ->ArgName("gl")
    ->Arg(kCpu)
    ->Arg(kGl)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FrameRatio(benchmark::State& state) {
    const Walkthrough& w = Case();
    const auto backend = static_cast<Backend>(state.range(0));
    const bool reportSchedule = state.range(1) == 1;
    std::unique_ptr<FramePipeline> pipeline;
    if (backend == kGl) {
        if (!Gl(state)) return;
        pipeline = gl::MakeGlFramePipeline(w.scene.geometry);
    } else {
        pipeline = MakeCpuFramePipeline(w.scene.geometry);
    }
    lexel::cases::TimingOptions options;
    if (reportSchedule) {
        options.updateEvery = 3;
        options.standardEvery = 2;
    }
    const auto poses = w.scene.cameraPath;
    pipeline->RenderFrame(w.scene, poses[0], w.lights, FrameMethod::kFocused);  // warm-up
    pipeline->RenderFrame(w.scene, poses[0], w.lights, FrameMethod::kOptimal);
    // The GPU passes untimed: a software renderer's per-pass glFinish would serialize the frame.
    FrameOptions focusedOptions;
    focusedOptions.timePasses = false;
    double focusedMs = 0.0, optimalMs = 0.0;
    int frames = 0;
    for (auto _ : state) {
        for (int k = 0; k < 6; ++k, ++frames) {
            const Camera& camera = poses[static_cast<std::size_t>(frames) % poses.size()];
            FrameOptions optimalOptions = lexel::cases::ScheduleOf(options, k);
            optimalOptions.timePasses = false;
            focusedMs +=
                pipeline
                    ->RenderFrame(w.scene, camera, w.lights, FrameMethod::kFocused, focusedOptions)
                    .total;
            optimalMs +=
                pipeline
                    ->RenderFrame(w.scene, camera, w.lights, FrameMethod::kOptimal, optimalOptions)
                    .total;
        }
    }
    state.counters["focused_ms"] = focusedMs / frames;
    state.counters["optimal_ms"] = optimalMs / frames;
    state.counters["ratio"] = optimalMs / focusedMs;
}
BENCHMARK(BM_FrameRatio)
    ->ArgNames({"gl", "report_schedule"})
    ->ArgsProduct({{kCpu, kGl}, {0, 1}})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
