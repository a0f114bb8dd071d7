// Lloyd, Tuft, Yoon & Manocha, "Warping and Partitioning for Low Error Shadow Maps" (EGSR 2006),
// eq. 1's perspective aliasing per point: how wide a shadow-map texel is against a frame pixel
// there. The evaluation measures every method by it (spatial/harness/evaluation.h: the effective
// storage factor), and virtual shadow maps choose their page level from it
// (virtual_shadow_map.h).
#pragma once

#include <glm/glm.hpp>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial {

// Lloyd et al. 2006 eq. 1's perspective factor w_l/w_i at a world point served by `matrix`:
// w_l = σ₁ of the inverse of ∂u/∂x restricted to the plane perpendicular to the light's ray
// through the point (world units per texel: the widest cross-section of the texel's beam), and
// w_i = 2 tanθ z / H (eq. 2 per pixel: z the planar eye depth, H the frame's height in pixels,
// square pixels). Unlike σ₁(J⁻¹) it leaves out the receiver's orientation (eq. 1's cosine ratio,
// projection aliasing), as Lloyd's storage factor does. +inf where the map is singular there or
// the point is not in front of the map; throws nothing.
double PerspectiveAliasing(const Camera& camera, const LightSpace& lightSpace,
                           const LightMatrix& matrix, const glm::dvec3& wsPoint);

// The same factor for any map whose rows ∂u¹/∂X, ∂u²/∂X (texels per light-space unit) at the
// point are given: a linear matrix's (LightMatrix::MapJacobian) or a warp's (MapWarp::Jacobian).
// +inf where they are singular on the plane ⊥ the light's ray; throws nothing.
double PerspectiveAliasingOfRows(const Camera& camera, const LightSpace& lightSpace,
                                 const glm::dvec3& du1dX, const glm::dvec3& du2dX,
                                 const glm::dvec3& wsPoint);

}  // namespace lexel::spatial
