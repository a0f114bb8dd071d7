#include "lexel/cases/app/commands.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/output_guard.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/case_methods.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/record/sweep_journal.h"
#include "lexel/cases/report/flatland_report.h"
#include "lexel/cases/report/html_report.h"
#include "lexel/cases/report/method_listing.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_frame.h"
#include "lexel/spatial/harness/mesh_loader.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/methods/registry.h"

#ifndef LEXEL_SOURCE_DATA_DIR
#define LEXEL_SOURCE_DATA_DIR ""
#endif

namespace lexel::cases {

namespace fs = std::filesystem;

fs::path DataDirectory() {
    // An installed lexel finds its data beside the binary (<prefix>/bin/lexel →
    // <prefix>/share/lexel/cases); a build tree uses the source tree's.
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "lexel" / "cases";
        if (fs::is_directory(installed / "published", error)) return installed;
    }
    return fs::path(LEXEL_SOURCE_DATA_DIR);
}

namespace {

std::string MethodLines(const std::vector<std::string>& names,
                        std::string_view (*describe)(std::string_view)) {
    std::size_t width = 0;
    for (const std::string& name : names) width = std::max(width, name.size());
    std::string lines;
    for (const std::string& name : names)
        lines += "  " + name + std::string(width + 2 - name.size(), ' ') +
                 std::string(describe(name)) + '\n';
    return lines;
}

}  // namespace

std::string MethodsHelp(bool flatland, bool spatial) {
    std::string help;
    if (flatland)
        help += "Flatland methods (default: all):\n" +
                MethodLines(flatland::FlatlandMethodNames(), &flatland::FlatlandMethodDescription);
    if (spatial)
        help += std::string(flatland ? "\n" : "") +
                "3D methods (default: all, and a case's own \"methods\", cases/README.md):\n" +
                MethodLines(spatial::SpatialMethodNames(), &spatial::SpatialMethodDescription) +
                "\n3D methods run only when named (--method):\n" +
                MethodLines(spatial::OptInMethodNames(), &spatial::SpatialMethodDescription);
    return help;
}

