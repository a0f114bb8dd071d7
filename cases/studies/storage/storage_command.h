// `lexel storage [frustum flags] [--format F] [--out DIR]` and `lexel storage --case CASE
// [--method M...]`: Lloyd et al. 2006's storage factor (README.md here).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lexel::cases {

// Lloyd et al. 2006's storage factor for one view frustum (the frustum flags), or with a case
// file every method's measured storage factor beside the analytic one for the case's camera.
struct StorageFlags {
    double fovYDeg = 60.0;
    double aspect = 1.0;
    double nearPlane = 1.0;
    double farPlane = 1000.0;
    std::string casePath;              // --case: measured beside analytic instead of the figures
    std::vector<std::string> methods;  // with --case; empty: all
    std::string format = "table";      // table | json | csv
    std::string outDir;                // empty: print only
};
int StorageCommand(const StorageFlags& flags);

// Adds the subcommand and its flags to `app`; returns the command to run when it is chosen.
std::function<int()> RegisterStorage(CLI::App& app);

}  // namespace lexel::cases
