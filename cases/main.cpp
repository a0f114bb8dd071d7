// lexel — the command line. Subcommands:
//   lexel run CASE.json... [--method NAME...] [--metric l1|l2|linf] [--format table|json|csv]
//             [--out DIR] [--no-map-truth] [--cascades K] [--phases K] [--max-phases N]
//                                                                       flatland and 3D
//   lexel sweep CASE.json [--lights N] [--light-type point|directional] [--method NAME...]
//             [--cascades K] [--phases K] [--max-phases N] [--shimmer-poses P]
//             [--format table|markdown|csv|json]
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
//   lexel error-model CASE.json --out DIR [--lights N] [--method NAME...] [--phases K]
// Exit status: 0 success, 2 bad input (one line on stderr naming the field and the reason) or
// too little memory for it, 1 an I/O failure while writing results, 128 + n stopped by signal n
// (SIGINT, SIGTERM, SIGHUP; the --out staging removed). Every failure is one line
// "lexel: error: ...".
#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "lexel/cases/app/commands.h"
#include "lexel/cases/app/flags.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/cases/studies/error_model/error_model_command.h"
#include "lexel/cases/studies/storage/storage_command.h"
#include "lexel/cases/studies/thesis/thesis_command.h"
#include "lexel/cases/studies/timing/timing_command.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
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

// One registration function per subcommand: it adds the subcommand and its flags to `app`, bound
// to a flags struct it owns, and returns the command to run when the subcommand is chosen.
using Command = std::function<int()>;
namespace cases = lexel::cases;

using cases::AddBackend;
using cases::AddPhases;
using cases::NonEmpty;
// The studies' commands, each in its folder (cases/studies/<name>/<name>_command.h).
using cases::RegisterErrorModel;
using cases::RegisterFitThesis;
using cases::RegisterLowres;
using cases::RegisterStorage;
using cases::RegisterTables;
using cases::RegisterTiming;

