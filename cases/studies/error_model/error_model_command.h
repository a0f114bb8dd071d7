// `lexel error-model CASE --out DIR [--lights N] [--light-type point|directional]
// [--method M ...] [--phases K] [--backend cpu|gl]`: the error model (spatial/error_model.h)
// checked per boundary sample over a case's light sweep
// (cases/studies/error_model/error_model_study.h), its scatter plot, fit and CSV written to DIR
// (cases/README.md).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lexel::cases {

struct ErrorModelFlags {
    std::string casePath;
    std::string outDir;
    int lights = 0;                    // 0: the case's light_sweep count
    std::string lightType;             // point | directional; empty: the case's
    std::vector<std::string> methods;  // empty: kErrorModelDefaultMethods
    int phases = 16;                   // K = n², a stratified n × n grid of sub-texel phases
    std::string backend = "cpu";
};

// Writes error_model.csv, error_model.json, error_model.txt and error_model.png into --out and
// prints the text summary. Bad input (an unknown or not single-map method, a --phases that is not
// a square, an --out that cannot take the files) is an InputError naming the flag, before anything
// is computed or written.
int ErrorModelCommand(const ErrorModelFlags& flags);

// Adds the subcommand and its flags to `app`; returns the command to run when it is chosen.
std::function<int()> RegisterErrorModel(CLI::App& app);

}  // namespace lexel::cases
