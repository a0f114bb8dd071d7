// The optimization samples of Chong & Gortler's Algorithm 1 (report §2.3 steps 1–3, §2.4, Fig. 2)
// and the energy h(P) of eq. (6) over them.
//
// Step 1–2: a low-resolution camera pass (the readback) gives per pixel the z-buffer value x³ and
// the visible point. Every visible receiver point is a "relevant point" that must land in the map.
// Step 3: per light, the pixels near shadow boundaries — a pixel whose 8-neighbourhood holds both a
// lit and a shadowed receiver facing the light, under a standard (focused) shadow map — are the
// samples h is summed over.
//
// Appendix A: at a sample the screen → light-space Jacobian comes from the z-buffer. Writing the
// world point as W(x¹, x², x³) = dehomogenized Q⁻¹ (x¹, x², x³, 1), the chain rule gives
//     dW/dx^j = ∂W/∂x^j + ∂W/∂x³ · ∂x³/∂x^j,   ∂W/∂x^k = (q_k,xyz - W q_k,w) / h_w  (eq. 7),
// with q_k the k-th column of Q⁻¹ and h = Q⁻¹ x̂. ∂x³/∂x^j is the central difference of the
// z-buffer: the window depth is affine in screen space over a plane, so this is exact on planes.
//
// Depth discontinuities (report §2.4: "derivative continuity is checked by thresholding the
// acceleration in z"): a sample is kept only where, along both screen axes, the three pixels are
// covered and the second difference of x³ is at most kSmoothness times the central first
// difference (plus kDepthNoise for flat spots). Both are in window-depth units (x³ ∈ [0, 1]);
// the second difference is exactly 0 on a plane, of the order of the pixel's angular size over
// the surface's angular radius on a curved surface (≈ 0.05 for a unit sphere 10 units away at
// 180²), and of the order of the first difference itself across a silhouette or a crease.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "spatial/light_matrix.h"
#include "spatial/light_space.h"
#include "spatial/render_backend.h"

namespace lexel::spatial {

inline constexpr double kSmoothness = 0.25;   // dimensionless: |Δ²x³| ≤ 0.25 |Δx³|
inline constexpr double kDepthNoise = 1e-12;  // window-depth units: rounding of x³ in double

// The readback of one camera pose: the camera pass plus per-pixel world-space screen derivatives.
struct Readback {
    CameraBuffer buffer;
    std::vector<glm::dvec3> dWdx1, dWdx2;  // ∂W/∂x¹, ∂W/∂x² (world units per readback pixel)
    std::vector<std::uint8_t> smooth;      // 1 where the derivatives are reliable
    std::vector<glm::dvec3> wsRelevant;  // every visible point, in pixel order
};

Readback MakeReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution);

// The samples of one light.
struct LightSamples {
    std::vector<glm::dvec3> lsX;           // boundary samples in light space
    std::vector<glm::dvec3> dXdx1, dXdx2;  // ∂X/∂x¹, ∂X/∂x² at each
    std::vector<std::uint32_t> pixel;      // readback pixel of each
    std::vector<glm::dvec3> lsRelevant;    // every visible point in light space
    std::size_t boundaryPixels = 0;        // boundary pixels before rejecting non-smooth ones
};

// Boundary samples from the readback's shadow decisions `shades` (ShadePixels over
// readback.buffer with a standard shadow map).
LightSamples MakeLightSamples(const Readback& readback, const LightSpace& lightSpace,
                              std::span<const Shade> shades);

// J = ∂u/∂x at one sample (texels per readback pixel), as (row 1, row 2).
void SampleJacobian(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                    const glm::dvec3& dXdx2, glm::dvec2* row1, glm::dvec2* row2);

// ||J⁻¹||_F² of one sample (eq. 6's summand): +inf where J is singular or the sample is not in
// front of p4.
double SampleBadness(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                     const glm::dvec3& dXdx2);

// h(P) = Σ over the samples (eq. 6); +inf if any sample is not in front.
double Energy(const LightMatrix& matrix, const LightSamples& samples);

}  // namespace lexel::spatial
