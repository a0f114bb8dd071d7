// The frame of frame_pipeline.h on OpenGL with the buffers kept on the GPU, as a renderer runs
// report Algorithm 1: the readback's triangle ids and each light's boundary pixels are all that
// come back to the CPU. GPU passes are timed by GL_TIME_ELAPSED queries; before each transfer to
// the CPU the pipeline waits for the GPU (glFinish), so a transfer's time is the copy and the CPU
// work, not the wait for earlier passes. `total` is the wall time to the last pass finished.
#pragma once

#include <memory>

#include "lexel/spatial/harness/frame_pipeline.h"

namespace lexel::spatial::gl {

// Throws GlUnavailable when no OpenGL 4.5 context can be created (context.h).
std::unique_ptr<FramePipeline> MakeGlFramePipeline(const TriangleMesh& geometry);

}  // namespace lexel::spatial::gl
