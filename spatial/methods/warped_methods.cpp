// The warped family: single maps whose parameterization is not a light matrix (map_warp.h),
// measured like every other method on the same readback, visible points, margin, boundary
// samples, depth test and texel budget (W × H of the scene's map):
//   rtw           focused-tight's map and two 1-D warps from the readback's importance (rtw.h);
//   rtw-lagrange  the same base and warps with each axis's density from the thesis's Lagrange
//                 allocation of a separable per-sample cost, h's term (eq. 6) (rtw.h);
//   logpsm        the perspective warp followed by the logarithm of its depth, at the aspect its
//                 aliasing analysis asks for within the same texels (logpsm.h).
// Their maps are ray-cast (ray_cast_map.h), or rendered by a backend that rasterizes the warp (the
// GL backend for rtw*); logpsm's logarithm is no vertex warp: its map is ray-cast on the CPU.
#include <stdexcept>

#include "lexel/spatial/logpsm.h"
#include "lexel/spatial/methods/families.h"
#include "lexel/spatial/rtw.h"

namespace lexel::spatial {

namespace {

constexpr const char* kRosen =
    "P. Rosen, \"Rectilinear Texture Warping for Fast Adaptive Shadow Mapping\", I3D 2012";
constexpr const char* kLloyd2008 =
    "D. B. Lloyd, N. K. Govindaraju, C. Quammen, S. E. Molnar, D. Manocha, \"Logarithmic "
    "Perspective Shadow Maps\", ACM TOG 2008";

// rtw: the warp over focused-tight from the readback's importance map.
MethodMatrix Rtw(const MethodContext& context) {
    if (!context.readback || !context.samples)
        throw std::invalid_argument("rtw needs the readback and the samples");
    const BaselineContext& b = context.baseline;
    MethodMatrix m;
    m.matrix = FocusedTightLightMatrix(b);
    const ImportanceMap importance =
        RtwImportance(*context.readback, b.camera, *b.lightSpace, m.matrix, b.map, context.frame,
                      context.samples->pixel, RtwOptions{});
    m.warp = RectilinearWarp(m.matrix, b.map, RowColumnMaxima(importance), RtwOptions{});
    return m;
}

// rtw-lagrange: the warp over focused-tight from the Lagrange densities of h's per-sample cost
// over the boundary samples.
MethodMatrix RtwLagrange(const MethodContext& context) {
    if (!context.samples) throw std::invalid_argument("rtw-lagrange needs the samples");
    const Resolution map = context.baseline.map;
    MethodMatrix m;
    m.matrix = FocusedTightLightMatrix(context.baseline);
    const SeparableCost cost = EnergyHCost();
    const AxisProfile costs = LagrangeAxisCosts(*context.samples, m.matrix, map, map, cost);
    m.warp = RectilinearWarp(m.matrix, map, LagrangeDensities(costs, cost.exponent), RtwOptions{});
    return m;
}

MethodMatrix LogPsm(const MethodContext& context) {
    if (!context.samples) throw std::invalid_argument("logpsm needs the samples");
    const LogPsmMap log = LogPsmLightMap(context.baseline);
    MethodMatrix m;
    m.matrix = log.warp.base;
    m.warp = log.warp;
    m.resolution = log.resolution;
    return m;
}

}  // namespace

std::vector<MethodDescriptor> WarpedMethods() {
    const auto warped = [](std::string name, std::string description, std::string citation,
                           bool gpuMap, StorageModel storage,
                           MethodMatrix (*compute)(const MethodContext&)) {
        return MethodDescriptor{{std::move(name),
                                 std::move(description),
                                 std::move(citation),
                                 MethodFamily::kWarped,
                                 {.warped = true, .gpuMap = gpuMap},
                                 storage},
                                compute};
    };
    return {
        warped("rtw", "Rosen 2012: focused-tight + two 1-D warps from the readback's importance",
               kRosen, true, StorageModel::kAdaptive, &Rtw),
        warped("rtw-lagrange",
               "rtw's warps with Lagrange densities of h's per-sample cost per row/column", kRosen,
               true, StorageModel::kAdaptive, &RtwLagrange),
        warped("logpsm", "Lloyd et al. 2008: perspective warp, then the log of its depth (CPU map)",
               kLloyd2008, false, StorageModel::kLogPsm, &LogPsm),
    };
}

}  // namespace lexel::spatial