namespace {

int RunSpatial(const RunFlags& flags, const CaseFile& file) {
    if (flags.cases.size() != 1)
        throw InputError("run: give one 3D case at a time (got " +
                         std::to_string(flags.cases.size()) + " files)");
    if (flags.metricGiven)
        throw InputError(
            "--metric: 3D cases are measured by the report's h (eq. 6) and misclassified pixels; "
            "--metric applies to flatland cases");
    const fs::path casePath = flags.cases.front();
    const spatial::Scene scene =
        LoadSceneWithOverrides(file, flags.cascades, flags.phases, flags.maxPhases);
    SpatialRunOptions options;
    options.methods = SpatialMethodsOfCase(flags.methods, scene, false);
    WithCaseName(casePath, [&] { CheckCaseMethodLights(scene, options.methods, false); });
    options.mapTruth = flags.mapTruth;
    options.keepBuffers = !flags.outDir.empty();
    options.backend = BackendOf(flags.backend);
    NoteCpuOnlyMethods(options.methods, options.backend);
    std::optional<OutputSet> out;             // --out is checked before anything is computed
    std::optional<SweepExclusion> exclusion;  // no sweep into --out meanwhile (made after out)
    if (!flags.outDir.empty())
        out.emplace(
            flags.outDir,
            OutputPlan{{casePath}, [name = scene.name](const std::string& file) {
                           // <name>.json/.csv, <name>_light<k>_*.png, the index page
                           return file == name + ".json" || file == name + ".csv" ||
                                  (file.starts_with(name + "_light") && file.ends_with(".png")) ||
                                  file == "index.html";
                       }});
    if (!flags.outDir.empty()) exclusion.emplace(flags.outDir);
    Progress bar("run " + scene.name, SpatialRunSteps(scene, options), "steps");
    options.onStep = [&] { bar.Step(); };
    const SpatialRun run = WithCaseName(casePath, [&] { return RunSpatialCase(scene, options); });
    PrintReport(flags.format, {.json = [&] { return SpatialRunJson(scene, run); },
                               .csv = [&] { return SpatialRunCsv(run); },
                               .markdown = {},
                               .text = [&] { return SpatialRunText(scene, run); }});
    if (!out) return 0;
    Progress imageBar("run " + scene.name + ": images", SpatialImageCount(run), "images");
    const std::vector<SpatialImageFile> images = out->Writing([&] {
        return WriteSpatialImages(out->StagingDir(), scene, run, [&] { imageBar.Step(); });
    });
    out->WriteText(scene.name + ".json", SpatialRunJson(scene, run).dump(2) + "\n");
    out->WriteText(scene.name + ".csv", SpatialRunCsv(run));
    out->WriteText("index.html",
                   SpatialRunHtml(scene, run, images,
                                  {{scene.name + ".json", "every number of this run (JSON)"},
                                   {scene.name + ".csv", "one row per light and method (CSV)"}}));
    out->Commit();
    std::cerr << "lexel: wrote " << images.size() << " images, index.html and " << scene.name
              << ".json/.csv to " << flags.outDir << '\n';
    return 0;
}

// `run --out` with flatland cases writes <name>.json/.csv/.md per case (and the index page):
// refuses two cases of one name; the plan keeps the case files from being replaced.
OutputPlan FlatlandOutputPlan(const RunFlags& flags,
                              const std::vector<flatland::FlatScene>& scenes) {
    std::vector<std::string> names;
    for (const auto& scene : scenes) names.push_back(scene.name);
    RefuseDuplicateNames(names, flags.cases);
    return {{flags.cases.begin(), flags.cases.end()}, [names](const std::string& file) {
                for (const std::string& name : names)
                    if (file == name + ".json" || file == name + ".csv" || file == name + ".md")
                        return true;
                return file == "index.html";
            }};
}

int RunFlatland(const RunFlags& flags, const CaseFile& first) {
    if (flags.backend != "cpu")
        throw InputError(
            "--backend: flatland cases have no renderer; --backend applies to 3D cases");
    const std::optional<Metric> metric = ParseMetric(flags.metric);
    if (!metric)
        throw InputError("--metric: must be one of l1, l2, linf, got '" + flags.metric + "'");
    const std::vector<std::string> methods = FlatlandMethods(flags.methods);
    // Everything is computed before anything is written: a bad second case leaves no files.
    std::vector<flatland::FlatScene> scenes;
    scenes.push_back(LoadFlatScene(first));
    for (std::size_t i = 1; i < flags.cases.size(); ++i)
        scenes.push_back(LoadFlatScene(flags.cases[i]));
    std::optional<OutputSet> out;             // --out is checked before anything is computed
    std::optional<SweepExclusion> exclusion;  // no sweep into --out meanwhile (made after out)
    if (!flags.outDir.empty()) out.emplace(flags.outDir, FlatlandOutputPlan(flags, scenes));
    if (!flags.outDir.empty()) exclusion.emplace(flags.outDir);
    std::vector<flatland::CaseReport> reports;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        try {
            reports.push_back(flatland::RunFlatlandCase(scenes[i], methods, *metric));
            // The report needs no samples: each case's pass is freed before the next one runs,
            // so a run holds one case's memory at a time (flatland/memory.h).
            reports.back().fullPass.reset();
        } catch (const DomainError& e) {
            throw FlatlandInputError(flags.cases[i], e);
        }
    }
    PrintReport(flags.format, {.json = [&] { return RunJson(reports); },
                               .csv = [&] { return RunCsv(reports); },
                               .markdown = {},
                               .text =
                                   [&] {
                                       std::string text;
                                       for (std::size_t i = 0; i < reports.size(); ++i) {
                                           if (i > 0) text += '\n';
                                           text += CaseTable(reports[i]);
                                       }
                                       return text;
                                   }});
    if (!out) return 0;
    std::vector<LinkedFile> files;
    for (const auto& r : reports) {
        out->WriteText(r.caseName + ".json", CaseReportJson(r).dump(2) + "\n");
        out->WriteText(r.caseName + ".csv", RunCsv(std::span(&r, 1)));
        out->WriteText(r.caseName + ".md", CaseMarkdown(r));
        files.push_back({r.caseName + ".json", "every number of " + r.caseName + " (JSON)"});
        files.push_back({r.caseName + ".csv", "one row per method (CSV)"});
        files.push_back({r.caseName + ".md", "the table in Markdown"});
    }
    out->WriteText("index.html", FlatlandRunHtml(reports, files));
    out->Commit();
    std::cerr << "lexel: wrote index.html and " << reports.size() * 3 << " files to "
              << flags.outDir << '\n';
    return 0;
}

}  // namespace

