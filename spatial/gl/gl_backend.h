// The OpenGL backend of the 3D harness behind RenderBackend (render_backend.h): the passes of
// GlRenderer, with every result returned in CPU form as the interface promises.
//   - RenderCamera: the GPU resolves visibility, the CPU recomputes each pixel's point in double
//     from its triangle (visibility.h), so readbacks and ground truth see exact points;
//   - RenderShadowMap: the GPU map, read back (linear light depth, +inf where empty);
//   - ShadePixels: the given buffers uploaded (points and normals as float) and shaded on the
//     GPU with ShadePoint's decision;
//   - BoundarySamples: the readback shaded and its boundary pixels found on the GPU; those pixels
//     and the readback's decisions come back (LightSamplesAtPixels builds the samples, their
//     edge normals and the prior's points from them, as MakeLightSamples does on the CPU).
//
// Threads: one context for the process (context.h); every call makes it current on the calling
// thread under its mutex, so calls from parallel threads (the sweep's lights) run one after
// another on the GPU while the CPU work around them (shadow rays, the optimizer) stays parallel.
#pragma once

#include <memory>

#include "lexel/spatial/gl/context.h"
#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial::gl {

// Throws GlUnavailable when no OpenGL 4.5 context can be created (context.h).
std::unique_ptr<RenderBackend> MakeGlBackend(const TriangleMesh& geometry);

}  // namespace lexel::spatial::gl
