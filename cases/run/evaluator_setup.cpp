#include "lexel/cases/run/evaluator_setup.h"

#include <cstddef>
#include <cstdint>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

std::unique_ptr<spatial::Evaluator> MakeEvaluator(const spatial::Scene& scene,
                                                  const spatial::RenderBackend& backend,
                                                  const std::string& camera) {
    try {
        return std::make_unique<spatial::Evaluator>(scene, backend);
    } catch (const DomainError& e) {
        throw InputError(SpatialErrorField(e, "/lights", camera) + ": " + e.what());
    }
}

void CheckLightFacesPixels(const spatial::Evaluator& evaluator, const spatial::Light& light,
                           const std::string& field) {
    std::int64_t counted = 0;
    try {
        counted = evaluator.CountedPixels(light);
    } catch (const DomainError& e) {
        throw InputError(SpatialErrorField(e, field) + ": " + e.what());
    }
    if (counted > 0) return;
    const spatial::CameraBuffer& frame = evaluator.frame();
    std::int64_t visible = 0;
    for (std::size_t i = 0; i < frame.triangle.size(); ++i) visible += frame.Covered(i);
    const bool point = light.type == spatial::Light::Type::kPoint;
    throw InputError(field + (point ? "/position" : "/direction") +
                     ": no visible pixel faces the light: all " + std::to_string(visible) +
                     " pixels the camera sees have n·l <= 0 (the light lies in the plane of, or "
                     "behind, every surface in view), so every count and h would be 0");
}

}  // namespace lexel::cases
