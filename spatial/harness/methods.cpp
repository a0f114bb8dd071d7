#include "lexel/spatial/harness/methods.h"

#include <algorithm>
#include <stdexcept>

namespace lexel::spatial {

std::vector<std::string> SpatialMethodNames() {
    return {"optimal", "focused", "lispsm",          "plane-optimal",
            "normal",  "psm",     "optimal-refined", "optimal-shear"};
}

bool IsSpatialMethod(std::string_view name) {
    const std::vector<std::string> names = SpatialMethodNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds,
                                    std::span<const glm::dvec3> wsRelevant) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = scene.camera;
    context.map = scene.shadowMap;
    context.wsBounds = wsBounds;
    context.wsRelevant = wsRelevant;
    context.floorPlane = scene.floorPlane;
    return context;
}

MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context) {
    if (name == "normal") return {NormalLightMatrix(context.baseline), std::nullopt};
    if (name == "focused") return {FocusedLightMatrix(context.baseline), std::nullopt};
    if (name == "lispsm") return {LispsmLightMatrix(context.baseline), std::nullopt};
    if (name == "psm") return {PsmLightMatrix(context.baseline), std::nullopt};
    if (name == "plane-optimal") return {PlaneOptimalLightMatrix(context.baseline), std::nullopt};
    if (name == "optimal" || name == "optimal-refined" || name == "optimal-shear") {
        if (!context.samples) throw std::invalid_argument("optimal needs the light's samples");
        OptimizerOptions options;
        options.refine = name == "optimal-refined";
        options.shear = name == "optimal-shear";
        const BaselineContext& b = context.baseline;
        const glm::dvec3 initialP4 = InitialLightAxis(*b.lightSpace, b.wsBounds, b.wsRelevant);
        OptimizerResult r =
            OptimizeLightMatrix(*context.samples, initialP4, context.baseline.map, options);
        return {r.matrix, std::move(r)};
    }
    throw std::invalid_argument("unknown 3D method '" + std::string(name) + "'");
}

}  // namespace lexel::spatial
