#include "lexel/cases/app/commands.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <optional>
#include <sstream>

#include "lexel/cases/app/output_guard.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/case_methods.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/published.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/load/sweep_record_reader.h"
#include "lexel/cases/report/figures.h"
#include "lexel/cases/report/fit_report.h"
#include "lexel/cases/report/flatland_report.h"
#include "lexel/cases/report/html_report.h"
#include "lexel/cases/report/lowres_report.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/report/storage_report.h"
#include "lexel/cases/report/sweep_journal.h"
#include "lexel/cases/report/sweep_record.h"
#include "lexel/cases/report/sweep_report.h"
#include "lexel/cases/report/tables_report.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/report/timing_report.h"
#include "lexel/cases/run/cascade_study.h"
#include "lexel/cases/run/lowres.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/cases/run/storage.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/cases/run/sweep_share.h"
#include "lexel/cases/run/thesis_tables.h"
#include "lexel/cases/run/timing.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_frame.h"
#include "lexel/spatial/harness/mesh_loader.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/harness/warped_methods.h"

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

// One command's report in the output format chosen by --format, on stdout: JSON (indented), CSV,
// Markdown (where the command has it) or the terminal text. Each form is made only when chosen.
struct ReportForms {
    std::function<nlohmann::json()> json;
    std::function<std::string()> csv;
    std::function<std::string()> markdown;  // empty: the command has no Markdown form
    std::function<std::string()> text;
};

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
                MethodLines(spatial::SpatialMethodNames(), &spatial::SpatialMethodDescription);
    return help;
}

namespace {

std::string KnownList(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return list;
}

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

std::vector<std::string> SpatialMethods(std::vector<std::string> methods) {
    return MethodsOf(std::move(methods), spatial::SpatialMethodNames(), "3D");
}

// The --method values for `lexel run` or `lexel sweep` (forSweep) on `scene`: also the case's own
// methods, by default those for this command's lights (CheckCaseMethodLights checks the rest).
std::vector<std::string> SpatialMethodsOfCase(std::vector<std::string> methods,
                                              const spatial::Scene& scene, bool forSweep) {
    std::vector<std::string> known = spatial::SpatialMethodNames();
    if (methods.empty()) {
        for (std::string& m : CaseMethodNames(scene, forSweep)) known.push_back(std::move(m));
        return known;
    }
    for (const spatial::CaseMethod& m : scene.methods) known.push_back(m.name);
    return MethodsOf(std::move(methods), known, "3D");
}

std::vector<std::string> FlatlandMethods(std::vector<std::string> methods) {
    return MethodsOf(std::move(methods), flatland::FlatlandMethodNames(), "flatland");
}

// The --backend value (main.cpp checks it is cpu or gl). For gl, says on stderr which renderer
// runs, and turns "no context" into the one-line error of --backend.
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
// (logpsm: a logarithm is no vertex warp, its map is ray-cast on the CPU: warped_methods.h).
void NoteCpuOnlyMethods(const std::vector<std::string>& methods, BackendKind backend) {
    if (backend != BackendKind::kGl) return;
    for (const std::string& m : methods)
        if (spatial::IsWarpedMethod(m) && !spatial::WarpedMethodRendersOnGl(m))
            std::cerr << "lexel: note: --backend gl: " << m
                      << "'s map is ray-cast on the CPU (a logarithmic warp is no vertex warp)\n";
}

// Errors a runner finds after loading get the case file's name in front, like the loader's own.
template <class Body>
auto WithCaseName(const fs::path& casePath, Body body) {
    try {
        return body();
    } catch (const InputError& e) {
        throw InputError(casePath.string() + ": " + e.what());
    }
}

// The case's scene with --cascades applied.
spatial::Scene LoadSceneWithCascades(const CaseFile& file, int cascades) {
    spatial::Scene scene = LoadSpatialScene(file);
    if (cascades > 0) scene.partitions.count = cascades;
    return scene;
}
spatial::Scene LoadSceneWithCascades(const fs::path& casePath, int cascades) {
    return LoadSceneWithCascades(ReadCaseFile(casePath), cascades);
}

int RunSpatial(const RunFlags& flags, const CaseFile& file) {
    if (flags.cases.size() != 1)
        throw InputError("run: give one 3D case at a time (got " +
                         std::to_string(flags.cases.size()) + " files)");
    if (flags.metricGiven)
        throw InputError(
            "--metric: 3D cases are measured by the report's h (eq. 6) and misclassified pixels; "
            "--metric applies to flatland cases");
    const fs::path casePath = flags.cases.front();
    const spatial::Scene scene = LoadSceneWithCascades(file, flags.cascades);
    SpatialRunOptions options;
    options.methods = SpatialMethodsOfCase(flags.methods, scene, false);
    WithCaseName(casePath, [&] { CheckCaseMethodLights(scene, options.methods, false); });
    options.mapTruth = flags.mapTruth;
    options.keepBuffers = !flags.outDir.empty();
    options.backend = BackendOf(flags.backend);
    NoteCpuOnlyMethods(options.methods, options.backend);
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!flags.outDir.empty())
        out.emplace(
            flags.outDir,
            OutputPlan{{casePath}, [name = scene.name](const std::string& file) {
                           // <name>.json/.csv, <name>_light<k>_*.png, the index page
                           return file == name + ".json" || file == name + ".csv" ||
                                  (file.starts_with(name + "_light") && file.ends_with(".png")) ||
                                  file == "index.html";
                       }});
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
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!flags.outDir.empty()) out.emplace(flags.outDir, FlatlandOutputPlan(flags, scenes));
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

