// `lexel sweep` and `lexel merge` (commands.h): a case's light sweep, whole or one shard, its
// journal for --resume, and the shards' records joined into one sweep's files.
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

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/commands.h"
#include "lexel/cases/app/output_guard.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/case_methods.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/hostile_file.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/published.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/record/sweep_journal.h"
#include "lexel/cases/record/sweep_record.h"
#include "lexel/cases/record/sweep_record_reader.h"
#include "lexel/cases/record/sweep_record_text.h"
#include "lexel/cases/report/flatland_report.h"
#include "lexel/cases/report/html_report.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/report/sweep_lights_csv.h"
#include "lexel/cases/report/sweep_report.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/cascade_study.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/cases/run/sweep_share.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_frame.h"
#include "lexel/spatial/harness/mesh_loader.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/methods/registry.h"

#ifndef LEXEL_SOURCE_DATA_DIR
#define LEXEL_SOURCE_DATA_DIR ""
#endif

namespace lexel::cases {

namespace fs = std::filesystem;

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
                  BackendKind backend, int shimmerPoses) {
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
            backend, shimmerPoses);
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
    if (indices.empty() || shard.count > lights)
        throw InputError("--shard " + ShardText(shard) + ": the sweep has " +
                         std::to_string(lights) + " lights, fewer than its " +
                         std::to_string(shard.count) + " shards (give at most " +
                         std::to_string(lights) + " shards)");
    return indices;
}

// --shimmer-poses: at most the case's camera path's poses, within the sweep's memory budget.
void CheckShimmerPoses(const spatial::Scene& scene, std::size_t methods, int poses) {
    if (static_cast<std::size_t>(poses) > scene.cameraPath.size())
        throw InputError("--shimmer-poses: " + std::to_string(poses) +
                         " poses, but the case's camera_path has " +
                         std::to_string(scene.cameraPath.size()));
    if (const std::string excess = SweepMemoryExcess(scene, methods, poses);
        poses > 0 && !excess.empty())
        throw InputError("--shimmer-poses: the sweep " + excess);
}

// What makes two sweeps (or a sweep and its journal, or two shards) the same sweep.
SweepIdentity IdentityOf(const CaseFile& caseFile, const spatial::Scene& scene,
                         const std::vector<std::string>& methods, const SweepFlags& flags,
                         const std::vector<spatial::Light>& lights) {
    return {.caseName = scene.name,
            .caseHash = Fnv1a64Hex(caseFile.text),
            .methods = methods,
            .backend = flags.backend,
            .cascades = scene.partitions.count,
            .phases = scene.phases,
            .maxPhases = spatial::MostPhases(scene.phases, scene.maxPhases),
            .shimmerPoses = flags.shimmerPoses,
            .lights = lights.size(),
            .lightsHash = LightsHash(lights)};
}

}  // namespace

