// Shadow maps of any warp by ray casting: a nonlinear parameterization (map_warp.h:
// RTW, LogPSM) cannot be rasterized exactly by a linear matrix, so each texel's map is built the
// way the raster path's value is defined. Texel t stands for the light ray through its centre,
// X = warp.Inverse(t + ½); Embree (ray_caster.h) finds the nearest triangle on that ray, and the
// texel stores the linear light depth (LightSpace::Depth) to that triangle's plane along the ray,
// computed in double from the mesh — exactly what the CPU rasterizer stores (the depth of the
// triangle's point under the texel centre, cpu_renderer.cpp) and the GL shadow pass computes. So
// every method's decision is ShadePoint's receiver-plane test, whatever builds its map.
//
// With a linear warp the ray-cast map equals the rasterized one: the same depths (the float of
// the same double, up to the double rounding of two routes to one plane point) wherever both pick
// the same triangle; they differ only where a texel centre falls within Embree's float
// tolerance of a triangle edge (the rasterizer's top-left rule and Embree's watertight test then
// give the centre to different triangles). RayCastMap.EqualsTheRasterMapOnEveryShippedScene
// measures both.
//
// The shading of warped maps (ShadePoint with ShadowMap::warp, the functions below) runs on the
// CPU for every backend.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/map_warp.h"

namespace lexel::spatial {

class RayCaster;

// Builds maps by ray casting against one mesh: `caster` must be built from `mesh`, and both must
// outlive the mapper (it keeps references, and the triangles' planes in double).
class RayCastMapper {
  public:
    RayCastMapper(const TriangleMesh& mesh, const RayCaster& caster);

    // The map of `warp` (phase included) at `resolution`: per texel the depth above, +inf where
    // the ray hits nothing; ShadowMap::matrix = warp.base, ShadowMap::warp = warp (empty when
    // the warp is linear with zero phase — then the map is the matrix's, as a rasterizer's).
    // Rays go out in coherent order (texel rows). Throws std::invalid_argument for an empty
    // resolution.
    ShadowMap Render(const LightSpace& lightSpace, const MapWarp& warp,
                     Resolution resolution) const;

  private:
    const RayCaster& caster_;
    std::vector<glm::dvec4> planes_;  // (n, d): n·x = d per triangle, n unit (0 if degenerate)
};

// ShadePoint for a map with a warp (render_backend.h's decision: attached shadow, a receiver
// outside the map or behind its plane lit, the receiver's plane depth along texel t's ray
// warp->Inverse(t + ½) against the stored depth with kRelativeBias). For a linear warp with zero
// phase the decision is ShadePoint's through the matrix, bit for bit.
Shade ShadeWarpedPoint(const LightSpace& lightSpace, const ShadowMap& map,
                       const glm::dvec3& wsPoint, const glm::dvec3& wsNormal);
// Every pixel of `frame` (kEmpty where not covered), TBB-parallel.
std::vector<Shade> ShadeWarpedPixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                     const ShadowMap& map);

// The map's texel coordinates of X: the warp's Forward, or the matrix's Map where X is in front
// of its plane; nullopt behind it.
std::optional<glm::dvec2> MapCoordinates(const ShadowMap& map, const glm::dvec3& lsX);
// ∂u/∂X of the map at X (the warp's or the matrix's); false where MapCoordinates is nullopt.
bool MapJacobianAt(const ShadowMap& map, const glm::dvec3& lsX, glm::dvec3* du1dX,
                   glm::dvec3* du2dX);
// SampleBadness (samples.h) under the map's own parameterization.
double MapSampleBadness(const ShadowMap& map, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                        const glm::dvec3& dXdx2, Badness badness);

// Lloyd et al. 2006 eq. 1's perspective factor w_l/w_i (evaluation.h, PerspectiveAliasing) of any
// warp at a world point: the widest cross-section of the texel's beam, σ₁ of the inverse of ∂u/∂x
// on the plane ⊥ the light ray, over the pixel's width at the point's planar eye depth. +inf where
// the warp does not map the point or is singular there.
double WarpPerspectiveAliasing(const Camera& camera, const LightSpace& lightSpace,
                               const MapWarp& warp, const glm::dvec3& wsPoint);

}  // namespace lexel::spatial