// For `lexel sweep --out`: the frame, errors and per-cascade maps of the partitioned methods for
// the sweep's first light.
std::vector<SpatialImageFile> WriteFirstLightCascades(const fs::path& dir,
                                                      const spatial::Scene& scene,
                                                      const SweepResult& r, BackendKind backend) {
    SpatialRunOptions options;
    options.backend = backend;
    for (const std::string& m : r.methods)
        if (spatial::IsPartitionedMethod(m)) options.methods.push_back(m);
    if (options.methods.empty() || r.lights.empty()) return {};
    options.mapTruth = false;
    options.keepBuffers = true;
    spatial::Scene first = scene;
    first.lights = {r.lights.front()};
    first.cameraPath.clear();
    const SpatialRun run = RunSpatialCase(first, options);
    return WriteSpatialImages(dir, first, run);
}

// What `lexel sweep --out` writes: the tables, the per-light data, the cascade-count study, the
// first light's images and the index page; the case file itself is never replaced.
OutputPlan SweepOutputPlan(const fs::path& casePath, const std::string& name) {
    return {{casePath}, [name](const std::string& file) {
                for (const char* fixed :
                     {"table1.md", "table1.csv", "sweep.json", "lights.csv", "sweep-record.json",
                      "cascades.csv", "cascades.png", "index.html"})
                    if (file == fixed) return true;
                return file.starts_with(name + "_light") && file.ends_with(".png");
            }};
}

