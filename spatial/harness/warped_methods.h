// The warped methods of the 3D harness: single maps whose parameterization is not a
// light matrix (map_warp.h), measured like every other method on the same readback, visible
// points, margin, boundary samples, depth test and texel budget (W × H of the scene's map):
//   rtw           P. Rosen, "Rectilinear Texture Warping for Fast Adaptive Shadow Mapping", I3D
//                 2012: focused-tight's map and two 1-D warps from the readback's importance
//                 (rtw.h);
//   rtw-lagrange  the same base and warps with each axis's density from the thesis's Lagrange
//                 allocation of a separable per-sample cost — h's term (eq. 6) until the edge
//                 energy's energy lands (rtw.h, SeparableCost);
//   logpsm        D. B. Lloyd et al., "Logarithmic Perspective Shadow Maps", ACM TOG 2008: the
//                 perspective warp followed by the logarithm of its depth, at the aspect its
//                 aliasing analysis asks for within the same texels (logpsm.h).
// Their maps are ray-cast (ray_cast_map.h), or rendered by a backend that rasterizes the warp
// (RenderBackend::RenderWarpedShadowMap: the GL backend for rtw*); logpsm's on the CPU only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/rtw.h"

namespace lexel::spatial {

std::vector<std::string> WarpedMethodNames();  // rtw, rtw-lagrange, logpsm
bool IsWarpedMethod(std::string_view name);
// Whether the GL backend renders the method's map on the GPU (rtw, rtw-lagrange); logpsm's
// logarithm is not a vertex warp of tessellated geometry: its map is ray-cast on the CPU.
bool WarpedMethodRendersOnGl(std::string_view name);

// rtw's and rtw-lagrange's warp over a base map: from the readback's importance map, or from the
// Lagrange densities of `cost` over the context's boundary samples.
MapWarp RtwLightWarp(const MethodContext& context, const LightMatrix& base,
                     const RtwOptions& options = {});
MapWarp RtwLagrangeLightWarp(const MethodContext& context, const LightMatrix& base,
                             const SeparableCost& cost, const RtwOptions& options = {});

// The method's matrix (the warp's base), warp and resolution. std::invalid_argument for an
// unknown name, or without the context's samples (every warped method) or readback (rtw).
MethodMatrix WarpedLightMatrix(std::string_view name, const MethodContext& context);

}  // namespace lexel::spatial
