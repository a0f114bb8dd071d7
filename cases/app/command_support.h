// What the `lexel` commands share (cases/app only): choosing and checking methods and the
// backend from the flags, loading a 3D case with --cascades and --phases, prefixing errors with the
// case's name, and printing a report in the --format chosen.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/run/backend.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// One command's report in the output format chosen by --format, on stdout: JSON (indented), CSV,
// Markdown (where the command has it) or the terminal text. Each form is made only when chosen.
struct ReportForms {
    std::function<nlohmann::json()> json;
    std::function<std::string()> csv;
    std::function<std::string()> markdown;  // empty: the command has no Markdown form
    std::function<std::string()> text;
};
void PrintReport(const std::string& format, const ReportForms& forms);

// "a, b, c": the names an error lists as known.
std::string KnownList(const std::vector<std::string>& names);

// The --method values, checked against the 3D or flatland methods (all of them when none are
// given): an unknown or repeated name is an InputError naming --method.
std::vector<std::string> SpatialMethods(std::vector<std::string> methods);
std::vector<std::string> FlatlandMethods(std::vector<std::string> methods);
// The --method values for `lexel run` or `lexel sweep` (forSweep) on `scene`: also the case's own
// methods, by default those for this command's lights (CheckCaseMethodLights checks the rest).
std::vector<std::string> SpatialMethodsOfCase(std::vector<std::string> methods,
                                              const spatial::Scene& scene, bool forSweep);

// The --backend value (main.cpp checks it is cpu or gl). For gl, says on stderr which renderer
// runs, and turns "no context" into the one-line error of --backend.
BackendKind BackendOf(const std::string& name);
// With --backend gl, one line on stderr for each method whose map the GPU does not render.
void NoteCpuOnlyMethods(const std::vector<std::string>& methods, BackendKind backend);

// Errors a runner finds after loading get the case file's name in front, like the loader's own.
template <class Body>
auto WithCaseName(const std::filesystem::path& casePath, Body body) {
    try {
        return body();
    } catch (const InputError& e) {
        throw InputError(casePath.string() + ": " + e.what());
    }
}

// The case's scene with --cascades, --phases and --max-phases applied (0: the case's own count).
// Throws InputError when the most phases end up below the phases.
spatial::Scene LoadSceneWithOverrides(const CaseFile& file, int cascades, int phases,
                                      int maxPhases);

}  // namespace lexel::cases