// Stages every `lexel sweep --out` (and `lexel merge`) file: `stageImages` writes the first
// light's images when the study ran and this share holds light 0 (the sweep draws them, a merge
// copies them), and the record gets their list. Returns what was written, for the closing line.
std::string StageSweepFiles(OutputSet& out, const SweepResult& r, const ReportTable1& report,
                            const CascadeCountStudy* study, SweepRecord record,
                            const std::function<std::vector<SpatialImageFile>()>& stageImages) {
    out.WriteText("table1.md", SweepMarkdown(r, report));
    out.WriteText("table1.csv", SweepCsv(r, report));
    out.WriteText("sweep.json", SweepJson(r).dump(2) + "\n");
    out.WriteText("lights.csv", SweepLightsCsv(r));
    std::vector<LinkedFile> files = {
        {"table1.md", "the tables above in Markdown"},
        {"table1.csv", "the tables above, one row per table, set of lights and method (CSV)"},
        {"sweep.json", "every number of the tables (JSON)"},
        {"lights.csv",
         "one row per light: its position, counted pixels, and every method's "
         "misclassified pixels, h and time"},
        {"sweep-record.json",
         "every cell of the sweep, losslessly, for lexel merge (JSON, cases/README.md)"}};
    std::string written =
        "index.html, table1.md, table1.csv, sweep.json, lights.csv, "
        "sweep-record.json";
    std::vector<SpatialImageFile> images;
    if (study) {
        out.WriteText("cascades.csv", CascadeStudyCsv(*study));
        out.Writing([&] { WriteCascadeStudyPlot(out.Staged("cascades.png").string(), *study, r); });
        if (stageImages) images = stageImages();
        files.push_back({"cascades.csv", "mean misclassified pixels per method and k"});
        files.push_back({"cascades.png", "the same as a plot"});
        written += ", cascades.csv, cascades.png and " + std::to_string(images.size()) +
                   " images of the first light";
    }
    record.images = images;
    out.WriteText("sweep-record.json", SweepRecordText(record));
    out.WriteText("index.html",
                  SweepHtml(r, report, study, study ? "cascades.png" : "", images, files));
    return written;
}

// Prints the sweep's tables in `format` (table: with `closing`, the line after them).
void PrintSweep(const SweepResult& r, const ReportTable1& report, const std::string& format,
                const std::string& closing) {
    PrintReport(format, {.json = [&] { return SweepJson(r); },
                         .csv = [&] { return SweepCsv(r, report); },
                         .markdown = [&] { return SweepMarkdown(r, report); },
                         .text = [&] { return SweepTable(r, report) + closing + "\n"; }});
}

// The --shard value "K/N": N ≥ 1, 0 ≤ K < N, both decimal integers.
SweepShard ShardOf(const std::string& text) {
    const std::size_t slash = text.find('/');
    const auto number = [](std::string_view digits, std::size_t& value) {
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), value);
        return !digits.empty() && error == std::errc() && end == digits.data() + digits.size();
    };
    SweepShard shard;
    if (slash == std::string::npos ||
        !number(std::string_view(text).substr(0, slash), shard.index) ||
        !number(std::string_view(text).substr(slash + 1), shard.count) || shard.count < 1 ||
        shard.index >= shard.count)
        throw InputError(
            "--shard: must be K/N with N >= 1 and K = 0 ... N-1 (light i belongs to "
            "shard i mod N), got '" +
            text + "'");
    return shard;
}

std::string FileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) throw InputError(path.string() + ": cannot be read");
    return bytes;
}

// One line on stderr for a resumed run: how many of its lights its journal held.
void SayResumed(const SweepDone& done, std::size_t lights, std::size_t studyLights,
                const SweepJournal& journal) {
    std::cerr << "lexel: resuming from " << journal.Path().string() << ": " << done.lights.size()
              << " of " << lights << " lights done";
    if (studyLights > 0)
        std::cerr << ", " << done.study.size() << " of " << studyLights
                  << " lights of the partitions study";
    std::cerr << '\n';
}

// A share's evaluation: its lights and, with `withStudy`, the partitions study; each light
// finished is appended to `journal` (when there is one) and those it holds are not evaluated.
struct ShareRun {
    SweepResult result;
    StudyMisclassified study;
};
ShareRun RunShare(const fs::path& casePath, const spatial::Scene& scene,
                  const std::vector<std::string>& methods,
                  const std::vector<spatial::Light>& lights,
                  const std::vector<std::size_t>& indices, bool withStudy, SweepJournal* journal,
                  BackendKind backend) {
    const SweepDone done = journal ? journal->Done() : SweepDone{};
    ShareRun run;
    run.result = WithCaseName(casePath, [&] {
        Progress bar("sweep", indices.size() - done.lights.size(), "lights");
        return RunSweepShare(
            scene, methods, lights, indices, done,
            [&](const SweepLightRecord& light) {
                if (journal) journal->Append(JournalLightLine(light));
                bar.Step();
            },
            backend);
    });
    if (!withStudy) return run;
    run.study = WithCaseName(casePath, [&] {
        const std::size_t studyLights =
            CascadeStudyExtraCounts(scene.partitions.count).size() * indices.size();
        Progress bar("partitions k = 1, 2, 4, 8", studyLights - done.study.size(), "lights");
        return RunStudyShare(
            scene, run.result, done,
            [&](const StudyLightRecord& light) {
                if (journal) journal->Append(JournalStudyLine(light));
                bar.Step();
            },
            backend);
    });
    return run;
}

