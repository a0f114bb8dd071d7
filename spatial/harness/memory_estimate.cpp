// The byte counts behind EstimateEvaluationMemory, from the buffers the evaluation keeps (sizes on
// x86-64: glm::dvec3 24, double 8, float 4, Shade 1). Each count is rounded up, and the sum is
// multiplied by kHeadroom for what vectors over-reserve and the allocator keeps.
#include "lexel/spatial/harness/memory_estimate.h"

namespace lexel::spatial {
namespace {

// Per frame pixel, for the run: CameraBuffer (windowDepth 8, wsPosition 24, wsNormal 24,
// triangle 4) + the plane derivatives ∂W/∂x¹, ∂W/∂x² (48) + planar eye depth (8) = 116.
constexpr double kFrameBytes = 116;
// Per readback pixel: CameraBuffer (60) + ∂W/∂x (48) + smooth (1) + wsRelevant (24) + the
// relevant-hull input (24) = 157.
constexpr double kReadbackBytes = 157;
// Per readback pixel and light: the light-space samples of a pixel (lsX, ∂X/∂x¹, ∂X/∂x², wsX:
// 96, pixel 4, the energy's structure-of-arrays copy 72 + margin 8, lsRelevant 24) ≈ 204, and
// the baselines' and optimizer's copies of the relevant points (2 × 24).
constexpr double kReadbackPerLightBytes = 252;
// Per frame pixel and light: the ray-traced truth (1) and the renderer's per-pixel scratch
// (light-space point and depth, 32); per kept method its shades (Shade, 1).
constexpr double kFramePerLightBytes = 33, kShadeBytes = 1;
// Per shadow-map texel: the rasterizer's scratch (8) once, per kept map its linear light depth
// (float, 4).
constexpr double kTexelScratchBytes = 8, kTexelBytes = 4;
// Kept buffers become images one at a time (images.h, RGB float: 12 bytes a pixel): the frame
// and its error map per frame pixel, the shadow map's picture per texel.
constexpr double kImageBytes = 12;
// Per triangle: the mesh (3 double vertices 72, indices 12) and Embree's BVH (about 100 in its
// high-quality build) with world-space copies for the CPU rasterizer (72).
constexpr double kTriangleBytes = 256;
// Over-reservation by std::vector growth and allocator slack.
constexpr double kHeadroom = 1.5;

double Pixels(Resolution r) { return static_cast<double>(r.width) * r.height; }

}  // namespace

EvaluationMemory EstimateEvaluationMemory(const EvaluationSizes& s) {
    const double frame = Pixels(s.frame), readback = Pixels(s.readback);
    const double texels = Pixels(s.shadowMap);
    const double keptMethods = s.keepBuffers ? s.methods : 1;
    const double truthTexels = static_cast<double>(s.truthMapSize) * s.truthMapSize;
    EvaluationMemory m;
    m.shared = kHeadroom * (kFrameBytes * frame + kReadbackBytes * readback +
                            kTriangleBytes * static_cast<double>(s.triangles));
    m.perLight = kHeadroom * (kReadbackPerLightBytes * readback +
                              (kFramePerLightBytes + kShadeBytes * keptMethods) * frame +
                              (kTexelScratchBytes + kTexelBytes * keptMethods) * texels +
                              (kTexelScratchBytes + kTexelBytes) * truthTexels);
    if (s.keepBuffers) m.perLight += kHeadroom * kImageBytes * (2 * frame + texels);
    return m;
}

}  // namespace lexel::spatial
