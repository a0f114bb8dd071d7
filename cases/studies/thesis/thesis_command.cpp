#include "lexel/cases/studies/thesis/thesis_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "lexel/cases/app/command_support.h"
#include "lexel/cases/app/commands.h"
#include "lexel/cases/app/flags.h"
#include "lexel/cases/app/progress.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/published.h"
#include "lexel/cases/load/stored_fits.h"
#include "lexel/cases/plot/case_figure.h"
#include "lexel/cases/plot/curve_plot.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/studies/thesis/fit_report.h"
#include "lexel/cases/studies/thesis/lowres.h"
#include "lexel/cases/studies/thesis/lowres_report.h"
#include "lexel/cases/studies/thesis/tables_report.h"
#include "lexel/cases/studies/thesis/thesis_tables.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace fs = std::filesystem;

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

std::function<int()> RegisterTables(CLI::App& app) {
    auto* tables =
        app.add_subcommand("tables", "Reproduce the thesis tables (Chong 2003, ch. 4.1.3)");
    auto outDir = std::make_shared<std::string>("out"), casesDir = std::make_shared<std::string>();
    tables->add_option("--out", *outDir, "Directory for the Markdown, CSV and figures")
        ->capture_default_str()
        ->check(NonEmpty("a directory"));
    tables
        ->add_option("--cases", *casesDir,
                     "Directory holding the four thesis cases (default: the shipped ones); "
                     "fitted/<case>.json there replaces a case where it matches better")
        ->check(NonEmpty("a directory"));
    return [outDir, casesDir] { return TablesCommand(*outDir, *casesDir); };
}

std::function<int()> RegisterLowres(CLI::App& app) {
    auto* lowres =
        app.add_subcommand("lowres", "Low-resolution decision study (thesis 4.1.1, Fig. 4.1)");
    auto casePath = std::make_shared<std::string>(), outDir = std::make_shared<std::string>();
    lowres->add_option("case", *casePath, "Case file (JSON)")->required()->check(CLI::ExistingFile);
    lowres->add_option("--out", *outDir, "Also write the table as CSV/Markdown and a plot here")
        ->check(NonEmpty("a directory"));
    return [casePath, outDir] { return LowresCommand(*casePath, *outDir); };
}

std::function<int()> RegisterFitThesis(CLI::App& app) {
    auto* fitThesis = app.add_subcommand(
        "fit-thesis", "Fit the thesis's scenes to its published tables (Chong 2003, ch. 4.1.3)");
    auto flags = std::make_shared<FitThesisFlags>();
    fitThesis->add_option("--case", flags->caseName, "One case (file stem); default: all four")
        ->check(NonEmpty("a thesis case"));
    fitThesis->add_option("--out", flags->outDir, "Directory for the fitted case files")
        ->capture_default_str()
        ->check(NonEmpty("a directory"));
    fitThesis->add_option("--seed", flags->options.seed, "Seed of the random starts")
        ->capture_default_str();
    fitThesis->add_option("--samples", flags->options.samples, "Random starts screened per case")
        ->capture_default_str()
        ->check(CLI::Range(0, 10000000));
    fitThesis
        ->add_option("--starts", flags->options.starts, "Least-squares runs from the best of them")
        ->capture_default_str()
        ->check(CLI::Range(0, 100000));
    fitThesis->add_flag("--explain", flags->options.explain,
                        "For a table not met: refit with each published number left out");
    return [flags] { return FitThesisCommand(*flags); };
}

}  // namespace lexel::cases