// The sweep's lights (--lights, --light-type) and the indices of shard's share of them.
std::vector<spatial::Light> SweepLightsFor(const fs::path& casePath, const spatial::Scene& scene,
                                           const SweepFlags& flags) {
    std::optional<spatial::Light::Type> type;
    if (!flags.lightType.empty())
        type = flags.lightType == "point" ? spatial::Light::Type::kPoint
                                          : spatial::Light::Type::kDirectional;
    return WithCaseName(casePath, [&] { return SweepLightsOf(scene, flags.lights, type); });
}

std::vector<std::size_t> ShareOf(std::size_t lights, SweepShard shard) {
    std::vector<std::size_t> indices = ShardLights(lights, shard);
    if (indices.empty())
        throw InputError("--shard " + ShardText(shard) + ": the sweep has " +
                         std::to_string(lights) + " lights, so this shard has none (give " +
                         "at most " + std::to_string(lights) + " shards)");
    return indices;
}

}  // namespace

int SweepCommand(const SweepFlags& flags) {
    const SweepShard shard = ShardOf(flags.shard);
    if (flags.resume && flags.outDir.empty())
        throw InputError("--resume: continues a sweep into its --out directory; give --out");
    const fs::path casePath = flags.casePath;
    const spatial::Scene scene = LoadSceneWithCascades(casePath, flags.cascades);
    const std::vector<std::string> methods = SpatialMethodsOfCase(flags.methods, scene, true);
    const BackendKind backend = BackendOf(flags.backend);
    NoteCpuOnlyMethods(methods, backend);
    const ReportTable1 report =
        LoadReportTable1(DataDirectory() / "published" / "report_table1.json");
    const std::vector<spatial::Light> lights = SweepLightsFor(casePath, scene, flags);
    WithCaseName(casePath, [&] { CheckCaseMethodLights(scene, methods, true, lights); });
    const std::vector<std::size_t> indices = ShareOf(lights.size(), shard);
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!flags.outDir.empty()) out.emplace(flags.outDir, SweepOutputPlan(casePath, scene.name));
    const SweepIdentity identity{scene.name,        Fnv1a64Hex(FileBytes(casePath)), methods,
                                 flags.backend,     scene.partitions.count,          lights.size(),
                                 LightsHash(lights)};
    // With --out: the cascade-count study, and the journal of the finished lights.
    const bool withStudy = out && !CascadeStudyMethods(methods).empty();
    const std::vector<int> studyCounts =
        withStudy ? CascadeStudyExtraCounts(scene.partitions.count) : std::vector<int>{};
    std::optional<SweepJournal> journal;
    if (out) journal.emplace(SweepJournal::PathFor(flags.outDir), identity, shard, flags.resume);
    if (flags.resume)
        SayResumed(journal->Done(), indices.size(), studyCounts.size() * indices.size(), *journal);
    const ShareRun run = RunShare(casePath, scene, methods, lights, indices, withStudy,
                                  journal ? &*journal : nullptr, backend);
    const SweepResult& r = run.result;
    std::optional<CascadeCountStudy> study;
    if (withStudy) study = CascadeStudyOf(r, scene.partitions.count, run.study);
    PrintSweep(r, report, flags.format,
               "sweep: " + Fixed(r.seconds, 1) + " s for " + std::to_string(r.lights.size()) +
                   " lights" + (shard.count > 1 ? " (shard " + ShardText(shard) + ")" : ""));
    if (!out) return 0;
    // The first light's cascades (light 0's shard's) are drawn before anything is published.
    const auto stageImages = [&] {
        if (r.indices.front() != 0) return std::vector<SpatialImageFile>{};
        return WithCaseName(casePath, [&] {
            return out->Writing(
                [&] { return WriteFirstLightCascades(out->StagingDir(), scene, r, backend); });
        });
    };
    const std::string written =
        StageSweepFiles(*out, r, report, study ? &*study : nullptr,
                        RecordOf(identity, shard, r, studyCounts, run.study, {}), stageImages);
    out->Commit();
    std::cerr << "lexel: wrote " << written << " to " << flags.outDir << '\n';
    return 0;
}

