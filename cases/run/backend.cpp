#include "lexel/cases/run/backend.h"

#include <tbb/info.h>

#ifdef LEXEL_HAVE_GL
#include "lexel/spatial/gl/gl_backend.h"
#include "lexel/spatial/gl/gl_frame_pipeline.h"
#endif

namespace lexel::cases {

std::optional<BackendKind> ParseBackend(std::string_view name) {
    if (name == "cpu") return BackendKind::kCpu;
    if (name == "gl") return BackendKind::kGl;
    return std::nullopt;
}

std::string_view BackendName(BackendKind kind) { return kind == BackendKind::kGl ? "gl" : "cpu"; }

bool GlBackendBuilt() {
#ifdef LEXEL_HAVE_GL
    return true;
#else
    return false;
#endif
}

#ifdef LEXEL_HAVE_GL

std::unique_ptr<spatial::RenderBackend> MakeRenderBackend(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry) {
    if (kind == BackendKind::kCpu) return spatial::MakeCpuRenderer(geometry);
    try {
        return spatial::gl::MakeGlBackend(geometry);
    } catch (const spatial::gl::GlUnavailable& e) {
        throw BackendUnavailable(e.what());
    }
}

std::unique_ptr<spatial::FramePipeline> MakeFramePipeline(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry) {
    if (kind == BackendKind::kCpu) return spatial::MakeCpuFramePipeline(geometry);
    try {
        return spatial::gl::MakeGlFramePipeline(geometry);
    } catch (const spatial::gl::GlUnavailable& e) {
        throw BackendUnavailable(e.what());
    }
}

std::string DescribeBackend(BackendKind kind) {
    if (kind == BackendKind::kCpu)
        return "cpu (" + std::to_string(tbb::info::default_concurrency()) + " threads)";
    try {
        return "gl: " + spatial::gl::Context::Shared().Info().Describe();
    } catch (const spatial::gl::GlUnavailable& e) {
        throw BackendUnavailable(e.what());
    }
}

#else  // built without OpenGL

namespace {
constexpr const char* kNoGl =
    "this lexel was built without OpenGL (EGL, OpenGL or libepoxy missing)";
}

std::unique_ptr<spatial::RenderBackend> MakeRenderBackend(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry) {
    if (kind == BackendKind::kCpu) return spatial::MakeCpuRenderer(geometry);
    throw BackendUnavailable(kNoGl);
}

std::unique_ptr<spatial::FramePipeline> MakeFramePipeline(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry) {
    if (kind == BackendKind::kCpu) return spatial::MakeCpuFramePipeline(geometry);
    throw BackendUnavailable(kNoGl);
}

std::string DescribeBackend(BackendKind kind) {
    if (kind == BackendKind::kCpu)
        return "cpu (" + std::to_string(tbb::info::default_concurrency()) + " threads)";
    throw BackendUnavailable(kNoGl);
}

#endif

}  // namespace lexel::cases
