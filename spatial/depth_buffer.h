// A renderer's depth buffer as the readback of Chong & Gortler's Algorithm 1 (report §2.3 steps
// 1–2, Appendix A): every depth convention engines use — OpenGL's clip depth in [-1, 1],
// Direct3D's and Vulkan's (and glClipControl's) in [0, 1], reversed-Z, either row order — and
// the low resolution Algorithm 1 wants.
//
// Resolution. Algorithm 1 needs the visible points (the map must cover them) and, at the pixels
// near shadow boundaries, the screen → world derivatives; the report subsamples: "for the scenes
// we tested (rendered at 1150x1150 resolution), a 180x180 sample resolution was sufficient" (§2.4),
// the number needed depending on "scene depth slope variation". MakeReadback's time grows with
// the pixels: every covered pixel of a depth buffer is a candidate for the visible points' 3D hull
// (a depth buffer carries no triangle ids, so no pixel can be dropped before Qhull): the
// walkthrough's camera at 1280×720 takes 269 ms (140 ms of it the hull), the same buffer through
// DownsampleDepth (160×90) 2.6 ms (bench/spatial_bench BM_ReadbackFromDepth). Render the camera
// pass of step 1 at about kReadbackSide² pixels, or pass a full-size buffer through
// DownsampleDepth.
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/readback.h"

namespace lexel::spatial {

// Algorithm 1's readback size per side (report §2.4: 180×180 for 1150² frames).
inline constexpr int kReadbackSide = 180;

// Which way the stored depth runs: kStandard, 0 (or -1 in clip space) at the near plane and the
// cleared value 1 where nothing was drawn; kReversed (reversed-Z: a projection that maps the near
// plane to 1 and the far plane, or infinity, to 0), cleared to 0.
enum class DepthDirection { kStandard, kReversed };

// Which NDC y the buffer's row 0 lies at: +1 (Direct3D's framebuffer, lexel's own images), or -1
// (OpenGL's glReadPixels, whose row 0 is the bottom row; Vulkan's framebuffer, whose NDC y points
// down).
enum class FirstRow { kAtNdcYPlusOne, kAtNdcYMinusOne };

struct DepthConvention {
    // Clip depth of the projection: kMinusOneToOne (OpenGL's default; the stored depth is
    // (z_ndc + 1) / 2) or kZeroToOne (Direct3D, Vulkan, glClipControl GL_ZERO_TO_ONE; the stored
    // depth is z_ndc).
    ClipDepth clipDepth = ClipDepth::kMinusOneToOne;
    DepthDirection direction = DepthDirection::kStandard;
    FirstRow firstRow = FirstRow::kAtNdcYPlusOne;
};

// A depth buffer as the renderer stored it, and the matrix that made it.
struct DepthBuffer {
    Resolution resolution;
    // resolution.Count() values, row-major, row 0 at convention.firstRow; the cleared value (1, or
    // 0 reversed) where nothing was drawn. Not owned.
    std::span<const float> depth;
    glm::dmat4 clipFromWorld{1.0};  // projection · view (a Camera's: ClipFromView · ViewFromWorld)
    DepthConvention convention;
};

// Q for the buffer: world → (x¹ w, x² w, x³ w, w) with pixel (x, y) of the array (y its row in
// memory) at x¹ ∈ [x, x + 1], x² ∈ [y, y + 1], and x³ the value stored there. With the default
// convention and a Camera's clipFromWorld it is Camera::ScreenFromWorld.
glm::dmat4 ScreenFromWorld(const DepthBuffer& buffer);

// CameraBufferFromDepth (readback.h) for any convention: a pixel is covered where its depth is
// finite and nearer than the cleared value (below 1; above 0 reversed), its world point the
// unprojection of its stored depth at the pixel centre; MakeReadback(buffer) is MakeReadback of
// that and ScreenFromWorld(buffer). Throws std::invalid_argument when the size does not match,
// the matrix is singular or not finite, or — for a perspective clipFromWorld — the stored depth
// runs the other way than convention.direction says (a reversed-Z projection declared standard,
// or the reverse), naming the convention to use.
CameraBuffer CameraBufferFromDepth(const DepthBuffer& buffer);
Readback MakeReadback(const DepthBuffer& buffer);

// A depth buffer that owns its values (DownsampleDepth's result); View() is its DepthBuffer.
struct DepthImage {
    Resolution resolution;
    std::vector<float> depth;
    glm::dmat4 clipFromWorld{1.0};
    DepthConvention convention;
    // The source pixels it samples: source column step · i + offset.x, row step · j + offset.y.
    int step = 1;
    glm::ivec2 offset{0};
    DepthBuffer View() const { return {resolution, depth, clipFromWorld, convention}; }
};

// The buffer point-sampled down to at most maxSide pixels per side: every step-th pixel of each
// row and column (step = ⌈max(W, H) / maxSide⌉, 1 when the buffer is already small enough), the
// sampled grid centred in the image, each sample the stored depth of its pixel (no filtering, which
// would invent points between a silhouette and what lies behind it). clipFromWorld becomes the
// projection under which the samples are the pixel centres of the smaller image (an NDC scale and
// shift), so the result is exactly the depth buffer a renderer would have drawn at that size
// through the source pixels' centres. Up to step - 1 source columns and rows at the edges are not
// sampled (as a smaller pass would not). Throws std::invalid_argument when maxSide < 1 or the
// buffer's size does not match.
DepthImage DownsampleDepth(const DepthBuffer& buffer, int maxSide = kReadbackSide);

}  // namespace lexel::spatial
