// A 3D case's own methods (`methods`, cases/README.md "Methods of a case"): per method a name and
// one OpenGL clip matrix per light, inline (`clip_from_world`, row-major 4×4s) or from a CSV file
// (`clip_from_world_csv`, one row of 16 numbers per light), evaluated like the built-in methods.
// Only this loader knows their JSON pointers; the harness sees spatial::CaseMethod.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "lexel/cases/load/json_reader.h"
#include "lexel/spatial/bounds.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// The largest clip_from_world_csv file read (bytes): 100 000 lights of 16 numbers each.
inline constexpr std::size_t kMaxClipCsvBytes = std::size_t{64} << 20;

// A method as read, with where each of its matrices came from ("/methods/0/clip_from_world/3",
// or "/methods/0/clip_from_world_csv: FILE:LINE") for the checks that need the whole scene.
struct CaseMethodEntry {
    spatial::CaseMethod method;
    std::vector<std::string> where;  // per matrix
};

// Reads `methods` (an array of {"name", one of "clip_from_world", "clip_from_world_csv"}) of a
// case whose lights and light_sweep are already in `scene`. A method's matrices are for the fixed
// lights when their count is the fixed lights' (lexel run), else for the sweep's lights when it is
// light_sweep.count (lexel sweep). Throws InputError naming the field: a name that is not a
// method name (IsValidMethodName) or is a built-in or registered method's or repeats an earlier
// one; a matrix that is not 4 rows of 4 finite numbers; a CSV row without 16 finite numbers or a
// CSV file that cannot be read; a count that fits neither set of lights.
std::vector<CaseMethodEntry> ReadCaseMethods(const JsonField& methods, const spatial::Scene& scene,
                                             const std::filesystem::path& baseDir);

// The checks that need the geometry: every matrix is invertible in the scene's unit frame (|det|
// at least 1e-12 of the product of its rows' lengths there) and projects from its light (its x,
// y and w rows send the light to infinity: LightMatrixFromClip, clip_matrix.h), the sweep's
// lights being those of light_sweep. Throws InputError naming the matrix.
void CheckCaseMethodMatrices(const std::vector<CaseMethodEntry>& entries,
                             const spatial::Scene& scene, const spatial::Bounds& wsBounds);

// The case's methods for `lexel sweep` (forSweep) or `lexel run`, in case order.
std::vector<std::string> CaseMethodNames(const spatial::Scene& scene, bool forSweep);

// Every case method among `methods` is one for this command (forSweep: lexel sweep, else lexel
// run); for a sweep over `lights` (the case's light_sweep, its count or type possibly changed on
// the command line) it has a matrix for each light and each projects from its light. Throws
// InputError "/methods/i: ..." otherwise.
void CheckCaseMethodLights(const spatial::Scene& scene, const std::vector<std::string>& methods,
                           bool forSweep, const std::vector<spatial::Light>& lights = {});

}  // namespace lexel::cases
