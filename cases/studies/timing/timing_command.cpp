#include "lexel/cases/studies/timing/timing_command.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/commands.h"
#include "lexel/cases/app/flags.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/published.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/studies/timing/timing_report.h"
#include "lexel/cases/studies/timing/timing_study.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/methods/registry.h"

namespace lexel::cases {

namespace fs = std::filesystem;

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

std::function<int()> RegisterTiming(CLI::App& app) {
    auto* timing = app.add_subcommand(
        "timing", "3D: time focused and optimal frames pass by pass (report Tables 2-3)");
    auto flags = std::make_shared<TimingFlags>();
    timing->add_option("case", flags->casePath, "3D case file (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    AddBackend(timing, flags->backend, "The renderer (gl: OpenGL 4.5 via EGL)");
    timing->add_option("--lights", flags->lights, "Lights per frame (default 4, as Table 3)")
        ->check(CLI::Range(1, 64));
    timing
        ->add_option("--frames", flags->frames,
                     "Timed frames per method, walking the camera_path (default 8)")
        ->check(CLI::Range(1, 10000));
    timing
        ->add_option("--update-every", flags->updateEvery,
                     "Optimal: run Algorithm 1 every U frames, keep P between (report: 3)")
        ->check(CLI::Range(1, 1000));
    timing
        ->add_option("--standard-every", flags->standardEvery,
                     "Optimal: step 1 from a standard map every S updates, else from the "
                     "previous map (report: 2)")
        ->check(CLI::Range(1, 1000));
    timing
        ->add_option(
            "--optimizer", flags->optimizer,
            "The optimal frames' method (default optimal-report: Algorithm 1 as published)")
        ->check(CLI::IsMember(lexel::spatial::OptimizerMethodNames()));
    timing->add_option("--format", flags->format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    return [flags] { return TimingCommand(*flags); };
}

}  // namespace lexel::cases
