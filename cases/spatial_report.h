// `lexel run` on a 3D case and `lexel sweep`: the experiment of Chong & Gortler's report §3 and
// its Table 1 (misclassified shadow pixels, all lights and each method's worst 10%).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// Per light and method, what a sweep keeps (matrices and buffers are dropped).
struct SweepCell {
    std::int64_t misclassified = 0;
    double h = 0.0;
    double ms = 0.0;
};

struct SweepResult {
    std::string caseName;
    std::vector<std::string> methods;
    std::vector<spatial::Light> lights;
    std::vector<std::vector<SweepCell>> cells;  // [light][method]
    std::vector<std::int64_t> receiverPixels;   // per light
    double seconds = 0.0;                       // wall time of the whole sweep
};

// The lights of the sweep: the case's light_sweep (count overridden by `lights` when > 0).
// Throws InputError when the case has no light_sweep.
std::vector<spatial::Light> SweepLightsOf(const spatial::Scene& scene, int lights);

// Evaluates every light (in parallel over lights; deterministic for the case's seed). Shows a
// progress bar on stderr when `progress` is set.
SweepResult RunSweep(const spatial::Scene& scene, const std::vector<std::string>& methods,
                     const std::vector<spatial::Light>& lights, bool progress);

// Table 1 in three forms. The reference column is `optimal` when it was run, else the first
// method; "% more" is relative to it. Beside our percentages the report's are printed for the
// methods it measured.
std::string SweepTable(const SweepResult& result);
std::string SweepMarkdown(const SweepResult& result);
std::string SweepCsv(const SweepResult& result);
// {"case": ..., "lights": N, "methods": [{"method", "mean_misclassified", "mean_h", "mean_ms",
// ...}], "worst_10_percent": [...]} — schema in cases/README.md.
nlohmann::json SweepJson(const SweepResult& result);

struct SpatialRunOptions {
    std::vector<std::string> methods;  // empty: all
    std::string format = "table";      // table | json | csv
    std::string outDir;                // images and reports; empty: none
    bool mapTruth = true;              // also the report's focused 4000² truth map
};
int RunSpatialCommand(const std::filesystem::path& casePath, const SpatialRunOptions& options);

struct SweepOptions {
    int lights = 0;                    // 0: the case's light_sweep count
    std::vector<std::string> methods;  // empty: all
    std::string format = "table";      // table | markdown | csv | json
    std::string outDir;                // also write table1.md, table1.csv, sweep.json, lights.csv
};
int RunSweepCommand(const std::filesystem::path& casePath, const SweepOptions& options);

}  // namespace lexel::cases
