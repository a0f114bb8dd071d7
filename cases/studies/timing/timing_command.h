// `lexel timing CASE [--backend cpu|gl] [--lights N] [--frames F] [--update-every U]
// [--standard-every S] [--optimizer M] [--format table|json|csv]`: focused and optimal frames timed
// pass by pass (report Tables 2-3; README.md here).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lexel/spatial/methods/method_info.h"

namespace CLI {
class App;
}

namespace lexel::cases {

struct TimingFlags {
    std::string casePath;
    std::string backend = "cpu";  // cpu | gl
    int lights = 4;
    int frames = 8;
    int updateEvery = 1;    // optimal: Algorithm 1 every U frames (the report: 3)
    int standardEvery = 1;  // optimal: step 1 from a standard map every S updates (the report: 2)
    // The optimal frames' optimizer: one of spatial::OptimizerMethodNames.
    std::string optimizer = spatial::kReportOptimalMethod;
    std::string format = "table";  // table | json | csv
};
int TimingCommand(const TimingFlags& flags);

// Adds the subcommand and its flags to `app`; returns the command to run when it is chosen.
std::function<int()> RegisterTiming(CLI::App& app);

}  // namespace lexel::cases
