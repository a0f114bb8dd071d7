// `lexel run` on a 3D case: per fixed light and method the misclassified pixels, h and time as
// terminal text, one JSON document and CSV (schemas in cases/README.md), the camera-path study,
// and the images (frame, error map, shadow map with samples) per light and method.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "lexel/cases/run/spatial_run.h"

namespace lexel::cases {

std::string SpatialRunText(const spatial::Scene& scene, const SpatialRun& run);
nlohmann::json SpatialRunJson(const spatial::Scene& scene, const SpatialRun& run);
std::string SpatialRunCsv(const SpatialRun& run);

// <case>_light<k>_<method>_{frame,errors,map}.png in `dir` (the run must have kept its buffers);
// returns how many files were written. Throws std::runtime_error when a file cannot be written.
int WriteSpatialImages(const std::filesystem::path& dir, const spatial::Scene& scene,
                       const SpatialRun& run);

}  // namespace lexel::cases
