// Runs named flatland methods on a case: the decision pass feeds each solver, and every reported
// number is measured from scratch at full resolution at the chosen angle (Chong 2003, §4.1.3).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/flatland/sampling.h"
#include "lexel/solvers/footprint_metrics.h"

namespace lexel::flatland {

// One light frustum of a split method (thesis §3.2).
struct FrustumReport {
    double wsRayLowDeg = 0.0, wsRayHighDeg = 0.0;  // world angles of its two bounding rays
    double lexelPlaneDeg = 0.0;
    double wsAxis = 0.0;  // optical axis, world radians
    int lexels = 0;
    FootprintStats stats;
};

struct MethodReport {
    std::string method;
    double lexelPlaneDeg = 0.0;         // for split methods: the first frustum's
    FootprintStats stats;               // over Ω at full resolution
    double solveMs = 0.0;               // the solver alone, on the decision samples
    std::string note;                   // fallbacks and clamps, if any
    std::vector<FrustumReport> frusta;  // split methods only
    double wsAxis = 0.0;                // optical axis, world radians (first frustum's when split)
    std::vector<double> footprints;     // f per visible full-resolution pixel, in fullPass order,
                                        // when RunFlatlandCase is asked to keep them
};

struct CaseReport {
    std::string caseName;
    int pixels = 0, decisionPixels = 0, pixelsVisible = 0, lexels = 0;
    Metric metric = Metric::kL1;  // the metric `sweep` minimizes
    double samplingMs = 0.0;      // both passes
    std::vector<MethodReport> methods;
    std::shared_ptr<const SamplingPass> fullPass;  // the full-resolution pass every number uses
};

// All method names, in report order.
const std::vector<std::string>& FlatlandMethodNames();
bool IsFlatlandMethod(std::string_view name);
// One line saying what the method is (for `lexel --help`); empty for an unknown name.
std::string_view FlatlandMethodDescription(std::string_view name);

// Runs `methods` (names from FlatlandMethodNames; std::invalid_argument otherwise) on the scene.
// Throws DomainError as CheckSceneGeometry, RunSamplingPass and SplitLightFrustum do.
// `fullPass`, when given, must be RunSamplingPass(scene, scene.camera.pixels), and
// `decisionPass` RunSamplingPass(scene, scene.DecisionPixels()): callers that run one scene
// repeatedly with different decision resolutions pass them to avoid recomputing them.
// Each method's footprints are kept (8 bytes per visible pixel and method) only with
// keepFootprints (figures need them); otherwise MethodReport::footprints is empty and the run
// stays within FlatlandRunBytes (flatland/memory.h).
CaseReport RunFlatlandCase(const FlatScene& scene, std::span<const std::string> methods,
                           Metric metric, std::shared_ptr<const SamplingPass> fullPass = nullptr,
                           const SamplingPass* decisionPass = nullptr, bool keepFootprints = false);

}  // namespace lexel::flatland
