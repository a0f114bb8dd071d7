// The frame of frame_pipeline.h over the RenderBackend interface, every stage timed by wall clock.
#include "lexel/spatial/harness/frame_pipeline.h"

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/optimizer.h"

namespace lexel::spatial {

bool SameLight(const Light& a, const Light& b) {
    return a.type == b.type && a.position == b.position && a.direction == b.direction;
}

BaselineContext FrameBaselineContext(const Scene& scene, const Camera& camera,
                                     const LightSpace& lightSpace, const Bounds& wsBounds,
                                     const Readback* readback) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = camera;
    context.map = scene.shadowMap;
    context.wsBounds = wsBounds;
    if (readback) {
        context.wsRelevant = readback->wsRelevant;
        context.wsRelevantHull = readback->wsRelevantHull;
    }
    context.floorPlane = scene.floorPlane;
    return context;
}

bool IsFrameOptimizer(std::string_view method) {
    return method == "optimal-report" || method == "optimal" || method == "optimal-refined" ||
           method == "optimal-shear";
}

LightMatrix TimedOptimizer(const std::string& method, BaselineContext context,
                           const LightSamples& samples, FrameTimes* t) {
    if (!IsFrameOptimizer(method))
        throw std::invalid_argument("frame pipeline: '" + method + "' is not an optimizer");
    context.samples = &samples;
    MethodContext methodContext;
    methodContext.baseline = context;
    methodContext.samples = &samples;
    const Stopwatch clock;
    const MethodMatrix m = ComputeLightMatrix(method, methodContext);
    const double ms = clock.Ms();
    const double hullMs = m.optimizer ? m.optimizer->hullMs : 0.0;
    t->hull += hullMs;
    t->search += ms - hullMs;
    return m.matrix;
}

namespace {

class BackendFramePipeline final : public FramePipeline {
  public:
    BackendFramePipeline(const RenderBackend& backend, const TriangleMesh& geometry,
                         std::unique_ptr<RenderBackend> owned = nullptr)
        : owned_(std::move(owned)), backend_(backend), bounds_(geometry.ComputeBounds()) {}

    FrameTimes RenderFrame(const Scene& scene, const Camera& camera, std::span<const Light> lights,
                           FrameMethod method, FrameOptions options) override {
        FrameTimes t;
        const Stopwatch frameTime;
        const bool optimal = method == FrameMethod::kOptimal;
        used_.clear();
        KeepState(lights, optimal);
        const bool anyUpdate = optimal && (options.optimize || matrices_.empty() ||
                                           std::any_of(matrices_.begin(), matrices_.end(),
                                                       [](const auto& m) { return !m; }));
        std::optional<Readback> readback;
        if (anyUpdate) readback = RenderReadback(scene, camera, &t);
        Stopwatch pass;
        const CameraBuffer frame = backend_.RenderCamera(camera, camera.resolution);
        t.cameraPass += pass.Ms();

        for (std::size_t l = 0; l < lights.size(); ++l) {
            const LightSpace lightSpace(lights[l], bounds_);
            LightMatrix matrix;
            if (optimal && !options.optimize && matrices_[l]) {
                matrix = *matrices_[l];  // P kept between updates
            } else {
                pass.Restart();
                matrix = FocusedLightMatrix(FrameBaselineContext(scene, camera, lightSpace, bounds_,
                                                                 readback ? &*readback : nullptr));
                t.hull += pass.Ms();
                if (optimal)
                    matrix = Optimize(scene, camera, *readback, lightSpace, matrix,
                                      options.standardMap || !maps_[l] ? nullptr : &*maps_[l],
                                      options.optimal, &t);
            }
            pass.Restart();
            ShadowMap map = backend_.RenderShadowMap(lightSpace, matrix, scene.shadowMap);
            t.shadowMap += pass.Ms();
            pass.Restart();
            backend_.ShadePixels(frame, lightSpace, map);
            t.shading += pass.Ms();
            used_.push_back(matrix);
            if (optimal) {
                matrices_[l] = matrix;
                maps_[l] = std::move(map);
            }
        }
        t.total = frameTime.Ms();
        return t;
    }

    const std::vector<LightMatrix>& Matrices() const override { return used_; }

    std::string PassClock() const override {
        return "wall clock per pass (" + std::string(backend_.Name()) + " backend)";
    }

  private:
    // Per-light state survives only while the optimal frames see the same lights.
    void KeepState(std::span<const Light> lights, bool optimal) {
        if (!optimal) return;
        const bool same = lights.size() == lights_.size() &&
                          std::equal(lights.begin(), lights.end(), lights_.begin(), SameLight);
        if (same) return;
        lights_.assign(lights.begin(), lights.end());
        matrices_.assign(lights.size(), std::nullopt);
        maps_.assign(lights.size(), std::nullopt);
    }

    Readback RenderReadback(const Scene& scene, const Camera& camera, FrameTimes* t) const {
        Stopwatch pass;
        CameraBuffer buffer = backend_.RenderCamera(camera, scene.readback);
        t->cameraPass += pass.Ms();
        pass.Restart();
        Readback readback = MakeReadback(std::move(buffer), camera.ScreenFromWorld(scene.readback));
        t->readback += pass.Ms() - readback.relevantHullMs;
        t->hull += readback.relevantHullMs;
        return readback;
    }

    // Algorithm 1 for one light, step 1 from `previousMap` or (null) a fresh standard map.
    LightMatrix Optimize(const Scene& scene, const Camera& camera, const Readback& readback,
                         const LightSpace& lightSpace, const LightMatrix& focused,
                         const ShadowMap* previousMap, const std::string& method,
                         FrameTimes* t) const {
        Stopwatch pass;
        std::optional<ShadowMap> standard;
        if (!previousMap) {
            standard = backend_.RenderShadowMap(lightSpace, focused, scene.shadowMap);
            t->shadowMap += pass.Ms();
        }
        pass.Restart();
        const LightSamples samples =
            backend_.BoundarySamples(readback, lightSpace, previousMap ? *previousMap : *standard);
        t->extraction += pass.Ms();
        return TimedOptimizer(method,
                              FrameBaselineContext(scene, camera, lightSpace, bounds_, &readback),
                              samples, t);
    }

    std::unique_ptr<RenderBackend> owned_;
    const RenderBackend& backend_;
    Bounds bounds_;
    std::vector<Light> lights_;  // of the last optimal frame
    std::vector<std::optional<LightMatrix>> matrices_;
    std::vector<LightMatrix> used_;  // by the last frame
    std::vector<std::optional<ShadowMap>> maps_;
};

}  // namespace

std::unique_ptr<FramePipeline> MakeBackendFramePipeline(const RenderBackend& backend,
                                                        const TriangleMesh& geometry) {
    return std::make_unique<BackendFramePipeline>(backend, geometry);
}

std::unique_ptr<FramePipeline> MakeCpuFramePipeline(const TriangleMesh& geometry) {
    std::unique_ptr<RenderBackend> cpu = MakeCpuRenderer(geometry);
    const RenderBackend& ref = *cpu;
    return std::make_unique<BackendFramePipeline>(ref, geometry, std::move(cpu));
}

}  // namespace lexel::spatial