Command RegisterRun(CLI::App& app) {
    auto* run =
        app.add_subcommand("run", "Run methods on case files and report their footprint metrics");
    auto flags = std::make_shared<cases::RunFlags>();
    auto noMapTruth = std::make_shared<bool>(false);
    run->add_option("cases", flags->cases, "Case files (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    run->add_option("--method", flags->methods, "Methods to run (default: all; listed below)");
    run->footer(cases::MethodsHelp(true, true));
    run->add_option("--metric", flags->metric, "Metric the sweep minimizes")
        ->check(CLI::IsMember({"l1", "l2", "linf"}));
    run->add_option("--format", flags->format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    run->add_option("--out", flags->outDir,
                    "Also write <case>.json/.csv/.md (and for 3D cases the images) here")
        ->check(NonEmpty("a directory"));
    run->add_option("--cascades", flags->cascades,
                    "3D: partitions of pssm, sdsm, ... (default: the case's cascades.count, or 4)")
        ->check(CLI::Range(1, lexel::spatial::kMaxCascades));
    AddPhases(run, flags->phases, flags->maxPhases);
    AddBackend(run, flags->backend, "3D cases: the renderer (gl: OpenGL 4.5 via EGL)");
    run->add_flag("--no-map-truth", *noMapTruth,
                  "3D cases: skip the report's focused 4000² truth map (rays are the truth)");
    return [run, flags, noMapTruth] {
        flags->metricGiven = run->count("--metric") > 0;
        flags->mapTruth = !*noMapTruth;
        return cases::RunCommand(*flags);
    };
}

Command RegisterSweep(CLI::App& app) {
    auto* sweep = app.add_subcommand(
        "sweep", "3D: evaluate every method over the case's light sweep (report Table 1)");
    auto flags = std::make_shared<cases::SweepFlags>();
    sweep->add_option("case", flags->casePath, "3D case file (JSON) with a light_sweep")
        ->required()
        ->check(CLI::ExistingFile);
    sweep
        ->add_option("--lights", flags->lights, "Number of hemisphere lights (default: the case's)")
        ->check(CLI::Range(1LL, cases::kMaxSweepLights));
    sweep
        ->add_option("--light-type", flags->lightType,
                     "Sweep point or directional lights (default: the case's light_sweep type)")
        ->check(CLI::IsMember({"point", "directional"}));
    sweep->add_option("--method,--methods", flags->methods,
                      "Methods to run (default: all; listed below)");
    sweep->footer(cases::MethodsHelp(false, true));
    sweep->add_option("--format", flags->format, "Output format")
        ->check(CLI::IsMember({"table", "markdown", "csv", "json"}));
    sweep
        ->add_option("--out", flags->outDir,
                     "Also write table1.md/.csv, sweep.json, lights.csv here (and with partitioned "
                     "methods the k = 1, 2, 4, 8 study and the first light's cascades)")
        ->check(NonEmpty("a directory"));
    sweep
        ->add_option("--cascades", flags->cascades,
                     "Partitions of pssm, sdsm, ... (default: the case's cascades.count, or 4)")
        ->check(CLI::Range(1, lexel::spatial::kMaxCascades));
    AddPhases(sweep, flags->phases, flags->maxPhases);
    sweep
        ->add_option("--shimmer-poses", flags->shimmerPoses,
                     "Also measure each light's shimmer along the first P poses of the case's "
                     "camera_path (one more evaluation per pose and light)")
        ->check(CLI::Range(2, lexel::cases::kMaxShimmerPoses));
    AddBackend(sweep, flags->backend, "The renderer (gl: OpenGL 4.5 via EGL)");
    sweep->add_option("--shard", flags->shard,
                      "K/N: evaluate only the lights i with i mod N = K (K = 0 ... N-1), for a "
                      "job array; join the shards' --out directories with lexel merge");
    sweep->add_flag("--resume", flags->resume,
                    "Continue a killed sweep into --out DIR from the lights it finished (its "
                    "journal beside DIR: .DIR.lexel-sweep-journal)");
    return [flags] { return cases::SweepCommand(*flags); };
}

Command RegisterMerge(CLI::App& app) {
    auto* merge = app.add_subcommand(
        "merge", "3D: join the --out directories of sweep shards into one whole sweep's files");
    auto flags = std::make_shared<cases::MergeFlags>();
    merge->add_option("dirs", flags->dirs, "The shards' --out directories (any order)")
        ->required()
        ->check(CLI::ExistingDirectory);
    merge->add_option("--out", flags->outDir, "Write the whole sweep's files here")
        ->required()
        ->check(NonEmpty("a directory"));
    merge->add_option("--format", flags->format, "Output format")
        ->check(CLI::IsMember({"table", "markdown", "csv", "json"}));
    merge->footer(
        "The merged files are those of one unsharded run, bit for bit, but for the times: each "
        "light keeps its shard's ms, and the sweep's seconds are the sum of the shards'.");
    return [flags] { return cases::MergeCommand(*flags); };
}

Command RegisterMethods(CLI::App& app) {
    auto* methods = app.add_subcommand(
        "methods", "Every method: its family, whether it runs by default, its storage model");
    auto format = std::make_shared<std::string>("text");
    methods->add_option("--format", *format, "text (a table) or json (for scripts)")
        ->capture_default_str()
        ->check(CLI::IsMember({"text", "json"}));
    return [format] { return cases::MethodsCommand(*format == "json"); };
}

Command RegisterMeshInfo(CLI::App& app) {
    auto* meshInfo = app.add_subcommand(
        "mesh-info", "A mesh file's format, triangles and bounds, and its placement by a case");
    auto file = std::make_shared<std::string>(), casePath = std::make_shared<std::string>();
    meshInfo->add_option("file", *file, "Mesh file (obj, off, stl, ply, gltf, glb)")
        ->required()
        ->check(NonEmpty("a mesh file"));
    meshInfo
        ->add_option("--case", *casePath,
                     "3D case: also the bounds after each of its entries for the file (up axis, "
                     "units, transform)")
        ->check(CLI::ExistingFile);
    return [file, casePath] { return cases::MeshInfoCommand(*file, *casePath); };
}

Command RegisterInfo(CLI::App& app) {
    app.add_subcommand("info", "The version and the renderers available here");
    return [] { return cases::InfoCommand(std::string("lexel ") + LEXEL_VERSION); };
}

// Runs the chosen command, each failure one line: bad input (InputError, an untranslated
// DomainError, too little memory) exit 2, anything else 1.
int RunCommandSafely(const Command& command) {
    try {
        return command();
    } catch (const lexel::InputError& e) {
        return Failure(e.what(), 2);
    } catch (
        const lexel::DomainError& e) {  // a domain error no command translated: still bad input
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
}

int RunLexel(int argc, char** argv) {
    CLI::App app{"lexel: choose the light projection that minimizes shadow-map aliasing"};
    app.set_version_flag("--version", std::string("lexel ") + LEXEL_VERSION);
    app.require_subcommand(1);
    // In `lexel --help` order.
    const std::vector<Command> commands = {
        RegisterRun(app),    RegisterSweep(app),   RegisterMerge(app),     RegisterMethods(app),
        RegisterTiming(app), RegisterStorage(app), RegisterMeshInfo(app),  RegisterInfo(app),
        RegisterTables(app), RegisterLowres(app),  RegisterFitThesis(app), RegisterErrorModel(app)};
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
    const std::vector<CLI::App*> subcommands = app.get_subcommands({});
    for (std::size_t i = 0; i < subcommands.size(); ++i)
        if (subcommands[i]->parsed()) return RunCommandSafely(commands[i]);
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
