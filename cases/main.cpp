// lexel — the command line. Subcommands:
//   lexel run CASE.json... [--method NAME...] [--metric l1|l2|linf] [--format table|json|csv]
//   [--out DIR] lexel tables [--out DIR] [--cases DIR] lexel lowres CASE.json [--out DIR]
// Exit status: 0 success, 2 bad input (one line on stderr naming the field and the reason),
// 1 an I/O failure while writing results.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "cases/flatland_case.h"
#include "cases/report.h"
#include "cases/tables.h"
#include "solvers/errors.h"

#ifndef LEXEL_VERSION
#define LEXEL_VERSION "unknown"
#endif

namespace {

using namespace lexel;

int RunCommand(const std::vector<std::string>& casePaths, std::vector<std::string> methods,
               const std::string& metricName, const std::string& format,
               const std::string& outDir) {
    const Metric metric = ParseMetric(metricName);
    if (methods.empty()) methods = flatland::FlatlandMethodNames();
    for (const auto& m : methods) flatland::CheckFlatlandMethod(m);
    // Everything is computed before anything is written: a bad second case leaves no files.
    std::vector<flatland::CaseReport> reports;
    for (const auto& path : casePaths) {
        const flatland::FlatScene scene = cases::LoadFlatScene(path);
        try {
            reports.push_back(flatland::RunFlatlandCase(scene, methods, metric));
        } catch (const InputError& e) {
            throw InputError(path + ": " + e.what());
        }
    }
    if (format == "json")
        std::cout << cases::RunJson(reports).dump(2) << '\n';
    else if (format == "csv")
        std::cout << cases::RunCsv(reports);
    else
        for (std::size_t i = 0; i < reports.size(); ++i)
            std::cout << (i ? "\n" : "") << cases::CaseTable(reports[i]);
    if (!outDir.empty()) {
        std::filesystem::create_directories(outDir);
        for (const auto& r : reports) {
            const std::string base = (std::filesystem::path(outDir) / r.caseName).string();
            cases::WriteFileAtomically(base + ".json", cases::CaseReportJson(r).dump(2) + "\n");
            cases::WriteFileAtomically(base + ".csv", cases::RunCsv(std::span(&r, 1)));
            cases::WriteFileAtomically(base + ".md", cases::CaseMarkdown(r));
        }
        std::cerr << "lexel: wrote " << reports.size() * 3 << " files to " << outDir << '\n';
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lexel: choose the light projection that minimizes shadow-map aliasing"};
    app.set_version_flag("--version", std::string("lexel ") + LEXEL_VERSION);
    app.require_subcommand(1);

    auto* run =
        app.add_subcommand("run", "Run methods on case files and report their footprint metrics");
    std::vector<std::string> casePaths, methods;
    std::string metric = "l1", format = "table", runOut;
    run->add_option("cases", casePaths, "Case files (JSON)")->required()->check(CLI::ExistingFile);
    run->add_option("--method", methods, "Methods to run (default: all)");
    run->add_option("--metric", metric, "Metric the sweep minimizes")
        ->check(CLI::IsMember({"l1", "l2", "linf"}));
    run->add_option("--format", format, "Output format")
        ->check(CLI::IsMember({"table", "json", "csv"}));
    run->add_option("--out", runOut, "Also write <case>.json/.csv/.md into this directory");

    auto* tables =
        app.add_subcommand("tables", "Reproduce the thesis tables (Chong 2003, ch. 4.1.3)");
    std::string tablesOut = "out", casesDir;
    tables->add_option("--out", tablesOut, "Directory for the Markdown, CSV and figures")
        ->capture_default_str();
    tables->add_option("--cases", casesDir,
                       "Directory holding the four thesis cases (default: the shipped ones)");

    auto* lowres =
        app.add_subcommand("lowres", "Low-resolution decision study (thesis 4.1.1, Fig. 4.1)");
    std::string lowresCase, lowresOut;
    lowres->add_option("case", lowresCase, "Case file (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    lowres->add_option("--out", lowresOut, "Also write the table as CSV/Markdown and a plot here");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        if (*run) return RunCommand(casePaths, methods, metric, format, runOut);
        if (*tables) return cases::RunTablesCommand(tablesOut, casesDir);
        if (*lowres) return cases::RunLowresCommand(lowresCase, lowresOut);
    } catch (const InputError& e) {
        std::cerr << "lexel: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "lexel: failed: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
