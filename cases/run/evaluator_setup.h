// The run layer's side of a loaded 3D case: the evaluator of its scene and the check that a fixed
// light has something to light, with the DomainErrors they meet translated into one-line
// InputErrors naming the case's field (SpatialErrorField, cases/load/spatial_case.h). The loader
// parses and validates; what can only fail once the scene is rendered is translated here.
#pragma once

#include <memory>
#include <string>

#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// The evaluator of a loaded scene seen from `scene.camera`; its DomainErrors become InputErrors
// naming `camera` or /geometry.
std::unique_ptr<spatial::Evaluator> MakeEvaluator(const spatial::Scene& scene,
                                                  const spatial::RenderBackend& backend,
                                                  const std::string& camera = "/camera");

// Refuses a fixed light that no counted pixel faces (Evaluator::CountedPixels is 0: it lies in the
// plane of, or behind, every surface the camera sees), before any method runs: every count and h
// would be 0 and say nothing. `field` is the light's pointer ("/lights/k"); the error names its
// position or direction. A light sweep does not call this: such a light is kept in the sweep with
// receiver_pixels 0 (lights.csv), since one unlucky light should not abort the others.
void CheckLightFacesPixels(const spatial::Evaluator& evaluator, const spatial::Light& light,
                           const std::string& field);

}  // namespace lexel::cases