namespace {

// Copies `from` into the staging directory as `name`, byte for byte.
void StageCopy(OutputSet& out, const fs::path& from, const std::string& name) {
    std::error_code error;
    if (!fs::copy_file(from, out.Staged(name), error))
        throw std::runtime_error(from.string() + ": cannot copy (" + error.message() + ")");
}

}  // namespace

int MergeCommand(const MergeFlags& flags) {
    std::vector<SweepRecord> records;
    for (const std::string& dir : flags.dirs) records.push_back(ReadSweepRecord(dir));
    const MergedSweep merged = MergeRecords(records, flags.dirs);
    const SweepIdentity& id = merged.record.identity;
    // No output may replace a shard's record or image (a shard directory given as --out).
    OutputPlan plan = SweepOutputPlan("", id.caseName);
    plan.inputs.clear();
    for (std::size_t d = 0; d < flags.dirs.size(); ++d) {
        plan.inputs.push_back(fs::path(flags.dirs[d]) / "sweep-record.json");
        for (const SpatialImageFile& image : records[d].images)
            plan.inputs.push_back(fs::path(flags.dirs[d]) / image.file);
    }
    OutputSet out(flags.outDir, plan);
    const ReportTable1 report =
        LoadReportTable1(DataDirectory() / "published" / "report_table1.json");
    std::optional<CascadeCountStudy> study;
    if (!merged.record.studyCounts.empty())
        study = CascadeStudyOf(merged.result, id.cascades, merged.record.study);
    PrintSweep(merged.result, report, flags.format,
               "merge: " + std::to_string(merged.result.lights.size()) + " lights from " +
                   std::to_string(records.size()) + " shards (" + Fixed(merged.record.seconds, 1) +
                   " s of sweeping)");
    const auto stageImages = [&] {
        if (merged.imagesFrom < 0) return std::vector<SpatialImageFile>{};
        for (const SpatialImageFile& image : merged.record.images)
            StageCopy(out, fs::path(flags.dirs[merged.imagesFrom]) / image.file, image.file);
        return merged.record.images;
    };
    const std::string written = StageSweepFiles(
        out, merged.result, report, study ? &*study : nullptr, merged.record, stageImages);
    out.Commit();
    std::cerr << "lexel: wrote " << written << " to " << flags.outDir << '\n';
    return 0;
}

