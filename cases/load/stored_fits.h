// The committed fits of the thesis scenes (cases/flatland/fitted/parameters.json, written by
// `lexel fit-thesis`; schema: cases/README.md): per case, its scene family's parameters and the
// agreement its fitted case file reached with the published table.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace lexel::cases {

struct StoredFit {
    std::string caseName;            // the family's name, a thesis case's file stem
    std::vector<double> parameters;  // in the family's order (flatland/studies/scene_family.h)
    double worstAngleDeg = NAN;      // max |angle error|, degrees
    double worstFootprint = NAN;     // max |relative footprint error|
};

// Reads a parameters file; a missing file gives an empty list. Throws InputError naming the file,
// the JSON pointer and the reason: an unknown case, an unknown or missing parameter, a value
// outside its family's range.
std::vector<StoredFit> LoadStoredFits(const std::filesystem::path& path);

}  // namespace lexel::cases
