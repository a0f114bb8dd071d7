#include "lexel/cases/studies/storage/storage_command.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/commands.h"
#include "lexel/cases/app/flags.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/record/sweep_journal.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/studies/storage/storage_report.h"
#include "lexel/cases/studies/storage/storage_study.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace fs = std::filesystem;

namespace {

// The frustum `lexel storage` evaluates, as flags allow it (stated in --help): inside these
// limits every figure is finite and the warp searches converge (each corner of the box measured,
// RESULTS.md "Lloyd's storage factor"); outside, the frustum is a sliver or a plane, tan θ or the
// aspect overflow the light-space axes, or f - n falls below the searches' steps.
constexpr double kMinFovYDeg = 0.1, kMaxFovYDeg = 179.0;             // degrees
constexpr double kMinAspect = 0.01, kMaxAspect = 100.0;              // width / height
constexpr double kMinPlane = 1e-6, kMaxPlane = 1e9;                  // world units, near and far
constexpr double kMinDepthRatio = 1.0 + 1e-6, kMaxDepthRatio = 1e6;  // f / n

// The frustum flags, each checked against those limits with the flag's name.
spatial::ViewFrustum StorageFrustum(const StorageFlags& flags) {
    const auto number = [](double v) {  // the shortest text that reads back as v
        char text[32];
        return std::string(text, std::to_chars(text, text + sizeof text, v).ptr);
    };
    const auto range = [&](const char* flag, double v, double lo, double hi, const char* unit) {
        if (!(v >= lo && v <= hi))
            throw InputError(std::string(flag) + ": must be in [" + number(lo) + ", " + number(hi) +
                             "]" + unit + ", got " + number(v));
    };
    range("--fov-y", flags.fovYDeg, kMinFovYDeg, kMaxFovYDeg, " degrees");
    range("--aspect", flags.aspect, kMinAspect, kMaxAspect, "");
    range("--near", flags.nearPlane, kMinPlane, kMaxPlane, "");
    range("--far", flags.farPlane, kMinPlane, kMaxPlane, "");
    const double ratio = flags.farPlane / flags.nearPlane;
    if (!(ratio >= kMinDepthRatio && ratio <= kMaxDepthRatio))
        throw InputError("--far: must be " + number(kMinDepthRatio) + " to " +
                         number(kMaxDepthRatio) + " times --near (" + number(flags.nearPlane) +
                         "), got " + number(flags.farPlane) + " (" + number(ratio) + " times)");
    return {flags.fovYDeg, flags.aspect, flags.nearPlane, flags.farPlane};
}

int CaseStorageCommand(const StorageFlags& flags) {
    const fs::path casePath = flags.casePath;
    const spatial::Scene scene = LoadSpatialScene(casePath);
    const std::vector<std::string> methods = SpatialMethods(flags.methods);
    std::optional<OutputSet> out;             // --out is checked before anything is computed
    std::optional<SweepExclusion> exclusion;  // no sweep into --out meanwhile (made after out)
    const std::string stem = "storage_" + scene.name;
    if (!flags.outDir.empty())
        out.emplace(flags.outDir, OutputPlan{{casePath}, [stem](const std::string& file) {
                                                 return file == stem + ".json" ||
                                                        file == stem + ".csv";
                                             }});
    if (!flags.outDir.empty()) exclusion.emplace(flags.outDir);
    const CaseStorage result =
        WithCaseName(casePath, [&] { return RunCaseStorage(scene, methods); });
    PrintReport(flags.format, {.json = [&] { return CaseStorageJson(result); },
                               .csv = [&] { return CaseStorageCsv(result); },
                               .markdown = {},
                               .text = [&] { return CaseStorageText(result); }});
    if (!out) return 0;
    out->WriteText(stem + ".json", CaseStorageJson(result).dump(2) + "\n");
    out->WriteText(stem + ".csv", CaseStorageCsv(result));
    out->Commit();
    std::cerr << "lexel: wrote " << stem << ".json/.csv to " << flags.outDir << '\n';
    return 0;
}

}  // namespace

int StorageCommand(const StorageFlags& flags) {
    if (!flags.casePath.empty()) return CaseStorageCommand(flags);
    if (!flags.methods.empty())
        throw InputError("--method: applies with --case (the measured storage factor)");
    const spatial::ViewFrustum frustum = StorageFrustum(flags);
    std::optional<OutputSet> out;             // --out is checked before anything is computed
    std::optional<SweepExclusion> exclusion;  // no sweep into --out meanwhile (made after out)
    if (!flags.outDir.empty())
        out.emplace(flags.outDir,
                    OutputPlan{{}, [](const std::string& file) {
                                   return file == "storage.json" || file == "storage.csv" ||
                                          (file.starts_with("fig") && file.ends_with(".png"));
                               }});
    if (!flags.outDir.empty()) exclusion.emplace(flags.outDir);
    const StorageStudy study = RunStorageStudy(frustum);
    PrintReport(flags.format, {.json = [&] { return StorageJson(study); },
                               .csv = [&] { return StorageCsv(study); },
                               .markdown = {},
                               .text = [&] { return StorageText(study); }});
    if (!out) return 0;
    out->WriteText("storage.json", StorageJson(study).dump(2) + "\n");
    out->WriteText("storage.csv", StorageCsv(study));
    const std::vector<std::string> figures =
        out->Writing([&] { return WriteStorageFigures(out->StagingDir(), study); });
    out->Commit();
    std::cerr << "lexel: wrote storage.json, storage.csv and " << figures.size() << " figures to "
              << flags.outDir << '\n';
    return 0;
}

std::function<int()> RegisterStorage(CLI::App& app) {
    auto* storage = app.add_subcommand(
        "storage",
        "Lloyd et al. 2006's storage factor: the data and figures of Figs. 5-7, 10, 12, 13");
    auto flags = std::make_shared<StorageFlags>();
    storage->add_option("--fov-y", flags->fovYDeg, "Vertical field of view in degrees, 0.1 to 179")
        ->capture_default_str();
    storage->add_option("--aspect", flags->aspect, "Image width / height, 0.01 to 100")
        ->capture_default_str();
    storage->add_option("--near", flags->nearPlane, "Near plane n, 1e-6 to 1e9")
        ->capture_default_str();
    storage
        ->add_option("--far", flags->farPlane,
                     "Far plane f, 1e-6 to 1e9, with f/n from 1 + 1e-6 to 1e6")
        ->capture_default_str();
    auto* storageCase =
        storage
            ->add_option("--case", flags->casePath,
                         "3D case: every method's measured storage factor beside the analytic "
                         "one for the case's camera (instead of the figures)")
            ->check(CLI::ExistingFile);
    for (const char* flag : {"--fov-y", "--aspect", "--near", "--far"})
        storageCase->excludes(storage->get_option(flag));
    storage->add_option("--method", flags->methods,
                        "With --case: methods (default: all; listed below)");
    storage->footer(MethodsHelp(false, true));
    storage->add_option("--format", flags->format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    storage
        ->add_option("--out", flags->outDir,
                     "Also write storage.json, storage.csv and the figures (PNG) here")
        ->check(NonEmpty("a directory"));
    return [flags] { return StorageCommand(*flags); };
}

}  // namespace lexel::cases
