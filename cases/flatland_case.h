// Loading and validating flatland case files (schema: cases/README.md).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "lexel/flatland/scene.h"

namespace lexel::cases {

// Limits that keep a case within what one run can hold in memory and time.
inline constexpr long long kMaxPixels = 100'000'000;
inline constexpr long long kMaxLexels = 1'000'000'000;
inline constexpr long long kMaxWedges = 4096;

// Validates a parsed document; throws InputError naming the JSON pointer and the reason.
flatland::FlatScene FlatSceneFromJson(const nlohmann::json& document,
                                      const std::string& fallbackName);
flatland::FlatScene LoadFlatScene(const std::filesystem::path& path);

// True when the document is a 3D case (it has "lights" or "light_sweep"); false for flatland.
bool IsSpatialCase(const nlohmann::json& document);

}  // namespace lexel::cases
