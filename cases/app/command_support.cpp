#include "lexel/cases/app/command_support.h"

#include <algorithm>
#include <iostream>
#include <optional>

#include "lexel/cases/load/case_methods.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/flatland/methods.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::cases {

namespace fs = std::filesystem;

void PrintReport(const std::string& format, const ReportForms& forms) {
    if (format == "json")
        std::cout << forms.json().dump(2) << '\n';
    else if (format == "csv")
        std::cout << forms.csv();
    else if (format == "markdown" && forms.markdown)
        std::cout << forms.markdown();
    else
        std::cout << forms.text();
}

std::string KnownList(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}

namespace {

// The --method values, checked against `known` (all of them when none are given).
std::vector<std::string> MethodsOf(std::vector<std::string> methods,
                                   const std::vector<std::string>& known, const char* world) {
    if (methods.empty()) return known;
    for (auto m = methods.begin(); m != methods.end(); ++m) {
        if (std::find(known.begin(), known.end(), *m) == known.end())
            throw InputError("--method: unknown " + std::string(world) + " method '" + *m +
                             "' (known: " + KnownList(known) + ")");
        // A method given twice would run twice and print two columns of one name.
        if (std::find(methods.begin(), m, *m) != m)
            throw InputError("--method: '" + *m + "' is given twice");
    }
    return methods;
}

}  // namespace

// What --method may name: every default method and the opt-in ones (run only when named).
std::vector<std::string> NameableSpatialMethods() {
    std::vector<std::string> known = spatial::SpatialMethodNames();
    for (std::string& m : spatial::OptInMethodNames()) known.push_back(std::move(m));
    return known;
}

std::vector<std::string> SpatialMethods(std::vector<std::string> methods) {
    if (methods.empty()) return spatial::SpatialMethodNames();
    return MethodsOf(std::move(methods), NameableSpatialMethods(), "3D");
}

std::vector<std::string> SpatialMethodsOfCase(std::vector<std::string> methods,
                                              const spatial::Scene& scene, bool forSweep) {
    std::vector<std::string> known = spatial::SpatialMethodNames();
    if (methods.empty()) {
        for (std::string& m : CaseMethodNames(scene, forSweep)) known.push_back(std::move(m));
        return known;
    }
    known = NameableSpatialMethods();
    for (const spatial::CaseMethod& m : scene.methods) known.push_back(m.name);
    return MethodsOf(std::move(methods), known, "3D");
}

std::vector<std::string> FlatlandMethods(std::vector<std::string> methods) {
    return MethodsOf(std::move(methods), flatland::FlatlandMethodNames(), "flatland");
}

BackendKind BackendOf(const std::string& name) {
    const std::optional<BackendKind> kind = ParseBackend(name);
    if (!kind) throw InputError("--backend: must be cpu or gl, got '" + name + "'");
    if (*kind == BackendKind::kGl) {
        std::string description;
        try {
            description = DescribeBackend(*kind);
        } catch (const BackendUnavailable& e) {
            throw InputError("--backend gl: " + std::string(e.what()));
        }
        std::cerr << "lexel: backend " << description << '\n';
    }
    return *kind;
}

// With --backend gl, one line on stderr for each method whose map the GPU does not render
// (MethodTraits::gpuMap false: logpsm, whose logarithm is no vertex warp; its map is ray-cast on
// the CPU).
void NoteCpuOnlyMethods(const std::vector<std::string>& methods, BackendKind backend) {
    if (backend != BackendKind::kGl) return;
    for (const std::string& m : methods)
        if (!spatial::RendersOnGl(m))
            std::cerr << "lexel: note: --backend gl: " << m
                      << "'s map is ray-cast on the CPU (a logarithmic warp is no vertex warp)\n";
}

spatial::Scene LoadSceneWithOverrides(const CaseFile& file, int cascades, int phases,
                                      int maxPhases) {
    spatial::Scene scene = LoadSpatialScene(file);
    if (cascades > 0) scene.partitions.count = cascades;
    if (phases > 0) scene.phases = phases;
    if (maxPhases > 0) scene.maxPhases = maxPhases;
    if (scene.maxPhases > 0 && scene.maxPhases < scene.phases) {
        if (maxPhases > 0)
            throw InputError("--max-phases: must be at least the phases (" +
                             std::to_string(scene.phases) + "), got " +
                             std::to_string(scene.maxPhases));
        throw InputError("--phases: " + std::to_string(scene.phases) +
                         " is above the case's max_phases (" + std::to_string(scene.maxPhases) +
                         "); give --max-phases too");
    }
    return scene;
}

}  // namespace lexel::cases