int RunCommand(const RunFlags& flags) {
    // 3D cases (they have "lights") go to the spatial harness, one at a time.
    // Each case file is read once: the first tells which world the run is in.
    const CaseFile first = ReadCaseFile(flags.cases.front());
    if (IsSpatialCase(first.document)) return RunSpatial(flags, first);
    return RunFlatland(flags, first);
}

namespace {

// Bounds to 6 significant digits: "[x, y, z] .. [x, y, z], size [dx, dy, dz]".
std::string BoundsText(const spatial::Bounds& bounds) {
    const auto vec = [](const glm::dvec3& v) {
        char text[96];
        std::snprintf(text, sizeof text, "[%.6g, %.6g, %.6g]", v.x, v.y, v.z);
        return std::string(text);
    };
    return vec(bounds.lo) + " .. " + vec(bounds.hi) + ", size " + vec(bounds.hi - bounds.lo);
}

// The case's mesh entries whose file is `meshPath` (the same file, however the paths are spelled).
std::vector<SpatialMeshEntry> EntriesForMesh(const std::string& casePath,
                                             const fs::path& meshPath) {
    std::error_code error;
    const fs::path mesh = fs::weakly_canonical(meshPath, error);
    std::vector<SpatialMeshEntry> found, all = LoadSpatialMeshEntries(casePath);
    for (const SpatialMeshEntry& entry : all)
        if (fs::weakly_canonical(entry.file, error) == mesh) found.push_back(entry);
    if (!found.empty()) return found;
    std::string files;
    for (const SpatialMeshEntry& entry : all)
        files += (files.empty() ? "" : ", ") + entry.pointer + " " + entry.file.string();
    throw InputError(
        "--case: " + casePath + " has no mesh entry for " + meshPath.string() + " (" +
        (files.empty() ? std::string("it has no mesh entries") : "its mesh entries: " + files) +
        ")");
}

}  // namespace

int MeshInfoCommand(const std::string& meshPath, const std::string& casePath) {
    const std::vector<SpatialMeshEntry> entries =
        casePath.empty() ? std::vector<SpatialMeshEntry>{} : EntriesForMesh(casePath, meshPath);
    const spatial::LoadedMesh loaded = spatial::LoadMeshFile(meshPath);
    std::ostringstream out;  // printed whole, after everything succeeded
    out << "file: " << meshPath << "\nformat: " << loaded.format
        << "\nvertices: " << loaded.mesh.positions.size()
        << "\ntriangles: " << loaded.mesh.triangles.size()
        << "\nbounds (file units): " << BoundsText(loaded.mesh.ComputeBounds()) << '\n';
    if (entries.empty())
        out << "up axis: y (the default; a case's mesh entry sets \"up\" and \"units\")\n";
    for (const SpatialMeshEntry& entry : entries) {
        const glm::dmat4 sceneFromFile = spatial::SceneFromFile(entry.frame);
        out << casePath << " " << entry.pointer << ":\n  up axis: " << UpAxisName(entry.frame.up)
            << ", units: " << FormatNumber(entry.frame.unitScale) << " scene units per file unit"
            << "\n  bounds (scene axes and units): "
            << BoundsText(spatial::TransformMesh(loaded.mesh, sceneFromFile).ComputeBounds())
            << "\n  bounds (world, after the transform): "
            << BoundsText(
                   spatial::TransformMesh(loaded.mesh, entry.transform.Matrix() * sceneFromFile)
                       .ComputeBounds())
            << '\n';
    }
    std::cout << out.str();
    return 0;
}

int MethodsCommand(bool json) {
    std::cout << (json ? MethodListingJson() : MethodListingText());
    return 0;
}

int InfoCommand(const std::string& version) {
    std::cout << version << '\n' << DescribeBackend(BackendKind::kCpu) << '\n';
    try {
        std::cout << DescribeBackend(BackendKind::kGl) << '\n';
    } catch (const BackendUnavailable& e) {
        std::cout << "gl: unavailable: " << e.what() << '\n';
    }
    return 0;
}

}  // namespace lexel::cases