int TimingCommand(const TimingFlags& flags) {
    const fs::path casePath = flags.casePath;
    const spatial::Scene scene = LoadSpatialScene(casePath);
    TimingOptions options;
    options.backend = BackendOf(flags.backend);
    options.lights = flags.lights;
    options.frames = flags.frames;
    options.updateEvery = flags.updateEvery;
    options.standardEvery = flags.standardEvery;
    options.optimal = flags.optimizer;
    const ReportTiming report =
        LoadReportTiming(DataDirectory() / "published" / "report_timing.json");
    Progress bar("timing", static_cast<std::size_t>(options.frames) + 1, "frames");
    options.onFrameDone = [&] { bar.Step(); };
    const TimingRun run = WithCaseName(casePath, [&] { return RunTiming(scene, options); });
    PrintReport(flags.format, {.json = [&] { return TimingJson(scene, run, report); },
                               .csv = [&] { return TimingCsv(run); },
                               .markdown = {},
                               .text = [&] { return TimingText(scene, run, report); }});
    return 0;
}

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
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    const std::string stem = "storage_" + scene.name;
    if (!flags.outDir.empty())
        out.emplace(flags.outDir, OutputPlan{{casePath}, [stem](const std::string& file) {
                                                 return file == stem + ".json" ||
                                                        file == stem + ".csv";
                                             }});
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
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!flags.outDir.empty())
        out.emplace(flags.outDir,
                    OutputPlan{{}, [](const std::string& file) {
                                   return file == "storage.json" || file == "storage.csv" ||
                                          (file.starts_with("fig") && file.ends_with(".png"));
                               }});
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

int InfoCommand(const std::string& version) {
    std::cout << version << '\n' << DescribeBackend(BackendKind::kCpu) << '\n';
    try {
        std::cout << DescribeBackend(BackendKind::kGl) << '\n';
    } catch (const BackendUnavailable& e) {
        std::cout << "gl: unavailable: " << e.what() << '\n';
    }
    return 0;
}

int TablesCommand(const std::string& outDir, const std::string& casesDir) {
    const std::vector<ThesisTable> tables =
        LoadThesisTables(DataDirectory() / "published" / "thesis_tables.json");
    const fs::path dir = casesDir.empty() ? DataDirectory() / "flatland" : fs::path(casesDir);
    // Checked before anything is computed: tables.md/.csv, lowres.csv, <case file stem>.png,
    // lowres_<name>.png (the name is the case's, read later); the inputs are the thesis cases and
    // their fitted versions. Other PNGs in DIR are not the command's.
    std::vector<std::string> figures;
    for (const ThesisTable& thesis : tables)
        figures.push_back(fs::path(thesis.file).stem().string() + ".png");
    OutputPlan plan{{}, [figures](const std::string& file) {
                        return file == "tables.md" || file == "tables.csv" ||
                               file == "lowres.csv" ||
                               std::find(figures.begin(), figures.end(), file) != figures.end() ||
                               (file.starts_with("lowres_") && file.ends_with(".png"));
                    }};
    for (const ThesisTable& thesis : tables) {
        plan.inputs.push_back(dir / thesis.file);
        plan.inputs.push_back(dir / "fitted" / thesis.file);
    }
    OutputSet out(outDir, std::move(plan));
    const std::vector<TableResult> results = RunThesisTables(tables, dir);
    std::vector<std::vector<LowresRow>> lowres;
    std::vector<std::pair<std::string, std::vector<LowresRow>>> studies;
    for (const auto& r : results) {
        lowres.push_back(RunLowresStudy(r.scene));
        studies.emplace_back(r.scene.name, lowres.back());
    }
    std::cout << TablesText(results);
    for (const auto& [name, rows] : studies) std::cout << LowresText(name, rows) << '\n';
    const std::string summary = LowresSummary(results, lowres);
    std::cout << WrapText(summary);

    std::string markdown =
        TablesMarkdown(results) + "## Low-resolution decision (thesis 4.1.1, Fig. 4.1)\n\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const std::string& name = results[i].scene.name;
        const std::string stem = fs::path(results[i].thesis.file).stem().string();
        out.Writing([&] {
            WriteCaseFigure(out.Staged(stem + ".png").string(), results[i].scene,
                            results[i].report);
            WriteLowresPlot(out.Staged("lowres_" + name + ".png").string(),
                            "Low-resolution decision: " + name, LowresCurves(lowres[i]));
        });
        markdown += LowresMarkdown(name, lowres[i]);
    }
    markdown += summary;
    out.WriteText("tables.md", markdown);
    out.WriteText("tables.csv", TablesCsv(results));
    out.WriteText("lowres.csv", LowresCsv(studies));
    out.Commit();
    std::cout << "\nlexel: wrote tables.md, tables.csv, lowres.csv and " << 2 * results.size()
              << " figures to " << fs::absolute(outDir).string() << '\n';
    return 0;
}

