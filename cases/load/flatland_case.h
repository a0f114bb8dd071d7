// Loading and validating flatland case files (schema: cases/README.md).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "lexel/cases/load/json_reader.h"
#include "lexel/flatland/scene.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

// Limits that keep a case within what one run can hold in memory and time.
inline constexpr long long kMaxPixels = 100'000'000;
inline constexpr long long kMaxLexels = 1'000'000'000;
inline constexpr long long kMaxWedges = 4096;

// Validates a parsed document (CheckSceneGeometry included); throws InputError naming the JSON
// pointer and the reason.
flatland::FlatScene FlatSceneFromJson(const nlohmann::json& document,
                                      const std::string& fallbackName);
flatland::FlatScene LoadFlatScene(const std::filesystem::path& path);
// The same for a file already read (ReadCaseFile).
flatland::FlatScene LoadFlatScene(const CaseFile& file);

// A DomainError met while checking or running a flatland scene, as the one line the CLI prints:
// "<source>: <field>: <reason>", the field being the JSON pointer of the camera's or the light's
// position, the geometry, a segment, or the lexel count (a segment or polyline the reason
// mentions is pointed at in parentheses).
InputError FlatlandInputError(const std::string& source, const DomainError& e);

// True when the document is a 3D case (it has "lights" or "light_sweep"); false for flatland.
bool IsSpatialCase(const nlohmann::json& document);

}  // namespace lexel::cases
