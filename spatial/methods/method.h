// A 3D light-matrix method as the registry holds it (registry.h): its record (method_info.h) and
// the function that computes its map(s) for one light from what every method gets, the
// MethodContext: the camera, the map's texels, the visible points and their hull, the margin,
// the boundary samples, the readback, the cascades' options. Chong & Gortler, "Scene Optimized
// Shadow Mapping", Harvard TR-07-07 (2007), §3, is the comparison these methods take part in.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/map_warp.h"
#include "lexel/spatial/methods/method_info.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/virtual_shadow_map.h"

namespace lexel::spatial {

// A case's own method for the light being evaluated: its name and the light's clip matrix
// (OpenGL clip space, the form ClipFromWorld returns; its depth row is ignored).
struct GivenMatrix {
    std::string name;
    glm::dmat4 clipFromWorld{1.0};
};

struct MethodContext {
    BaselineContext baseline;               // its samples are set: plane-optimal uses them
    const LightSamples* samples = nullptr;  // boundary samples and relevant points (light space)
    PartitionOptions partitions;  // k, λ, the allocation and the energy of the partitioned methods
    const Readback* readback = nullptr;  // the readback (vsm*'s page requests, rtw's importance)
    Resolution frame;                    // the final frame's size (rtw's sampling rates)
    // The case's own methods for this light (looked up by name before the registry); may be empty.
    std::span<const GivenMatrix> given;
    // The optimal* methods' sample budget (OptimizerOptions::maxSamples; 0: every sample).
    std::size_t maxSamples = 0;
    // The exponent of optimal's and optimal-refined's edge energy (EnergyOptions::exponent).
    double edgeExponent = kDefaultEdgeExponent;
};

// The matrix; for the optimizer methods the optimizer's trace (h per iteration, time profile)
// and, for the multi-start ones, which start won; for a partitioned method its cascades (and
// `matrix` the first cascade's).
struct MethodMatrix {
    LightMatrix matrix;
    std::optional<OptimizerResult> optimizer;
    std::string winner;  // optimal, optimal-refined: the start whose map or search won; else empty
    std::vector<Cascade> cascades;  // partitioned methods only
    // vsm*: the virtual map and its resident pages (`matrix` is then its coarsest page's).
    std::optional<VirtualShadowMap> virtualMap;
    // Warped methods (rtw, rtw-lagrange, logpsm): the map's parameterization, whose base is
    // `matrix`, and its resolution when it is not the scene's (0 × 0: the scene's).
    std::optional<MapWarp> warp;
    Resolution resolution;
    // The baseline and trapezoid families: which fallback their construction took, and why.
    BaselineDiagnostics diagnostics;
};

// A method: its record and what computes it. `compute` returns the light matrix
// (MethodMatrix::matrix), or the cascades (::cascades, with `matrix` the first one's), the
// virtual map or the warp, from the context of one light; std::invalid_argument when the context
// lacks what it needs (the samples, the readback), which ComputeLightMatrix passes on.
struct MethodDescriptor {
    MethodInfo info{};
    std::function<MethodMatrix(const MethodContext&)> compute{};
};

}  // namespace lexel::spatial
