// The frame of gl_frame_pipeline.h: the passes of the one schedule (frame_schedule.h) on the GPU,
// with only the readback's triangle ids and each light's boundary pixels read back to the CPU.
#include "lexel/spatial/gl/gl_frame_pipeline.h"

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/gl/gl_renderer.h"
#include "lexel/spatial/gl/visibility.h"
#include "lexel/spatial/harness/frame_schedule.h"

namespace lexel::spatial::gl {

namespace {

// Map slots: the standard map of step 1, then per light its kept final map (optimal frames: the
// next frame's step 1 from the previous map) and its unkept one (focused frames).
constexpr int kStandardMap = 0;
int FinalMap(std::size_t light, bool keep) {
    return 1 + 2 * static_cast<int>(light) + (keep ? 0 : 1);
}

class GlFramePipeline final : public FramePipeline, private FramePasses {
  public:
    explicit GlFramePipeline(const TriangleMesh& geometry)
        : geometry_(geometry), renderer_(geometry_), schedule_(geometry.ComputeBounds()) {}

    FrameTimes RenderFrame(const Scene& scene, const Camera& camera, std::span<const Light> lights,
                           FrameMethod method, FrameOptions options) override {
        const CurrentContext current(renderer_.context());
        renderer_.SetPassTimer(!options.timePasses                   ? PassTimer::kOff
                               : renderer_.context().Info().software ? PassTimer::kFinish
                                                                     : PassTimer::kQueries);
        renderer_.TakeTimes();  // drop anything pending
        FrameTimes t;
        const Stopwatch frameTime;
        schedule_.Run(scene, camera, lights, method, options, *this, &t);
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

    const std::vector<LightMatrix>& Matrices() const override { return schedule_.Matrices(); }

    std::string PassClock() const override {
        return renderer_.context().Info().software
                   ? "GPU passes by glFinish-bracketed wall clock (a software renderer: its timer "
                     "queries miss the deferred rasterization), CPU stages by wall clock"
                   : "GPU passes by GL_TIME_ELAPSED queries, CPU stages by wall clock";
    }

  private:
    // The GPU passes are timed by the renderer (RenderFrame adds them); what comes back to the
    // CPU is timed here, after glFinish, so that it is the copy and the CPU work, not the wait.
    void RenderReadbackCamera(const Camera& camera, Resolution resolution, FrameTimes*) override {
        renderer_.RenderCamera(CameraSlot::kReadback, camera, resolution);
    }

    void RenderFrameCamera(const Camera& camera, FrameTimes*) override {
        renderer_.RenderCamera(CameraSlot::kFrame, camera, camera.resolution);
    }

    // The readback's triangle ids to the CPU, its points in double, Appendix A, its 3D hull.
    Readback ReadReadback(const Camera& camera, Resolution resolution, FrameTimes* t) override {
        glFinish();
        const Stopwatch stage;
        const std::vector<std::int32_t> ids = renderer_.ReadTriangles(CameraSlot::kReadback);
        Readback readback =
            MakeReadback(CameraBufferFromTriangles(geometry_, camera, resolution, ids),
                         camera.ScreenFromWorld(resolution));
        t->readback += stage.Ms();
        return readback;
    }

    void RenderStandardMap(const LightSpace& lightSpace, const LightMatrix& focused,
                           Resolution resolution, FrameTimes*) override {
        renderer_.RenderShadowMap(kStandardMap, lightSpace, focused, resolution);
    }

    // Readback shading and boundary pixels on the GPU, the samples at those pixels on the CPU.
    LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                 std::size_t light, bool fromKept, FrameTimes* t) override {
        renderer_.ShadePass(CameraSlot::kReadback, fromKept ? FinalMap(light, true) : kStandardMap,
                            lightSpace);
        renderer_.FindBoundary(CameraSlot::kReadback);
        glFinish();
        const Stopwatch stage;
        LightSamples samples = LightSamplesAtPixels(readback, lightSpace, renderer_.ReadBoundary());
        t->extraction += stage.Ms();
        return samples;
    }

    void RenderFinalMap(std::size_t light, const LightSpace& lightSpace, const LightMatrix& matrix,
                        Resolution resolution, bool keep, FrameTimes*) override {
        finalMap_ = FinalMap(light, keep);
        renderer_.RenderShadowMap(finalMap_, lightSpace, matrix, resolution);
    }

    void ShadeFrame(const LightSpace& lightSpace, FrameTimes*) override {
        renderer_.ShadePass(CameraSlot::kFrame, finalMap_, lightSpace);
    }

    TriangleMesh geometry_;
    GlRenderer renderer_;
    FrameSchedule schedule_;
    int finalMap_ = 0;  // the slot RenderFinalMap rendered last
};

}  // namespace

std::unique_ptr<FramePipeline> MakeGlFramePipeline(const TriangleMesh& geometry) {
    return std::make_unique<GlFramePipeline>(geometry);
}

}  // namespace lexel::spatial::gl
