// The frame of frame_pipeline.h over the RenderBackend interface: the passes of the one schedule
// (frame_schedule.h) as backend calls, every pass timed by wall clock.
#include "lexel/spatial/harness/frame_pipeline.h"

#include <optional>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/harness/frame_schedule.h"

namespace lexel::spatial {

namespace {

class BackendFramePipeline final : public FramePipeline, private FramePasses {
  public:
    BackendFramePipeline(const RenderBackend& backend, const TriangleMesh& geometry,
                         std::unique_ptr<RenderBackend> owned = nullptr)
        : owned_(std::move(owned)), backend_(backend), schedule_(geometry.ComputeBounds()) {}

    FrameTimes RenderFrame(const Scene& scene, const Camera& camera, std::span<const Light> lights,
                           FrameMethod method, FrameOptions options) override {
        if (kept_.size() > lights.size()) kept_.resize(lights.size());
        FrameTimes t;
        const Stopwatch frameTime;
        schedule_.Run(scene, camera, lights, method, options, *this, &t);
        t.total = frameTime.Ms();
        // Only the kept maps outlive the frame.
        readbackBuffer_.reset();
        standard_.reset();
        frame_ = CameraBuffer{};
        unkept_ = ShadowMap{};
        return t;
    }

    const std::vector<LightMatrix>& Matrices() const override { return schedule_.Matrices(); }

    std::string PassClock() const override {
        return "wall clock per pass (" + std::string(backend_.Name()) + " backend)";
    }

  private:
    void RenderReadbackCamera(const Camera& camera, Resolution resolution, FrameTimes* t) override {
        const Stopwatch pass;
        readbackBuffer_ = backend_.RenderCamera(camera, resolution);
        t->cameraPass += pass.Ms();
    }

    void RenderFrameCamera(const Camera& camera, FrameTimes* t) override {
        const Stopwatch pass;
        frame_ = backend_.RenderCamera(camera, camera.resolution);
        t->cameraPass += pass.Ms();
    }

    Readback ReadReadback(const Camera& camera, Resolution resolution, FrameTimes* t) override {
        const Stopwatch pass;
        Readback readback =
            MakeReadback(std::move(*readbackBuffer_), camera.ScreenFromWorld(resolution));
        readbackBuffer_.reset();
        t->readback += pass.Ms();
        return readback;
    }

    void RenderStandardMap(const LightSpace& lightSpace, const LightMatrix& focused,
                           Resolution resolution, FrameTimes* t) override {
        const Stopwatch pass;
        standard_ = backend_.RenderShadowMap(lightSpace, focused, resolution);
        t->shadowMap += pass.Ms();
    }

    LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                 std::size_t light, bool fromKept, FrameTimes* t) override {
        const Stopwatch pass;
        LightSamples samples =
            backend_.BoundarySamples(readback, lightSpace, fromKept ? kept_[light] : *standard_);
        t->extraction += pass.Ms();
        return samples;
    }

    void RenderFinalMap(std::size_t light, const LightSpace& lightSpace, const LightMatrix& matrix,
                        Resolution resolution, bool keep, FrameTimes* t) override {
        if (keep && kept_.size() <= light) kept_.resize(light + 1);
        ShadowMap& slot = keep ? kept_[light] : unkept_;
        const Stopwatch pass;
        slot = backend_.RenderShadowMap(lightSpace, matrix, resolution);
        t->shadowMap += pass.Ms();
        final_ = &slot;
    }

    void ShadeFrame(const LightSpace& lightSpace, FrameTimes* t) override {
        const Stopwatch pass;
        backend_.ShadePixels(frame_, lightSpace, *final_);
        t->shading += pass.Ms();
    }

    std::unique_ptr<RenderBackend> owned_;
    const RenderBackend& backend_;
    FrameSchedule schedule_;
    // The frame's buffers: the passes' inputs and outputs between the schedule's calls.
    std::optional<CameraBuffer> readbackBuffer_;
    CameraBuffer frame_;
    std::optional<ShadowMap> standard_;
    std::vector<ShadowMap> kept_;  // per light, its last kept final map (the schedule's state)
    ShadowMap unkept_;             // a focused frame's final map
    const ShadowMap* final_ = nullptr;
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
