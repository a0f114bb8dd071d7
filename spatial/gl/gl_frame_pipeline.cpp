#include "lexel/spatial/gl/gl_frame_pipeline.h"

#include <algorithm>
#include <optional>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/gl/gl_renderer.h"
#include "lexel/spatial/gl/visibility.h"
#include "lexel/spatial/optimizer.h"

namespace lexel::spatial::gl {

namespace {

// Map slots: the standard map of step 1, then the final map of each light and method (optimal's
// are kept for the next frame's step 1).
constexpr int kStandardMap = 0;
int FinalMap(std::size_t light, bool optimal) {
    return 1 + 2 * static_cast<int>(light) + (optimal ? 0 : 1);
}

class GlFramePipeline final : public FramePipeline {
  public:
    explicit GlFramePipeline(const TriangleMesh& geometry)
        : geometry_(geometry), bounds_(geometry.ComputeBounds()), renderer_(geometry_) {}

    FrameTimes RenderFrame(const Scene& scene, const Camera& camera, std::span<const Light> lights,
                           FrameMethod method, FrameOptions options) override {
        const CurrentContext current(renderer_.context());
        renderer_.SetPassTimer(!options.timePasses                   ? PassTimer::kOff
                               : renderer_.context().Info().software ? PassTimer::kFinish
                                                                     : PassTimer::kQueries);
        renderer_.TakeTimes();  // drop anything pending
        FrameTimes t;
        const Stopwatch frameTime;
        const bool optimal = method == FrameMethod::kOptimal;
        used_.clear();
        KeepState(lights, optimal);
        const bool anyUpdate =
            optimal &&
            (options.optimize || std::any_of(matrices_.begin(), matrices_.end(),
                                             [](const auto& m) { return !m.has_value(); }));
        if (anyUpdate) renderer_.RenderCamera(CameraSlot::kReadback, camera, scene.readback);
        renderer_.RenderCamera(CameraSlot::kFrame, camera, camera.resolution);
        std::optional<Readback> readback;
        if (anyUpdate) readback = ReadReadback(scene, camera, &t);

        for (std::size_t l = 0; l < lights.size(); ++l) {
            const LightSpace lightSpace(lights[l], bounds_);
            LightMatrix matrix;
            if (optimal && !options.optimize && matrices_[l]) {
                matrix = *matrices_[l];  // P kept between updates
            } else {
                const Stopwatch stage;
                matrix = FocusedLightMatrix(FrameBaselineContext(scene, camera, lightSpace, bounds_,
                                                                 readback ? &*readback : nullptr));
                t.hull += stage.Ms();
                if (optimal) {
                    const bool previous = !options.standardMap && matrices_[l].has_value();
                    matrix = Optimize(scene, camera, *readback, lightSpace, matrix,
                                      previous ? FinalMap(l, true) : -1, options.optimal, &t);
                }
            }
            renderer_.RenderShadowMap(FinalMap(l, optimal), lightSpace, matrix, scene.shadowMap);
            renderer_.ShadePass(CameraSlot::kFrame, FinalMap(l, optimal), lightSpace);
            used_.push_back(matrix);
            if (optimal) matrices_[l] = matrix;
        }
        glFinish();
        t.total = frameTime.Ms();
        const GpuTimes gpu = renderer_.TakeTimes();
        renderer_.SetPassTimer(PassTimer::kOff);
        t.cameraPass += gpu.cameraPass;
        t.shadowMap += gpu.shadowMap;
        t.shading += gpu.shading;
        t.extraction += gpu.extraction;
        return t;
    }

    const std::vector<LightMatrix>& Matrices() const override { return used_; }

    std::string PassClock() const override {
        return renderer_.context().Info().software
                   ? "GPU passes by glFinish-bracketed wall clock (a software renderer: its timer "
                     "queries miss the deferred rasterization), CPU stages by wall clock"
                   : "GPU passes by GL_TIME_ELAPSED queries, CPU stages by wall clock";
    }

  private:
    // Per-light state survives only while the optimal frames see the same lights.
    void KeepState(std::span<const Light> lights, bool optimal) {
        if (!optimal) return;
        if (lights.size() == lights_.size() &&
            std::equal(lights.begin(), lights.end(), lights_.begin(), SameLight))
            return;
        lights_.assign(lights.begin(), lights.end());
        matrices_.assign(lights.size(), std::nullopt);
    }

    // The readback's triangle ids to the CPU, its points in double, Appendix A, its 3D hull.
    Readback ReadReadback(const Scene& scene, const Camera& camera, FrameTimes* t) {
        glFinish();
        const Stopwatch stage;
        const std::vector<std::int32_t> ids = renderer_.ReadTriangles(CameraSlot::kReadback);
        Readback readback =
            MakeReadback(CameraBufferFromTriangles(geometry_, camera, scene.readback, ids),
                         camera.ScreenFromWorld(scene.readback));
        t->readback += stage.Ms() - readback.relevantHullMs;
        t->hull += readback.relevantHullMs;
        return readback;
    }

    // Algorithm 1 for one light: step 1 from map slot `previousMap` (the light's last final map)
    // or, when -1, a fresh standard map; readback shading and boundary pixels on the GPU; the
    // samples and the optimization on the CPU.
    LightMatrix Optimize(const Scene& scene, const Camera& camera, const Readback& readback,
                         const LightSpace& lightSpace, const LightMatrix& focused, int previousMap,
                         const std::string& method, FrameTimes* t) {
        int map = previousMap;
        if (map < 0) {
            renderer_.RenderShadowMap(kStandardMap, lightSpace, focused, scene.shadowMap);
            map = kStandardMap;
        }
        renderer_.ShadePass(CameraSlot::kReadback, map, lightSpace);
        renderer_.FindBoundary(CameraSlot::kReadback);
        glFinish();
        const Stopwatch stage;
        const LightSamples samples =
            LightSamplesAtPixels(readback, lightSpace, renderer_.ReadBoundary());
        t->extraction += stage.Ms();
        return TimedOptimizer(method,
                              FrameBaselineContext(scene, camera, lightSpace, bounds_, &readback),
                              samples, t);
    }

    TriangleMesh geometry_;
    Bounds bounds_;
    GlRenderer renderer_;
    std::vector<Light> lights_;  // of the last optimal frame
    std::vector<std::optional<LightMatrix>> matrices_;
    std::vector<LightMatrix> used_;  // by the last frame
};

}  // namespace

std::unique_ptr<FramePipeline> MakeGlFramePipeline(const TriangleMesh& geometry) {
    return std::make_unique<GlFramePipeline>(geometry);
}

}  // namespace lexel::spatial::gl
