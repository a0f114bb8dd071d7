// Algorithm 1's standard map (standard_map.h): focused-tight over the readback's visible points.
#include "lexel/spatial/standard_map.h"

#include "lexel/solvers/errors.h"
#include "lexel/spatial/baselines.h"

namespace lexel::spatial {

LightMatrix StandardLightMatrix(const Readback& readback, const LightSpace& lightSpace,
                                const Bounds& wsSceneBounds, Resolution map) {
    if (readback.wsRelevant.empty())
        throw DomainError(Subject::kCamera, "the camera sees nothing: no visible points");
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.map = map;
    context.wsBounds = wsSceneBounds;
    context.wsRelevant = readback.wsRelevant;
    context.wsRelevantHull = readback.wsRelevantHull;
    context.margin = kStandardMapMargin;
    return FocusedTightLightMatrix(context);
}

}  // namespace lexel::spatial
