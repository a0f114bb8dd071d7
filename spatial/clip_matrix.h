// A light matrix as the 4×4 a rasterizer takes (Chong & Gortler report §2.1, Fig. 1, composed with
// the light frame of light_space.h): world points → the shadow map, for OpenGL's clip space with
// depth in [-1, 1] or in [0, 1] (glClipControl GL_ZERO_TO_ONE, Direct3D, Vulkan).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial {

// P·A in world form: rows (p1ᵀA, p2ᵀA, 0, p4ᵀA) with X = A [x; 1] (LightSpace), so that a world
// point x lands on texel u^i = row_i·[x; 1] / row_4·[x; 1] (i = 1, 2) when row_4·[x; 1] > 0.
glm::dmat4 MapFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix);

enum class ClipDepth { kMinusOneToOne, kZeroToOne };

// The range of the depth the matrix writes, in world units (see ClipFromWorld).
struct DepthRange {
    double near = 0.0, far = 1.0;  // 0 < near < far for point lights; near < far otherwise
};

// ClipFromWorld's depth quantity at a world point: w = p4·X for a point light (the distance from
// the light along the optical axis, for a unit p4), d·(s / w) for a directional one (d =
// LightSpace::Depth, s its frame's third coordinate). World units; +inf where w ≤ 0.
double ClipDepthQuantity(const LightSpace& lightSpace, const LightMatrix& matrix,
                         const glm::dvec3& wsPoint);

// The tightest DepthRange that loses no shadow for `matrix` (Filament's ShadowMap and Lauritzen
// et al.'s SDSM, I3D 2011, fit the light's depth range to the scene the same way): far is the
// largest depth quantity over the receivers (wsReceivers: the visible points, Readback::
// wsRelevant), near the smallest over the casters that can shadow a receiver the map covers,
// which lie on the segments from the light to those receivers, hence inside wsCasterBounds ∩ the
// map's frustum (the pyramid of texels [0, W] × [0, H] from the light): the vertices of that
// polyhedron give it, the depth quantity being affine (point) or linear-fractional (directional)
// in the world point. Each end is moved out by `margin` × (far - near) (the readback is
// subsampled, so frame pixels between its points can lie slightly farther; report §2.4), a point
// light's near by at most half itself; a span under 1e-3 of the depth (a floor facing the light:
// every receiver at one depth) is first widened to that about its middle, so near < far. A guess
// instead loses precision: {0.5, 60} puts the
// visible points of the embedding example (tests/spatial/clip_matrix_test.cpp) at NDC z
// 0.972–0.991 of [0, 1], this range at 0.546–0.994. Throws std::invalid_argument when wsReceivers
// is empty or a receiver is not in front of p4 (w ≤ 0).
DepthRange LightDepthRange(const LightSpace& lightSpace, const LightMatrix& matrix, Resolution map,
                           const Bounds& wsCasterBounds, std::span<const glm::dvec3> wsReceivers,
                           double margin = 0.02);

// Clip from world for a rasterizer: x_ndc = 2u¹/W - 1 and y_ndc = 2u²/H - 1 (texel row 0 is
// framebuffer row 0, at y_ndc = -1), w_clip = p4·X > 0 in front of the light, and z_ndc:
//   - point light: the perspective depth of w = p4·X (the distance from the light along the
//     optical axis): z_ndc = near at w = range.near and far at w = range.far, monotone in w;
//   - directional light: z_ndc affine in d·(s/w), with d = LightSpace::Depth and s the light
//     frame's fixed third coordinate, mapping d = range.near and range.far to the ends of the
//     depth range exactly where w = s (an unwarped map, p4 = (0, 0, 1)); w is constant along every
//     light ray, so z_ndc is monotone in d along each ray as a depth test needs.
// "near" and "far" are -1 and 1, or 0 and 1 for ClipDepth::kZeroToOne. Points outside the range
// are clipped (or clamped, with GL_DEPTH_CLAMP).
glm::dmat4 ClipFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix, Resolution map,
                         DepthRange range, ClipDepth convention);

// The inverse of ClipFromWorld up to depth: the LightMatrix whose texels are those of a clip
// matrix's x, y and w rows (u¹ = W (x_ndc + 1) / 2, u² = H (y_ndc + 1) / 2), in either depth
// convention; the depth row is ignored (the harness fits every method's depth range alike). Its
// rows must send the light to infinity (FromScreenRows, whose scaling it shares: |p4| = 1, p4·X > 0
// at `wsCenter`); nullopt otherwise, with the reason in *failure when given. For every matrix P
// and range, ClipFromWorld then LightMatrixFromClip gives P scaled to |p4| = 1, to rounding.
std::optional<LightMatrix> LightMatrixFromClip(const LightSpace& lightSpace,
                                               const glm::dmat4& clipFromWorld, Resolution map,
                                               const glm::dvec3& wsCenter,
                                               std::string* failure = nullptr);

}  // namespace lexel::spatial
