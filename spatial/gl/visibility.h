// A camera buffer from a triangle-id image (a "visibility buffer": C. Burns, W. Hunt, "The
// Visibility Buffer", JCGT 2(2), 2013): the GPU resolves which triangle each pixel sees, the CPU
// recomputes where, in double, as the CPU renderer does — the point of that triangle's plane on
// the ray through the pixel centre. So a GPU camera pass gives the readback of report Appendix A
// the same double-precision window depths as the CPU pass wherever both see the same triangle:
// its smoothness test (readback.h, kDepthNoise = 1e-12) cannot work on float depths.
#pragma once

#include <cstdint>
#include <span>

#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/readback.h"

namespace lexel::spatial::gl {

// Per covered pixel (triangle[i] ≥ 0) the point of triangle[i]'s plane on the ray through the
// pixel centre (Camera::RayDirection at `resolution`: the ray the camera pass rasterized through
// camera.ScreenFromWorld(resolution), whatever the two aspect ratios), its window depth x³ under
// that matrix, and the face normal turned towards the eye (as CpuRenderer);
// a pixel whose ray is parallel to the plane, or meets it behind the eye, becomes empty (triangle
// -1). `triangle` is row-major from the top row with resolution.Count() entries indexing
// geometry.triangles (std::invalid_argument otherwise). TBB-parallel, deterministic.
CameraBuffer CameraBufferFromTriangles(const TriangleMesh& geometry, const Camera& camera,
                                       Resolution resolution,
                                       std::span<const std::int32_t> triangle);

}  // namespace lexel::spatial::gl
