// The named light-matrix methods of the 3D harness (report §3): one registry so that `lexel run`,
// `lexel sweep` and the tests agree on names, order and inputs.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// The baselines' context for a scene: its camera, shadow-map resolution and floor plane.
BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant);

struct MethodContext {
    BaselineContext baseline;               // light space, camera, map, bounds, visible points
    const LightSamples* samples = nullptr;  // boundary samples and relevant points (light space)
};

// Every method, in the column order of the report's Table 1 followed by the extra ones.
std::vector<std::string> SpatialMethodNames();
bool IsSpatialMethod(std::string_view name);
// The matrix, and for `optimal`, `optimal-refined` and `optimal-shear` the optimizer's trace (h
// per iteration, time profile). `optimal` is Algorithm 1 as published (initial axis: focused's)
// without the optional affine shear; `optimal-refined` adds the Ceres refinement on the unit
// sphere; `optimal-shear` is Algorithm 1 with the shear (report Fig. 3, optimized exactly:
// FitOptions::shear), no refinement.
struct MethodMatrix {
    LightMatrix matrix;
    std::optional<OptimizerResult> optimizer;
};
MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context);

}  // namespace lexel::spatial
