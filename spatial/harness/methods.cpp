#include "lexel/spatial/harness/methods.h"

#include <algorithm>

namespace lexel::spatial {

BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant,
                                    std::span<const glm::dvec3> wsRelevantHull) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = scene.camera;
    context.map = scene.shadowMap;
    context.wsBounds = wsBounds;
    context.wsRelevant = wsRelevant;
    context.wsRelevantHull = wsRelevantHull;
    context.floorPlane = scene.floorPlane;
    return context;
}

std::vector<GivenMatrix> GivenMatricesOf(std::span<const CaseMethod> caseMethods,
                                         std::span<const std::string> methods, bool forSweep,
                                         std::size_t light) {
    std::vector<GivenMatrix> given;
    for (const CaseMethod& m : caseMethods)
        if (m.forSweep == forSweep && light < m.clipFromWorld.size() &&
            std::find(methods.begin(), methods.end(), m.name) != methods.end())
            given.push_back({m.name, m.clipFromWorld[light]});
    return given;
}

}  // namespace lexel::spatial
