// lexel — the command line. Subcommands:
//   lexel run CASE.json... [--method NAME...] [--metric l1|l2|linf] [--format table|json|csv]
//             [--out DIR] [--no-map-truth] [--cascades K]   flatland and 3D cases alike
//   lexel sweep CASE.json [--lights N] [--light-type point|directional] [--methods NAME...]
//             [--cascades K] [--format table|markdown|csv|json]
//             [--out DIR] [--shard K/N] [--resume]
//                                  the 3D report's Table 1, the fair and equal-texel tables
//   lexel merge DIR... --out DIR [--format ...]   sweep shards joined into one whole sweep
//   lexel timing CASE.json [--backend cpu|gl] [--lights N] [--frames F] [--format table|json|csv]
//             [--update-every U] [--standard-every S] [--optimizer optimal-report|optimal|...]
//                                                   the 3D report's Tables 2–3
//   lexel storage [--fov-y DEG] [--aspect A] [--near N] [--far F] [--format table|json|csv]
//             [--out DIR]                 Lloyd 2006's storage factor (Figs. 5–7, 10, 12, 13)
//   lexel storage --case CASE.json [--method NAME...] [--format ...] [--out DIR]
//                                   every method's measured storage factor beside the analytic
//   lexel info                                      version and backends (the GL renderer)
//   lexel mesh-info FILE [--case CASE.json]     a mesh's format, triangles, bounds, placement
//   (run and sweep take --backend cpu|gl for 3D cases)
//   lexel tables [--out DIR] [--cases DIR]
//   lexel lowres CASE.json [--out DIR]
//   lexel fit-thesis [--case NAME] [--out DIR] [--seed S] [--samples N] [--starts K] [--explain]
// Exit status: 0 success, 2 bad input (one line on stderr naming the field and the reason) or
// too little memory for it, 1 an I/O failure while writing results, 128 + n stopped by signal n
// (SIGINT, SIGTERM, SIGHUP; the --out staging removed). Every failure is one line
// "lexel: error: ...".
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>

#include "lexel/cases/app/commands.h"
#include "lexel/cases/report/output.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/partitions.h"

#ifndef LEXEL_VERSION
#define LEXEL_VERSION "unknown"
#endif

