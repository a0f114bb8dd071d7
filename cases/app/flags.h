// The flags several `lexel` commands share (CLI11), for the product's commands (main.cpp) and the
// studies' (cases/studies/<name>/<name>_command.cpp) alike.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace lexel::cases {

// A flag given as an empty string (`--out ''`) is refused rather than taken for "not given".
CLI::Validator NonEmpty(const std::string& what);

// --backend cpu|gl, described by `what`.
CLI::Option* AddBackend(CLI::App* sub, std::string& backend, const std::string& what);

// --phases K: each 3D method's errors averaged over K sub-texel phases of its map(s);
// --max-phases N: raised, doubling, up to N phases where the mean's residual is above 2%.
void AddPhases(CLI::App* sub, int& phases, int& maxPhases);

}  // namespace lexel::cases
