// A case's name is the stem of the files written for it (<out>/<name>.json, lowres_<name>.png,
// <name>_<method>_*.png, ...), so it must name one plain file inside --out and nothing else
// (schema: cases/README.md, "name").
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "lexel/cases/load/json_reader.h"

namespace lexel::cases {

// Longest accepted name, in bytes: with the longest suffix a report adds (about 60 bytes for a
// 3D image) a file name stays well under the 255 bytes of common file systems.
inline constexpr std::size_t kMaxCaseNameBytes = 100;

// Why `name` is not a safe file stem, or nullopt when it is. Refused: empty; longer than
// kMaxCaseNameBytes bytes; containing '/', '\', "..", or a control character (U+0000–U+001F,
// U+007F); not UTF-8 (a file stem of Latin-1 bytes, say: the JSON reports hold UTF-8 only). The
// reason never echoes the name (it may hold control characters).
std::optional<std::string> CaseNameProblem(std::string_view name);

// The case's name: the document's /name when it has one, else `fallbackName` (the case file's
// stem). Throws InputError "/name: <reason>" when the chosen name is not a safe file stem.
std::string CaseNameOf(const JsonField& root, const std::string& fallbackName);

}  // namespace lexel::cases
