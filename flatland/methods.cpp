#include "lexel/flatland/methods.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <utility>

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/baselines.h"
#include "lexel/flatland/frustum_split.h"
#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/sampling.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"

namespace lexel::flatland {

const std::vector<std::string>& FlatlandMethodNames() {
    static const std::vector<std::string> names = {
        "optimal-l1",       "optimal-l2",   "optimal-l2-newton",
        "optimal-l2-ceres", "optimal-linf", "sweep",
        "normal",           "psm",          "psm-thesis",
        "plane-optimal",    "split-greedy", "split-dp"};
    return names;
}

std::string_view FlatlandMethodDescription(std::string_view name) {
    // One line per method of FlatlandMethodNames (RESULTS.md, "Flatland methods", says more).
    static constexpr std::pair<std::string_view, std::string_view> kDescriptions[] = {
        {"optimal-l1", "exact L1 optimum: the roots of one quadratic in tan x"},
        {"optimal-l2", "exact L2 optimum: a quartic, solved by companion matrix"},
        {"optimal-l2-newton", "thesis Algorithm 1: Newton with seeded random restarts"},
        {"optimal-l2-ceres", "Ceres least squares over the angle"},
        {"optimal-linf", "exact L-infinity optimum over the upper envelope of lines"},
        {"sweep", "brute force over all valid angles, best cell refined (for --metric)"},
        {"normal", "the axis bisecting the light's sweep of the visible points"},
        {"psm", "Stamminger & Drettakis: the lexel plane that samples like a PSM"},
        {"psm-thesis", "the thesis's reading of PSM, used in its tables"},
        {"plane-optimal", "Theorem 1 for the case's first segment"},
        {"split-greedy", "thesis Algorithm 2: greedy frustum merges, Lagrange lexel allocation"},
        {"split-dp", "the exact frustum split by dynamic programming, Lagrange allocation"},
    };
    for (const auto& [method, description] : kDescriptions)
        if (method == name) return description;
    return {};
}

bool IsFlatlandMethod(std::string_view name) {
    const auto& names = FlatlandMethodNames();
    return std::find(names.begin(), names.end(), name) != names.end();
}

namespace {

// Measures a single-frustum axis at full resolution. The decision pass may see a narrower sweep
// than the full pass, so an axis valid for it can be invalid at full resolution; it is then
// clamped one part in 1e3 of the valid range inside the nearer end, and the note says so.
MethodReport EvaluateAxis(const FlatScene& scene, const SamplingPass& full,
                          const LexelSamples& fullSamples, std::string method, double wsAxis,
                          std::string note, double solveMs, bool keepFootprints) {
    const ValidInterval valid = ValidTInterval(fullSamples);
    double t = std::tan(wsAxis - fullSamples.wsAxis0);
    if (!valid.Contains(t) || !std::isfinite(t)) {
        const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
        const double inset = 1e-3 * (xHi - xLo);
        double x = std::atan(t);
        if (!std::isfinite(t)) x = std::numbers::pi / 2;
        x = std::clamp(x, xLo + inset, xHi - inset);
        t = std::tan(x);
        note += (note.empty() ? "" : "; ") + std::string("angle clamped into the valid range");
    }
    const double axis = WsAxisFromT(fullSamples, t);
    auto footprints = FootprintsFromScratch(full, scene.wsLight, axis, scene.lexels);
    MethodReport report;
    report.method = std::move(method);
    report.lexelPlaneDeg = LexelPlaneDegFromAxis(axis);
    if (keepFootprints) {
        report.stats = SummarizeFootprints(*footprints);
        report.footprints = std::move(*footprints);
    } else {
        report.stats = SummarizeFootprintsInPlace(*footprints);
    }
    report.wsAxis = axis;
    report.solveMs = solveMs;
    report.note = std::move(note);
    return report;
}

}  // namespace

CaseReport RunFlatlandCase(const FlatScene& scene, std::span<const std::string> methods,
                           Metric metric, std::shared_ptr<const SamplingPass> fullPass,
                           const SamplingPass* decisionPass, bool keepFootprints) {
    for (const auto& m : methods)
        if (!IsFlatlandMethod(m))
            throw std::invalid_argument("unknown flatland method '" + m + "'");
    CheckSceneGeometry(scene);
    CaseReport report;
    report.caseName = scene.name;
    report.pixels = scene.camera.pixels;
    report.decisionPixels = scene.DecisionPixels();
    report.lexels = scene.lexels;
    report.metric = metric;

    Stopwatch timer;
    if (!fullPass)
        fullPass =
            std::make_shared<const SamplingPass>(RunSamplingPass(scene, scene.camera.pixels));
    const SamplingPass& full = *fullPass;
    report.fullPass = fullPass;
    // The decision pass is the full one unless the case asks for a coarser one (no copy).
    std::optional<SamplingPass> coarse;
    if (!decisionPass && scene.DecisionPixels() != scene.camera.pixels)
        coarse = RunSamplingPass(scene, scene.DecisionPixels());
    const SamplingPass& decision = decisionPass ? *decisionPass : coarse ? *coarse : full;
    report.samplingMs = timer.Ms();
    report.pixelsVisible = static_cast<int>(full.samples.size());
    // Only the frame of the full pass is needed (the axis's validity); the decision samples are
    // built when a single-frustum method first needs them and released before a split, whose
    // planning builds its own per frustum (flatland/memory.h counts one set at a time).
    const LexelSamples fullFrame = MakeLexelFrame(full, scene.lexels);
    std::optional<LexelSamples> samples;
    const auto decisionSamples = [&]() -> const LexelSamples& {
        if (!samples) samples = MakeLexelSamples(decision, scene.lexels);
        return *samples;
    };

    for (const std::string& method : methods) {
        timer.Restart();
        if (method == "split-greedy" || method == "split-dp") {
            samples.reset();
            const FrustaOptions options = scene.frusta.value_or(FrustaOptions{});
            const SplitResult split = SplitLightFrustum(
                decision, scene.lexels, options,
                method == "split-dp" ? SplitStrategy::kDynamicProgram : SplitStrategy::kGreedy);
            const double ms = timer.Ms();
            MethodReport r = EvaluateSplit(scene, full, split, keepFootprints);
            r.method = method;
            r.solveMs = ms;
            report.methods.push_back(std::move(r));
            continue;
        }
        AngleSolution solution;
        if (method == "optimal-l1")
            solution = SolveL1Exact(decisionSamples());
        else if (method == "optimal-l2")
            solution = SolveL2Exact(decisionSamples());
        else if (method == "optimal-l2-newton")
            solution = SolveL2Newton(decisionSamples());
        else if (method == "optimal-l2-ceres")
            solution = SolveL2Ceres(decisionSamples());
        else if (method == "optimal-linf")
            solution = SolveLinfExact(decisionSamples());
        else if (method == "sweep")
            solution = SolveSweep(decisionSamples(), metric);
        else {
            BaselineAxis axis;
            if (method == "normal")
                axis = NormalAxis(decision);
            else if (method == "psm")
                axis = PsmAxis(scene, decision);
            else if (method == "psm-thesis")
                axis = PsmThesisAxis(scene, decision);
            else
                axis = PlaneOptimalAxis(scene);
            solution.wsAxis = axis.wsAxis;
            solution.note = axis.note;
        }
        const double ms = timer.Ms();
        report.methods.push_back(EvaluateAxis(scene, full, fullFrame, method, solution.wsAxis,
                                              solution.note, ms, keepFootprints));
    }
    return report;
}

}  // namespace lexel::flatland
