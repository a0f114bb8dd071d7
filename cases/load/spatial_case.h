// Loading and validating 3D case files (schema: cases/README.md, "3D cases"): the scene of
// Chong & Gortler's experiments (report §3) — camera, lights or a light sweep, resolutions, and
// geometry from primitives, model files and the floor-objects generator.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// Screen, readback and shadow-map sides are at most this many pixels or texels.
inline constexpr long long kMaxSide = 16384;

// Validates a parsed document; throws InputError naming the JSON pointer and the reason. Relative
// mesh paths are resolved against baseDir (the case file's directory).
spatial::Scene SpatialSceneFromJson(const nlohmann::json& document, const std::string& fallbackName,
                                    const std::filesystem::path& baseDir);
// Reads the file; errors are prefixed with its path.
spatial::Scene LoadSpatialScene(const std::filesystem::path& path);

// Where in a case a DomainError met while evaluating its loaded scene points, for one-line
// errors: `camera` (default "/camera") for Subject::kCamera, `light` for kLight ("/lights/k" of
// a fixed light: LightField; a description of a sweep light), "/geometry" for kGeometry.
std::string SpatialErrorField(const DomainError& e, const std::string& light,
                              const std::string& camera = "/camera");
std::string LightField(std::size_t light);      // "/lights/<light>"
std::string CameraPathField(std::size_t pose);  // "/camera_path/<pose>"

// The evaluator of a loaded scene seen from `scene.camera`; its DomainErrors become InputErrors
// naming `camera` or /geometry.
std::unique_ptr<spatial::Evaluator> MakeEvaluator(const spatial::Scene& scene,
                                                  const spatial::RenderBackend& backend,
                                                  const std::string& camera = "/camera");

}  // namespace lexel::cases