namespace {

// Prints the one line every failure prints (newlines of a library's message folded) and returns
// the exit status.
int Failure(std::string message, int status) {
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    std::cerr << "lexel: error: " << message << '\n';
    return status;
}

// A flag given as an empty string (`--out ''`) is refused rather than taken for "not given".
CLI::Validator NonEmpty(const std::string& what) {
    return CLI::Validator(
        [what](std::string& value) {
            return value.empty() ? "must name " + what + ", got an empty string" : std::string();
        },
        "", "NonEmpty");
}

int RunLexel(int argc, char** argv) {
    CLI::App app{"lexel: choose the light projection that minimizes shadow-map aliasing"};
    app.set_version_flag("--version", std::string("lexel ") + LEXEL_VERSION);
    app.require_subcommand(1);

    auto* run =
        app.add_subcommand("run", "Run methods on case files and report their footprint metrics");
    std::vector<std::string> casePaths, methods;
    std::string metric = "l1", format = "table", runOut;
    run->add_option("cases", casePaths, "Case files (JSON)")->required()->check(CLI::ExistingFile);
    run->add_option("--method", methods, "Methods to run (default: all; listed below)");
    run->footer(lexel::cases::MethodsHelp(true, true));
    run->add_option("--metric", metric, "Metric the sweep minimizes")
        ->check(CLI::IsMember({"l1", "l2", "linf"}));
    run->add_option("--format", format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    run->add_option("--out", runOut,
                    "Also write <case>.json/.csv/.md (and for 3D cases the images) here")
        ->check(NonEmpty("a directory"));
    int runCascades = 0;
    run->add_option("--cascades", runCascades,
                    "3D: partitions of pssm, sdsm, ... (default: the case's cascades.count, or 4)")
        ->check(CLI::Range(1, lexel::spatial::kMaxCascades));
    std::string runBackend = "cpu";
    run->add_option("--backend", runBackend, "3D cases: the renderer (gl: OpenGL 4.5 via EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}));
    bool noMapTruth = false;
    run->add_flag("--no-map-truth", noMapTruth,
                  "3D cases: skip the report's focused 4000² truth map (rays are the truth)");

    auto* sweep = app.add_subcommand(
        "sweep", "3D: evaluate every method over the case's light sweep (report Table 1)");
    std::string sweepCase, sweepFormat = "table", sweepOut, sweepLightType;
    std::vector<std::string> sweepMethods;
    int sweepLights = 0;
    sweep->add_option("case", sweepCase, "3D case file (JSON) with a light_sweep")
        ->required()
        ->check(CLI::ExistingFile);
    sweep->add_option("--lights", sweepLights, "Number of hemisphere lights (default: the case's)")
        ->check(CLI::Range(1, 100000));
    sweep
        ->add_option("--light-type", sweepLightType,
                     "Sweep point or directional lights (default: the case's light_sweep type)")
        ->check(CLI::IsMember({"point", "directional"}));
    sweep->add_option("--methods,--method", sweepMethods,
                      "Methods to run (default: all; listed below)");
    sweep->footer(lexel::cases::MethodsHelp(false, true));
    sweep->add_option("--format", sweepFormat, "Output format")
        ->check(CLI::IsMember({"table", "markdown", "csv", "json"}));
    sweep
        ->add_option("--out", sweepOut,
                     "Also write table1.md/.csv, sweep.json, lights.csv here (and with partitioned "
                     "methods the k = 1, 2, 4, 8 study and the first light's cascades)")
        ->check(NonEmpty("a directory"));
    int sweepCascades = 0;
    sweep
        ->add_option("--cascades", sweepCascades,
                     "Partitions of pssm, sdsm, ... (default: the case's cascades.count, or 4)")
        ->check(CLI::Range(1, lexel::spatial::kMaxCascades));
    std::string sweepBackend = "cpu";
    sweep->add_option("--backend", sweepBackend, "The renderer (gl: OpenGL 4.5 via EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}));
    std::string sweepShard = "0/1";
    sweep->add_option("--shard", sweepShard,
                      "K/N: evaluate only the lights i with i mod N = K (K = 0 ... N-1), for a "
                      "job array; join the shards' --out directories with lexel merge");
    bool sweepResume = false;
    sweep->add_flag("--resume", sweepResume,
                    "Continue a killed sweep into --out DIR from the lights it finished (its "
                    "journal beside DIR: .DIR.lexel-sweep-journal)");

    auto* merge = app.add_subcommand(
        "merge", "3D: join the --out directories of sweep shards into one whole sweep's files");
    lexel::cases::MergeFlags mergeFlags;
    merge->add_option("dirs", mergeFlags.dirs, "The shards' --out directories (any order)")
        ->required()
        ->check(CLI::ExistingDirectory);
    merge->add_option("--out", mergeFlags.outDir, "Write the whole sweep's files here")
        ->required()
        ->check(NonEmpty("a directory"));
    merge->add_option("--format", mergeFlags.format, "Output format")
        ->check(CLI::IsMember({"table", "markdown", "csv", "json"}));
    merge->footer(
        "The merged files are those of one unsharded run, bit for bit, but for the times: each "
        "light keeps its shard's ms, and the sweep's seconds are the sum of the shards'.");

    auto* timing = app.add_subcommand(
        "timing", "3D: time focused and optimal frames pass by pass (report Tables 2-3)");
    lexel::cases::TimingFlags timingFlags;
    timing->add_option("case", timingFlags.casePath, "3D case file (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    timing->add_option("--backend", timingFlags.backend, "The renderer (gl: OpenGL 4.5 via EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}));
    timing->add_option("--lights", timingFlags.lights, "Lights per frame (default 4, as Table 3)")
        ->check(CLI::Range(1, 64));
    timing
        ->add_option("--frames", timingFlags.frames,
                     "Timed frames per method, walking the camera_path (default 8)")
        ->check(CLI::Range(1, 10000));
    timing
        ->add_option("--update-every", timingFlags.updateEvery,
                     "Optimal: run Algorithm 1 every U frames, keep P between (report: 3)")
        ->check(CLI::Range(1, 1000));
    timing
        ->add_option("--standard-every", timingFlags.standardEvery,
                     "Optimal: step 1 from a standard map every S updates, else from the "
                     "previous map (report: 2)")
        ->check(CLI::Range(1, 1000));
    timing
        ->add_option(
            "--optimizer", timingFlags.optimizer,
            "The optimal frames' method (default optimal-report: Algorithm 1 as published)")
        ->check(CLI::IsMember({"optimal-report", "optimal", "optimal-refined", "optimal-shear"}));
    timing->add_option("--format", timingFlags.format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));

    auto* storage = app.add_subcommand(
        "storage",
        "Lloyd et al. 2006's storage factor: the data and figures of Figs. 5-7, 10, 12, 13");
    lexel::cases::StorageFlags storageFlags;
    storage
        ->add_option("--fov-y", storageFlags.fovYDeg,
                     "Vertical field of view in degrees, 0.1 to 179")
        ->capture_default_str();
    storage->add_option("--aspect", storageFlags.aspect, "Image width / height, 0.01 to 100")
        ->capture_default_str();
    storage->add_option("--near", storageFlags.nearPlane, "Near plane n, 1e-6 to 1e9")
        ->capture_default_str();
    storage
        ->add_option("--far", storageFlags.farPlane,
                     "Far plane f, 1e-6 to 1e9, with f/n from 1 + 1e-6 to 1e6")
        ->capture_default_str();
    auto* storageCase =
        storage
            ->add_option("--case", storageFlags.casePath,
                         "3D case: every method's measured storage factor beside the analytic "
                         "one for the case's camera (instead of the figures)")
            ->check(CLI::ExistingFile);
    for (const char* flag : {"--fov-y", "--aspect", "--near", "--far"})
        storageCase->excludes(storage->get_option(flag));
    storage->add_option("--method", storageFlags.methods,
                        "With --case: methods (default: all; listed below)");
    storage->footer(lexel::cases::MethodsHelp(false, true));
    storage->add_option("--format", storageFlags.format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    storage
        ->add_option("--out", storageFlags.outDir,
                     "Also write storage.json, storage.csv and the figures (PNG) here")
        ->check(NonEmpty("a directory"));

    auto* meshInfo = app.add_subcommand(
        "mesh-info", "A mesh file's format, triangles and bounds, and its placement by a case");
    std::string meshInfoFile, meshInfoCase;
    meshInfo->add_option("file", meshInfoFile, "Mesh file (obj, off, stl, ply, gltf, glb)")
        ->required()
        ->check(NonEmpty("a mesh file"));
    meshInfo
        ->add_option("--case", meshInfoCase,
                     "3D case: also the bounds after each of its entries for the file (up axis, "
                     "units, transform)")
        ->check(CLI::ExistingFile);

    auto* info = app.add_subcommand("info", "The version and the renderers available here");

    auto* tables =
        app.add_subcommand("tables", "Reproduce the thesis tables (Chong 2003, ch. 4.1.3)");
    std::string tablesOut = "out", casesDir;
    tables->add_option("--out", tablesOut, "Directory for the Markdown, CSV and figures")
        ->capture_default_str()
        ->check(NonEmpty("a directory"));
    tables
        ->add_option("--cases", casesDir,
                     "Directory holding the four thesis cases (default: the shipped ones); "
                     "fitted/<case>.json there replaces a case where it matches better")
        ->check(NonEmpty("a directory"));

    auto* lowres =
        app.add_subcommand("lowres", "Low-resolution decision study (thesis 4.1.1, Fig. 4.1)");
    std::string lowresCase, lowresOut;
    lowres->add_option("case", lowresCase, "Case file (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    lowres->add_option("--out", lowresOut, "Also write the table as CSV/Markdown and a plot here")
        ->check(NonEmpty("a directory"));

    auto* fitThesis = app.add_subcommand(
        "fit-thesis", "Fit the thesis's scenes to its published tables (Chong 2003, ch. 4.1.3)");
    lexel::cases::FitThesisFlags fitFlags;
    fitThesis->add_option("--case", fitFlags.caseName, "One case (file stem); default: all four")
        ->check(NonEmpty("a thesis case"));
    fitThesis->add_option("--out", fitFlags.outDir, "Directory for the fitted case files")
        ->capture_default_str()
        ->check(NonEmpty("a directory"));
    fitThesis->add_option("--seed", fitFlags.options.seed, "Seed of the random starts")
        ->capture_default_str();
    fitThesis->add_option("--samples", fitFlags.options.samples, "Random starts screened per case")
        ->capture_default_str()
        ->check(CLI::Range(0, 10000000));
    fitThesis
        ->add_option("--starts", fitFlags.options.starts,
                     "Least-squares runs from the best of them")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    fitThesis->add_flag("--explain", fitFlags.options.explain,
                        "For a table not met: refit with each published number left out");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        return Failure(e.what(), 2);
    }
    using namespace lexel;
    try {
        if (*run)
            return cases::RunCommand({casePaths, methods, metric, run->count("--metric") > 0,
                                      format, runOut, !noMapTruth, runCascades, runBackend});
        if (*sweep)
            return cases::SweepCommand({sweepCase, sweepLights, sweepLightType, sweepMethods,
                                        sweepFormat, sweepOut, sweepCascades, sweepBackend,
                                        sweepShard, sweepResume});
        if (*merge) return cases::MergeCommand(mergeFlags);
        if (*timing) return cases::TimingCommand(timingFlags);
        if (*storage) return cases::StorageCommand(storageFlags);
        if (*meshInfo) return cases::MeshInfoCommand(meshInfoFile, meshInfoCase);
        if (*info) return cases::InfoCommand(std::string("lexel ") + LEXEL_VERSION);
        if (*tables) return cases::TablesCommand(tablesOut, casesDir);
        if (*lowres) return cases::LowresCommand(lowresCase, lowresOut);
        if (*fitThesis) return cases::FitThesisCommand(fitFlags);
    } catch (const InputError& e) {
        return Failure(e.what(), 2);
    } catch (const DomainError& e) {  // a domain error no command translated: still bad input
        return Failure(e.what(), 2);
    } catch (const std::bad_alloc&) {
        // The loaders refuse cases over the memory budget; this is a machine with less to give.
        return Failure(
            "out of memory: this machine could not give the case what it needs (see "
            "the memory budget in cases/README.md)",
            2);
    } catch (const std::exception& e) {
        return Failure(e.what(), 1);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // Before any thread starts: SIGINT, SIGTERM and SIGHUP remove the --out staging and exit.
    lexel::cases::StopCleanlyOnSignals();
    const int status = RunLexel(argc, argv);
    // Results that did not reach stdout (a full disk, a closed pipe) are a failed run.
    std::cout.flush();
    if (!std::cout) {
        std::cerr << "lexel: error: cannot write to standard output\n";
        return status == 0 ? 1 : status;
    }
    return status;
}
