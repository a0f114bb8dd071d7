// The rendering passes of the 3D harness behind one interface (report Algorithm 1 steps 1–2 and
// the experiment of §3), so that any backend (the CPU reference here, a GPU one) provides the same
// passes:
//   1. the camera pass: per pixel the visible world point, its normal and its z-buffer value —
//      the readback at low resolution, the final frame at full resolution;
//   2. the shadow-map pass: linear light depth through any light matrix P;
//   3. shading: per pixel the shadow decision for one light from one shadow map.
//
// The shadow decision (ShadePoint) is the bias policy, identical for every method:
//   - a receiver whose normal faces away from the light (n · l ≤ 0) is in attached shadow and is
//     excluded from the misclassification counts (every method and the ground truth agree);
//   - otherwise the receiver-plane depth test of receiver_plane.h: the stored depth of texel t
//     against the depth of the receiver's own plane along the ray through t's centre, shadowed
//     iff stored < receiverPlaneDepth · (1 - kRelativeBias), kRelativeBias = 1e-5;
//   - a receiver outside the map, or behind the light's plane p4·X = 0, is lit (every method's map
//     covers the visible samples, so this only happens between readback samples).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "lexel/spatial/harness/receiver_plane.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/map_warp.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

struct ShadowMap {
    Resolution resolution;
    LightMatrix matrix;
    std::vector<float> depth;  // linear light depth (LightSpace::Depth); +inf where empty
    // A nonlinear map (map_warp.h, its base `matrix`): a point lands at warp->Forward(X) and
    // texel t stands for the ray warp->Inverse(t + ½), both in ShadePoint's decision; built by
    // ray casting (ray_cast_map.h) or a backend's RenderWarpedShadowMap. Empty: the matrix's map.
    std::optional<MapWarp> warp;
};

// The shadow decision for one receiver (see the header comment).
Shade ShadePoint(const LightSpace& lightSpace, const ShadowMap& map, const glm::dvec3& wsPoint,
                 const glm::dvec3& wsNormal);

class RenderBackend {
  public:
    virtual ~RenderBackend() = default;
    virtual std::string_view Name() const = 0;
    virtual CameraBuffer RenderCamera(const Camera& camera, Resolution resolution) const = 0;
    virtual ShadowMap RenderShadowMap(const LightSpace& lightSpace, const LightMatrix& matrix,
                                      Resolution resolution) const = 0;
    // The map of a nonlinear warp where this backend rasterizes it (the GL backend: RTW's
    // piecewise-linear warps by the vertex warp of tessellated geometry); nullopt where it does
    // not, and the harness ray-casts the map instead (ray_cast_map.h). The default: nullopt.
    virtual std::optional<ShadowMap> RenderWarpedShadowMap(const LightSpace& lightSpace,
                                                           const MapWarp& warp,
                                                           Resolution resolution) const;
    virtual std::vector<Shade> ShadePixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                           const ShadowMap& map) const = 0;
    // Algorithm 1 step 3 for one light: the boundary samples of `readback` under `map` (a
    // standard shadow map). Every backend must give MakeLightSamples over its own ShadePixels of
    // readback.buffer (the default does exactly that); a GPU backend finds the boundary pixels on
    // the GPU and reads back only them.
    virtual LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                         const ShadowMap& map) const;
};

// The readback of one camera pose rendered by `backend` (MakeReadback over its camera pass).
Readback RenderReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution);

// The CPU reference: exact (double) world points per pixel, TBB-parallel, deterministic.
std::unique_ptr<RenderBackend> MakeCpuRenderer(const TriangleMesh& geometry);

}  // namespace lexel::spatial
