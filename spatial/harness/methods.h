// The harness's side of the method registry (spatial/methods/registry.h): the MethodContext of a
// scene's light, and a case's own methods (one clip matrix per light, which only their case
// knows: cases/README.md "Methods of a case") as the GivenMatrix entries ComputeLightMatrix looks
// up before the registry.
#pragma once

#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::spatial {

// The baselines' context for a scene: its camera, shadow-map resolution and floor plane, the
// visible points and their hull, and Algorithm 1's margin.
BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant,
                                    std::span<const glm::dvec3> wsRelevantHull = {});

// The matrices for light `light` (an index into the fixed lights, or into the sweep's lights when
// forSweep) of the scene's own methods (Scene::methods) that are among `methods` and for those
// lights; none when forSweep differs from theirs.
std::vector<GivenMatrix> GivenMatricesOf(std::span<const CaseMethod> caseMethods,
                                         std::span<const std::string> methods, bool forSweep,
                                         std::size_t light);

}  // namespace lexel::spatial
