// Loading and validating 3D case files (schema: cases/README.md, "3D cases"): the scene of
// Chong & Gortler's experiments (report §3) — camera, lights or a light sweep, resolutions, and
// geometry from primitives, model files and the floor-objects generator.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

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

}  // namespace lexel::cases