int LowresCommand(const std::string& casePath, const std::string& outDir) {
    const flatland::FlatScene scene = LoadFlatScene(casePath);
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!outDir.empty())
        out.emplace(outDir, OutputPlan{{casePath}, [name = scene.name](const std::string& file) {
                                           return file == "lowres_" + name + ".md" ||
                                                  file == "lowres_" + name + ".png";
                                       }});
    std::vector<LowresRow> rows;
    try {
        rows = RunLowresStudy(scene);
    } catch (const DomainError& e) {
        throw FlatlandInputError(casePath, e);
    }
    std::cout << LowresText(scene.name, rows);
    if (!out) return 0;
    out->WriteText("lowres_" + scene.name + ".md", LowresMarkdown(scene.name, rows));
    out->Writing([&] {
        WriteLowresPlot(out->Staged("lowres_" + scene.name + ".png").string(),
                        "Low-resolution decision: " + scene.name, LowresCurves(rows));
    });
    out->Commit();
    return 0;
}

namespace {

// The thesis tables `fit-thesis --case` selects: all, or the one whose case file has that stem.
std::vector<ThesisTable> SelectThesisTables(const std::vector<ThesisTable>& tables,
                                            const std::string& caseName) {
    std::vector<ThesisTable> selected;
    std::vector<std::string> known;
    for (const ThesisTable& thesis : tables) {
        known.push_back(fs::path(thesis.file).stem().string());
        if (caseName.empty() || known.back() == caseName) selected.push_back(thesis);
    }
    if (selected.empty())
        throw InputError("--case: unknown thesis case '" + caseName +
                         "' (known: " + KnownList(known) + ")");
    return selected;
}

// fit-thesis writes <case>.json (the family, named by the case file's stem) and parameters.json
// into --out: none of them may replace a thesis case file it reads (e.g. --out cases/flatland).
OutputPlan FitThesisOutputPlan(const fs::path& casesDir, const std::vector<ThesisTable>& selected) {
    OutputPlan plan;
    std::vector<std::string> names = {"parameters.json"};
    for (const ThesisTable& thesis : selected) {
        plan.inputs.push_back(casesDir / thesis.file);
        names.push_back(fs::path(thesis.file).stem().string() + ".json");
    }
    plan.isOutput = [names](const std::string& file) {
        return std::find(names.begin(), names.end(), file) != names.end();
    };
    return plan;
}

}  // namespace

int FitThesisCommand(const FitThesisFlags& flags) {
    const std::vector<ThesisTable> tables =
        LoadThesisTables(DataDirectory() / "published" / "thesis_tables.json");
    const std::vector<ThesisTable> selected = SelectThesisTables(tables, flags.caseName);
    const fs::path casesDir = DataDirectory() / "flatland";
    OutputSet out(flags.outDir, FitThesisOutputPlan(casesDir, selected));  // before any fit
    // Everything is fitted before anything is written.
    const std::vector<CaseFit> fits =
        FitThesisCases(selected, casesDir, flags.options,
                       [](const CaseFit& fit) { std::cout << FitText(fit) << std::flush; });
    const fs::path outDir(flags.outDir);
    const std::vector<StoredFit> stored = MergeStoredFits(outDir / "parameters.json", fits, tables);
    for (const CaseFit& fit : fits) out.WriteText(fit.family->name + ".json", FittedCaseJson(fit));
    out.WriteText("parameters.json", StoredFitsJson(stored));
    out.Commit();
    std::cout << "lexel: wrote " << fits.size() << " fitted case file"
              << (fits.size() == 1 ? "" : "s") << " and parameters.json to "
              << fs::absolute(outDir).string() << '\n';
    return 0;
}

}  // namespace lexel::cases
