// Which renderer the 3D commands use (report §3's passes): the CPU reference or OpenGL. The
// command line maps its --backend flag onto BackendKind; the runners below take only the kind.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "lexel/spatial/harness/frame_pipeline.h"
#include "lexel/spatial/harness/render_backend.h"

namespace lexel::cases {

enum class BackendKind { kCpu, kGl };

std::optional<BackendKind> ParseBackend(std::string_view name);  // "cpu" | "gl"
std::string_view BackendName(BackendKind kind);

// The backend cannot be made on this machine: lexel was built without OpenGL, or no OpenGL 4.5
// context could be created. what() is one line with the reason.
class BackendUnavailable : public std::runtime_error {
  public:
    explicit BackendUnavailable(const std::string& message) : std::runtime_error(message) {}
};

// Whether this build has the OpenGL backend (lexel::gl).
bool GlBackendBuilt();

// The RenderBackend of `kind` for `geometry`. Throws BackendUnavailable.
std::unique_ptr<spatial::RenderBackend> MakeRenderBackend(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry);
// The frame pipeline of `kind` (frame_pipeline.h). Throws BackendUnavailable.
std::unique_ptr<spatial::FramePipeline> MakeFramePipeline(BackendKind kind,
                                                          const spatial::TriangleMesh& geometry);

// What renders for `kind`, on one line: "cpu (N threads)" or the GL renderer, version and how it
// was reached. Throws BackendUnavailable for gl without a context.
std::string DescribeBackend(BackendKind kind);

}  // namespace lexel::cases
