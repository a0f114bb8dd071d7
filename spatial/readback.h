// The readback of Chong & Gortler's Algorithm 1 (report §2.3 steps 1–2, Appendix A): what a
// low-resolution camera pass sees per pixel, and the screen → world derivatives h(P) needs.
//
// A renderer supplies the camera pass as a CameraBuffer: from its own G-buffer (world positions),
// or from a depth buffer alone (CameraBufferFromDepth). MakeReadback adds per pixel the world-space
// derivatives ∂W/∂x¹, ∂W/∂x² (eq. 7, exact on planes), keeps only pixels where they are reliable
// (report §2.4: the depth's second difference is small), and the vertices of the 3D convex hull
// of the visible points, which every light's optimization uses (optimizer.h).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"

namespace lexel::spatial {

// Smoothness test of a readback pixel, in window-depth units (x³ ∈ [0, 1]): along both screen
// axes the second difference of x³ must be at most kSmoothness times the central first
// difference plus kDepthNoise (see readback.cpp for the scales involved).
inline constexpr double kSmoothness = 0.25;   // dimensionless
inline constexpr double kDepthNoise = 1e-12;  // window-depth units: rounding of x³ in double

// What the camera sees, per pixel, row-major from the top row.
struct CameraBuffer {
    Resolution resolution;
    std::vector<double> windowDepth;  // the z-buffer x³ ∈ [0, 1] (affine in 1/z_view); 1 if empty
    std::vector<glm::dvec3> wsPosition;  // the visible point
    std::vector<glm::dvec3> wsNormal;    // unit geometric normal facing the camera (0 if unknown)
    // The visible triangle, -1 where nothing is visible. Pixels with the same id must show one
    // planar triangle: RelevantHullVertices drops points strictly between two such pixels.
    std::vector<std::int32_t> triangle;
    bool Covered(std::size_t pixel) const { return triangle[pixel] >= 0; }
};

// A CameraBuffer from a depth buffer in lexel's own convention and the matrix that made it
// (depth_buffer.h takes every other one: reversed-Z, [0, 1] clip depth, bottom-up rows): a pixel
// is covered where its window depth is finite and below 1, its world point is
// Q⁻¹ (x¹, x², x³, 1) dehomogenized at the pixel centre, and its triangle id is its own pixel
// index (no two pixels are known to share a triangle, so the hull keeps every point); normals are
// left 0. `windowDepth` is row-major from the top row, with `resolution.Count()` entries in
// [0, 1] (x³ of Q = Camera::ScreenFromWorld). Throws std::invalid_argument when the size does not
// match or screenFromWorld is singular or not finite.
CameraBuffer CameraBufferFromDepth(Resolution resolution, std::span<const float> windowDepth,
                                   const glm::dmat4& screenFromWorld);

// The readback of one camera pose.
struct Readback {
    CameraBuffer buffer;
    std::vector<glm::dvec3> dWdx1, dWdx2;  // ∂W/∂x¹, ∂W/∂x² (world units per readback pixel)
    std::vector<std::uint8_t> smooth;      // 1 where the derivatives are reliable
    std::vector<glm::dvec3> wsRelevant;  // every visible point, in pixel order
    // The vertices of the 3D convex hull of wsRelevant (RelevantHullVertices), once per frame.
    std::vector<glm::dvec3> wsRelevantHull;
    double relevantHullMs = 0.0;  // wall time of that hull, one thread
};

// Report Appendix A on a camera pass made with Q = screenFromWorld (Camera::ScreenFromWorld at
// the buffer's resolution). Single-threaded, deterministic. Its time grows with the covered
// pixels, and a depth buffer's (no triangle ids) all go to the 3D hull: Algorithm 1 wants about
// 180² pixels (kReadbackSide and DownsampleDepth, depth_buffer.h, say why).
Readback MakeReadback(CameraBuffer buffer, const glm::dmat4& screenFromWorld);

// The vertices of the 3D convex hull of the covered pixels' world points, in pixel order. Points
// strictly between two row or column neighbours that show the same triangle are dropped before
// Qhull: they cannot be vertices (proof in readback.cpp).
std::vector<glm::dvec3> RelevantHullVertices(const CameraBuffer& buffer);
// ∂W/∂x¹, ∂W/∂x² (world units per pixel) at every covered pixel of a camera pass with normals,
// exact for the plane through the pixel's point with its normal (eq. 7 with ∂x³/∂x^j from that
// plane instead of the z-buffer's differences, so no neighbour is needed): the final frame's
// footprints (evaluation.h). Zero where the pixel is empty, has no normal, or its plane contains
// the eye ray.
void PlaneDerivatives(const CameraBuffer& buffer, const glm::dmat4& screenFromWorld,
                      std::vector<glm::dvec3>* dWdx1, std::vector<glm::dvec3>* dWdx2);

}  // namespace lexel::spatial
