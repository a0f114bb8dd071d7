#include "lexel/spatial/harness/warped_methods.h"

#include <stdexcept>

#include "lexel/spatial/logpsm.h"

namespace lexel::spatial {

std::vector<std::string> WarpedMethodNames() { return {"rtw", "rtw-lagrange", "logpsm"}; }

bool IsWarpedMethod(std::string_view name) {
    return name == "rtw" || name == "rtw-lagrange" || name == "logpsm";
}

bool WarpedMethodRendersOnGl(std::string_view name) {
    return name == "rtw" || name == "rtw-lagrange";
}

MapWarp RtwLightWarp(const MethodContext& context, const LightMatrix& base,
                     const RtwOptions& options) {
    if (!context.readback || !context.samples)
        throw std::invalid_argument("rtw needs the readback and the samples");
    const BaselineContext& b = context.baseline;
    const ImportanceMap importance =
        RtwImportance(*context.readback, b.camera, *b.lightSpace, base, b.map, context.frame,
                      context.samples->pixel, options);
    return RectilinearWarp(base, b.map, RowColumnMaxima(importance), options);
}

MapWarp RtwLagrangeLightWarp(const MethodContext& context, const LightMatrix& base,
                             const SeparableCost& cost, const RtwOptions& options) {
    if (!context.samples) throw std::invalid_argument("rtw-lagrange needs the samples");
    const Resolution map = context.baseline.map;
    const AxisProfile costs = LagrangeAxisCosts(*context.samples, base, map, map, cost);
    return RectilinearWarp(base, map, LagrangeDensities(costs, cost.exponent), options);
}

MethodMatrix WarpedLightMatrix(std::string_view name, const MethodContext& context) {
    MethodMatrix m;
    if (name == "logpsm") {
        if (!context.samples) throw std::invalid_argument("logpsm needs the samples");
        const LogPsmMap log = LogPsmLightMap(context.baseline);
        m.matrix = log.warp.base;
        m.warp = log.warp;
        m.resolution = log.resolution;
        return m;
    }
    if (name != "rtw" && name != "rtw-lagrange")
        throw std::invalid_argument("unknown warped method '" + std::string(name) + "'");
    // The importance map's base: focused-tight, the focused map fitted to the visible points.
    m.matrix = FocusedTightLightMatrix(context.baseline);
    m.warp = name == "rtw" ? RtwLightWarp(context, m.matrix)
                           : RtwLagrangeLightWarp(context, m.matrix, EnergyHCost());
    return m;
}

}  // namespace lexel::spatial
