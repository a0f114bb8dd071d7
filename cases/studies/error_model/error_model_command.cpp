// `lexel error-model` (error_model_command.h).
#include "lexel/cases/studies/error_model/error_model_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/flags.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/cases/studies/error_model/error_model_report.h"
#include "lexel/cases/studies/error_model/error_model_study.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::cases {

namespace fs = std::filesystem;

namespace {

// The single-map methods compared by default: the fair baselines' best two and `optimal`.
const std::vector<std::string> kDefaultMethods = {"focused-tight", "lispsm-tight",
                                                  spatial::kOptimalMethod};
const std::vector<std::string> kOutputs = {"error_model.csv", "error_model.json", "error_model.txt",
                                           "error_model.png"};

std::vector<std::string> ErrorModelMethods(const std::vector<std::string>& given) {
    if (given.empty()) return kDefaultMethods;
    std::vector<std::string> methods = SpatialMethods(given);
    for (const std::string& m : methods)
        if (spatial::IsPartitionedMethod(m) || spatial::IsVirtualMethod(m) ||
            spatial::IsWarpedMethod(m))
            throw InputError("--method: " + m +
                             " renders more than one map or a warped one; the error model "
                             "takes single-map methods");
    return methods;
}

void CheckPhases(int phases) {
    if (phases < 1 || phases > spatial::kMaxPhases)
        throw InputError("--phases: must be in [1, " + std::to_string(spatial::kMaxPhases) +
                         "], got " + std::to_string(phases));
}

}  // namespace

int ErrorModelCommand(const ErrorModelFlags& flags) {
    if (flags.outDir.empty()) throw InputError("--out: must name a directory, got an empty string");
    CheckPhases(flags.phases);
    const std::vector<std::string> methods = ErrorModelMethods(flags.methods);
    const fs::path casePath = flags.casePath;
    const spatial::Scene scene = LoadSceneWithOverrides(ReadCaseFile(casePath), 0, 0, 0);
    const BackendKind backend = BackendOf(flags.backend);
    std::optional<spatial::Light::Type> type;
    if (!flags.lightType.empty())
        type = flags.lightType == "point" ? spatial::Light::Type::kPoint
                                          : spatial::Light::Type::kDirectional;
    const std::vector<spatial::Light> lights =
        WithCaseName(casePath, [&] { return SweepLightsOf(scene, flags.lights, type); });
    // --out is checked before anything is computed.
    OutputSet out(flags.outDir, {{casePath}, [](const std::string& file) {
                                     return std::find(kOutputs.begin(), kOutputs.end(), file) !=
                                            kOutputs.end();
                                 }});
    Progress bar("error-model " + scene.name, lights.size(), "lights");
    const ErrorModelStudy study = WithCaseName(casePath, [&] {
        return RunErrorModelStudy(scene, methods, lights, flags.phases, backend,
                                  [&] { bar.Step(); });
    });
    const std::string text = ErrorModelText(study);
    std::cout << text;
    out.WriteText("error_model.csv", ErrorModelCsv(study));
    out.WriteText("error_model.json", ErrorModelJson(study).dump(2) + "\n");
    out.WriteText("error_model.txt", text);
    out.Writing([&] { WriteErrorModelPlot(out.Staged("error_model.png").string(), study); });
    out.Commit();
    std::cerr << "lexel: wrote error_model.csv, error_model.json, error_model.txt, "
                 "error_model.png to "
              << flags.outDir << '\n';
    return 0;
}

std::function<int()> RegisterErrorModel(CLI::App& app) {
    auto* sub = app.add_subcommand(
        "error-model",
        "3D: the error model per boundary sample against phase-averaged misclassified pixels");
    auto flags = std::make_shared<ErrorModelFlags>();
    sub->add_option("case", flags->casePath, "3D case file (JSON) with a light_sweep")
        ->required()
        ->check(CLI::ExistingFile);
    sub->add_option("--out", flags->outDir,
                    "Write error_model.csv/.json/.txt and the scatter plot error_model.png here")
        ->required();
    sub->add_option("--lights", flags->lights, "Number of hemisphere lights (default: the case's)")
        ->check(CLI::Range(1, 100000));
    sub->add_option("--light-type", flags->lightType,
                    "Sweep point or directional lights (default: the case's light_sweep type)")
        ->check(CLI::IsMember({"point", "directional"}));
    sub->add_option("--method,--methods", flags->methods,
                    "Single-map methods (default: focused-tight lispsm-tight optimal)");
    sub->add_option("--phases", flags->phases,
                    "Sub-texel phases K averaged (as on run and sweep; default 16)")
        ->check(CLI::Range(1, spatial::kMaxPhases));
    AddBackend(sub, flags->backend, "The renderer (gl: OpenGL 4.5 via EGL)");
    return [flags] { return ErrorModelCommand(*flags); };
}

}  // namespace lexel::cases
