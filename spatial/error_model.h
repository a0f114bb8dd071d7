// The error model of a shadow map at a boundary sample: how many pixels a
// quantized shadow edge misclassifies, on average over the map's sub-texel phase, per pixel of
// edge — the footprint *across* the edge, ‖n̂ᵀJ⁻¹‖, rather than the footprint of eq. (6)
// (Chong & Gortler, "Scene Optimized Shadow Mapping", EG technical report, ~2006).
//
// Derivation. Near a boundary sample the shadow edge is a straight line in the image with unit
// normal n̂ (pixels, towards the shadow); the map sends pixel offsets dx to texel offsets du = J dx
// (J = ∂u/∂x, texels per pixel, SampleJacobian). A pixel's signed distance to the edge is
//     f(x) = n̂·(x − x₀) = n̂ᵀJ⁻¹ (u − u₀) = g·(u − u₀),    g = J⁻ᵀ n̂ (pixels per texel),
// so an edge moved by δ texels along its texel-space normal moves by |δ|·‖g‖ pixels across itself.
// ShadePoint (render_backend.h) decides a receiver at map position u by the ray through the centre
// c(u) = ⌊u⌋ + ½ of its texel: the receiver is misclassified exactly when the edge passes between
// u and c(u), i.e. when f and f + g·r differ in sign, r = c(u) − u. For a uniform sub-texel phase
// r is uniform on [−½, ½]², and integrating over f the misclassified band per pixel of edge is
//     E|g·r| = a/4 + b²/(12a),    a = max(|g₁|, |g₂|),  b = min(|g₁|, |g₂|)
// (condition on r₂: E|a r₁ + c| = a/4 + c²/a for |c| ≤ a/2, and E[(b r₂)²] = b²/12). This is
// ExpectedBandWidth. When the edge runs along a texel axis (b = 0) it is ‖g‖/4: the edge moves
// by |δ| ≤ ½ texel, mean ¼ (ExpectedBandWidthIsotropic, the isotropic ‖n̂ᵀJ⁻¹‖/4); at 45° to the
// texel axes it is ‖g‖/(3√2) = 0.943 ‖g‖/4, so ‖g‖/4 is an upper bound within 6%.
//
// Per boundary sample. The boundary pixels of a straight edge (an 8-neighbour decided the other
// way, BoundaryPixels in samples.h) fill the strip within ‖n̂‖₁ pixels of it on both sides, one
// per pixel², so each stands for 1/(2‖n̂‖₁) pixels of edge (EdgeLengthPerBoundaryPixel: ½ for an
// edge along a pixel axis, 1/(2√2) diagonally). A sample of the readback (w × h pixels) predicts
// band × length readback pixels²; one readback pixel covers (W·H)/(w·h) frame pixels of a W × H
// frame (FramePixelsFromReadbackArea; pixels need not be square, areas are affine-covariant).
//
// The edge normal n̂ comes from the readback's decisions under the standard map (the map the
// samples were found with): the 3×3 Sobel gradient of the shadowed indicator
// (EdgeNormalAt, samples.h; LightSamples::edgeNormal).
//
// What the model leaves out (so a study must count those pixels apart):
//  - thin shadows the readback misses (no boundary pixel near them) and shadows thinner than a
//    texel, which a phase makes appear and vanish as a whole;
//  - pixels no map covers (outside the map, behind its plane: shaded lit whatever the truth);
//  - lights whose readback shows no edge (no samples at all: the model predicts nothing);
//  - edges that are not straight over a texel (corners, curved or crossing edges) and receivers
//    that are not planar over a texel (receiver-plane depth is exact on planes only);
//  - filtering: it assumes nearest-texel lookups decided at the texel centre (ShadePoint's); PCF
//    or bilinear depth would blur the band instead of moving it;
//  - depth bias and self-shadowing: it assumes the receiver never shadows itself (receiver-plane
//    depth with kRelativeBias, render_backend.h); acne or peter-panning would add their own bands;
//  - J's variation over the band (exact for a planar receiver under an affine map).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// g = n̂ᵀJ⁻¹ (pixels per texel, per texel axis) for the unit edge normal n̂ (pixels) and
// J = ∂u/∂x given by rows (∂u¹/∂x, ∂u²/∂x) in texels per pixel (SampleJacobian's form). Returns
// (+inf, +inf) when J is singular or not finite.
glm::dvec2 EdgeNormalInTexels(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2);

// The expected misclassified band across a straight edge, in pixels per pixel of edge, for a
// uniform sub-texel phase and nearest-texel decisions at texel centres: a/4 + b²/(12a) with
// (a, b) the larger and smaller of |g₁|, |g₂| (header comment). 0 for n̂ = 0; +inf when J is
// singular.
double ExpectedBandWidth(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2);
// The isotropic form ‖n̂ᵀJ⁻¹‖/4: exact along a texel axis, at most 6% above
// ExpectedBandWidth.
double ExpectedBandWidthIsotropic(glm::dvec2 normal, glm::dvec2 jRow1, glm::dvec2 jRow2);

// The pixels of a straight edge one boundary pixel stands for: 1/(2‖n̂‖₁), for a unit n̂; 0 for
// n̂ = 0.
double EdgeLengthPerBoundaryPixel(glm::dvec2 normal);

// An area of `readbackArea` readback pixels² in frame pixels: × (W·H)/(w·h). 0 when the readback
// is empty.
double FramePixelsFromReadbackArea(double readbackArea, Resolution readback, Resolution frame);

}  // namespace lexel::spatial
