// `lexel tables`, `lexel lowres CASE` and `lexel fit-thesis`: the thesis's flatland tables, its
// low-resolution decisions and its scenes fitted to its numbers (README.md here).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lexel/cases/studies/thesis/fit_thesis.h"

namespace CLI {
class App;
}

namespace lexel::cases {

// tables.md, tables.csv, lowres.csv and the figures in outDir: every thesis table recomputed from
// the cases in casesDir (default: the shipped ones), each case's low-resolution decision study.
int TablesCommand(const std::string& outDir, const std::string& casesDir);
// One case's low-resolution decision study, printed; with outDir also its Markdown and plot.
int LowresCommand(const std::string& casePath, const std::string& outDir);

struct FitThesisFlags {
    std::string caseName;               // one case (file stem), or all when empty
    std::string outDir = "out/fitted";  // where the fitted case files go
    FitThesisOptions options;
};
int FitThesisCommand(const FitThesisFlags& flags);

// Adds the subcommand and its flags to `app`; returns the command to run when it is chosen.
std::function<int()> RegisterTables(CLI::App& app);
std::function<int()> RegisterLowres(CLI::App& app);
std::function<int()> RegisterFitThesis(CLI::App& app);

}  // namespace lexel::cases
