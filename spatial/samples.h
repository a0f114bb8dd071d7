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

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial {

inline constexpr double kSmoothness = 0.25;   // dimensionless: |Δ²x³| ≤ 0.25 |Δx³|
inline constexpr double kDepthNoise = 1e-12;  // window-depth units: rounding of x³ in double

// The readback of one camera pose: the camera pass plus per-pixel world-space screen derivatives.
struct Readback {
    CameraBuffer buffer;
    std::vector<glm::dvec3> dWdx1, dWdx2;  // ∂W/∂x¹, ∂W/∂x² (world units per readback pixel)
    std::vector<std::uint8_t> smooth;      // 1 where the derivatives are reliable
    std::vector<glm::dvec3> wsRelevant;  // every visible point, in pixel order
    // The vertices of the 3D convex hull of wsRelevant (RelevantHullVertices), once per frame:
    // light space is an affine image of world space, so for every light the cone of light rays
    // through the relevant points is the cone through these (optimizer.h).
    std::vector<glm::dvec3> wsRelevantHull;
    double relevantHullMs = 0.0;  // wall time of that hull, one thread
};

Readback MakeReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution);

// The vertices of the 3D convex hull of the covered pixels' world points, in pixel order. Before
// Qhull (solvers/convex_hull_3d.h), a pixel whose two neighbours along its row, or along its
// column, show the same triangle is dropped: the camera pass gives under each pixel centre the
// point of its triangle on the ray through that centre (spatial/raster.h), and the rays through
// three consecutive centres of a row (or column) lie in one plane through the eye, which cuts
// the triangle's plane in a line; so the three points lie on that line in the pixels' order,
// the middle one strictly between the others, and cannot be a vertex of the hull. Every vertex
// therefore survives, whatever else is dropped (a vertex of conv(S) is never strictly inside a
// segment of two points of S). In floating point the points carry the camera pass's rounding,
// so the hull of the survivors contains every relevant point up to that rounding. On the
// walkthrough's 180² readback this keeps about 10% of the points: the floor's interior goes.
std::vector<glm::dvec3> RelevantHullVertices(const CameraBuffer& buffer);

// The samples of one light.
struct LightSamples {
    std::vector<glm::dvec3> lsX;           // boundary samples in light space
    std::vector<glm::dvec3> dXdx1, dXdx2;  // ∂X/∂x¹, ∂X/∂x² at each
    std::vector<std::uint32_t> pixel;      // readback pixel of each
    std::vector<glm::dvec3> lsRelevant;    // every visible point in light space
    // The readback's wsRelevantHull in light space: generators of the cone of lsRelevant, all
    // the optimizer needs of it (optimizer.h). Empty (samples built by hand): it uses lsRelevant.
    std::vector<glm::dvec3> lsRelevantHull;
    std::size_t boundaryPixels = 0;  // boundary pixels before rejecting non-smooth ones
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

// Energy for many matrices over the same samples (the optimizer's search), bit for bit, with
// three savings that change no value below the bound. The in-front margins 1e-9|X| (InFront) are
// computed once instead of once per matrix. The samples are stored as structure-of-arrays and
// SampleEnergy (energy_gradient.h) runs over blocks of them in a loop without branches, which the
// compiler vectorizes with the same operations per sample, hence the same roundings (as long as
// it contracts no a·b + c into an FMA, which GCC cannot on x86-64 without -mfma); the sum then
// runs in Energy's order. And a caller that only asks whether h is below `bound` gets an early
// stop: every summand is ≥ 0 or +inf and rounded addition is monotone, so the partial sums never
// decrease, and the sum returns as soon as it reaches `bound` with that partial sum (≥ bound).
class BoundedEnergy {
  public:
    explicit BoundedEnergy(const LightSamples& samples);
    // Energy(matrix, samples) when that is < bound; otherwise some value ≥ bound (+inf when a
    // sample is not in front).
    double operator()(const LightMatrix& matrix,
                      double bound = std::numeric_limits<double>::infinity()) const;

  private:
    std::size_t count_;
    std::array<std::vector<double>, 9> soa_;  // X, ∂X/∂x¹, ∂X/∂x², component by component
    std::vector<double> frontMargin_;         // 1e-9 |X| (light-space units)
};

}  // namespace lexel::spatial