int SweepCommand(const SweepFlags& flags) {
    const SweepShard shard = ShardOf(flags.shard);
    if (flags.resume && flags.outDir.empty())
        throw InputError("--resume: continues a sweep into its --out directory; give --out");
    const fs::path casePath = flags.casePath;
    const CaseFile caseFile = ReadCaseFile(casePath);  // read once: the scene and the identity
    const spatial::Scene scene =
        LoadSceneWithOverrides(caseFile, flags.cascades, flags.phases, flags.maxPhases);
    const std::vector<std::string> methods = SpatialMethodsOfCase(flags.methods, scene, true);
    CheckShimmerPoses(scene, methods.size(), flags.shimmerPoses);
    const BackendKind backend = BackendOf(flags.backend);
    NoteCpuOnlyMethods(methods, backend);
    const ReportTable1 report =
        LoadReportTable1(DataDirectory() / "published" / "report_table1.json");
    const std::vector<spatial::Light> lights = SweepLightsFor(casePath, scene, flags);
    WithCaseName(casePath, [&] { CheckCaseMethodLights(scene, methods, true, lights); });
    const std::vector<std::size_t> indices = ShareOf(lights.size(), shard);
    std::optional<OutputSet> out;  // --out is checked before anything is computed
    if (!flags.outDir.empty()) out.emplace(flags.outDir, SweepOutputPlan(casePath, scene.name));
    const SweepIdentity identity = IdentityOf(caseFile, scene, methods, flags, lights);
    // With --out: the cascade-count study, and the journal of the finished lights.
    const bool withStudy = out && !CascadeStudyMethods(methods).empty();
    const std::vector<int> studyCounts =
        withStudy ? CascadeStudyExtraCounts(scene.partitions.count) : std::vector<int>{};
    std::optional<SweepJournal> journal;
    if (out) journal.emplace(SweepJournal::PathFor(flags.outDir), identity, shard, flags.resume);
    if (flags.resume)
        SayResumed(journal->Done(), indices.size(), studyCounts.size() * indices.size(), *journal);
    const ShareRun run = RunShare(casePath, scene, methods, lights, indices, withStudy,
                                  journal ? &*journal : nullptr, backend, flags.shimmerPoses);
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

// The most bytes a shard's first-light image may have, and its images together (a 16384² RGBA
// image compresses below it; a 720² sweep's images are about 30 KB each).
constexpr std::uintmax_t kMaxShardImageBytes = std::uintmax_t{1} << 30;

// The bytes of a shard's first-light image `file` in `dir`, read as every file beside an --out
// is: its name one the sweep writes (`<case>_light...png`), never through a symbolic link, a
// regular file of at most kMaxShardImageBytes and a complete PNG. InputError naming it otherwise.
std::string ReadShardImage(const fs::path& dir, const std::string& file,
                           const std::string& caseName) {
    const std::string shown = "merge: " + (dir / file).string();
    if (!file.starts_with(caseName + "_light"))
        throw InputError(shown + ": the record names an image that a sweep of " + caseName +
                         " does not write");
    std::string bytes = ReadHostileFile(dir / file, kMaxShardImageBytes, shown);
    if (const std::string defect = PngBytesDefect(bytes); !defect.empty())
        throw InputError(shown + ": not a complete PNG image (" + defect + ")");
    return bytes;
}

}  // namespace

int MergeCommand(const MergeFlags& flags) {
    std::vector<SweepRecord> records;
    for (const std::string& dir : flags.dirs) records.push_back(ReadSweepRecord(dir));
    const MergedSweep merged = MergeRecords(records, flags.dirs);
    const SweepIdentity& id = merged.record.identity;
    // Every shard's images are checked, and the ones merged read, before anything is printed.
    std::vector<std::string> imageBytes;
    std::uintmax_t keptBytes = 0;
    for (std::size_t d = 0; d < records.size(); ++d)
        for (const SpatialImageFile& image : records[d].images) {
            std::string bytes = ReadShardImage(flags.dirs[d], image.file, id.caseName);
            if (static_cast<int>(d) != merged.imagesFrom) continue;
            keptBytes += bytes.size();
            if (keptBytes > kMaxShardImageBytes)
                throw InputError("merge: " + flags.dirs[d] + ": its first-light images hold more " +
                                 "than " + std::to_string(kMaxShardImageBytes) + " bytes");
            imageBytes.push_back(std::move(bytes));
        }
    // No output may replace a shard's record or image (a shard directory given as --out).
    OutputPlan plan = SweepOutputPlan("", id.caseName);
    plan.inputs.clear();
    for (std::size_t d = 0; d < flags.dirs.size(); ++d) {
        plan.inputs.push_back(fs::path(flags.dirs[d]) / "sweep-record.json");
        for (const SpatialImageFile& image : records[d].images)
            plan.inputs.push_back(fs::path(flags.dirs[d]) / image.file);
    }
    OutputSet out(flags.outDir, plan);
    const SweepExclusion exclusion(flags.outDir);  // no sweep into --out meanwhile
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
        for (std::size_t i = 0; i < merged.record.images.size(); ++i)
            out.WriteText(merged.record.images[i].file, imageBytes[i]);
        return merged.record.images;
    };
    const std::string written = StageSweepFiles(
        out, merged.result, report, study ? &*study : nullptr, merged.record, stageImages);
    out.Commit();
    std::cerr << "lexel: wrote " << written << " to " << flags.outDir << '\n';
    return 0;
}

}  // namespace lexel::cases
