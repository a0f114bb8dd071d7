// 06 — Splitting the light frustum: greedy merges (Algorithm 2), the exact DP, Lagrange lexels.
//
// One film cannot serve a plank that points at the light and the floor around it (projection
// aliasing, Chong 2003 §3.2). Split the light's angular range evenly into `max` wedges; group
// adjacent non-empty wedges into at most `budget` frusta, each with its own optimal film. Frustum
// j's error at one lexel is e_j; with N_j lexels it is e_j / N_j^k (k = 1 for L1, 2 for L2).
// Lagrange multipliers for Σ N_j = L give (solvers/lagrange_allocation.h)
//     N_j = L e_j^(1/(k+1)) / Σ_i e_i^(1/(k+1)),    total = (Σ_j e_j^(1/(k+1)))^(k+1) / L^k,
// a sum of per-frustum terms: so besides the thesis's greedy merging (Algorithm 2), a dynamic
// program over contiguous groupings finds the best split exactly. The checks: the DP total is no
// worse than greedy; the closed-form total equals Σ e_j / N_j at the Lagrange allocation, and
// moving lexels between frusta only raises it; at full resolution the split beats one frustum.
//
// Public API: lexel::flatland (SplitLightFrustum, RunFlatlandCase), lexel::solvers (Lagrange
// allocation). Figure: the case layer's diagram and footprint plot (lexel::cases).
//
//   ./build/notebooks_cpp/notebook_06_frustum_split [OUT_DIR]        (default out/notebooks/)
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "lexel/cases/plot/case_figure.h"
#include "lexel/flatland.h"
#include "lexel/solvers/lagrange_allocation.h"
#include "notebook.h"

namespace {

// Σ e_j / N_j^k at real-valued lexel counts.
double Total(const std::vector<double>& e, const std::vector<double>& n, int k) {
    double total = 0;
    for (std::size_t j = 0; j < e.size(); ++j) total += e[j] / std::pow(n[j], k);
    return total;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace lexel;
    using namespace lexel::flatland;
    const auto outDir = notebooks::OutputDirectory(argc, argv);
    // The thesis's "Projection Aliasing" case (§4.1.3, reconstructed in cases/flatland/): a plank
    // within 4.6° of the light's direction, facing the viewer, on a floor.
    FlatScene scene;
    scene.camera.wsPosition = {0, 2.5};
    scene.camera.wsDirection = Vec2(1, -0.2).normalized();
    scene.camera.near = 0.1, scene.camera.far = 200;
    scene.wsLight = {5, 20};
    scene.decisionPixels = 100;
    scene.frusta = FrustaOptions{16, 2, Metric::kL1};
    scene.geometry = {{{-5, 0}, {40, 0}}, {{10, 0}, {9.6715, 1.9728}}};

    const SamplingPass decision = RunSamplingPass(scene, scene.DecisionPixels());
    FrustaOptions one = *scene.frusta;
    one.budget = 1;
    const SplitResult single =
        SplitLightFrustum(decision, scene.lexels, one, SplitStrategy::kDynamicProgram);
    const SplitResult greedy =
        SplitLightFrustum(decision, scene.lexels, *scene.frusta, SplitStrategy::kGreedy);
    const SplitResult dp =
        SplitLightFrustum(decision, scene.lexels, *scene.frusta, SplitStrategy::kDynamicProgram);
    const double deg = 180 / std::numbers::pi;
    std::printf("%d non-empty wedges of %d; budget %d frusta, %d lexels, L1\n", dp.wedges,
                scene.frusta->max, scene.frusta->budget, scene.lexels);
    const std::pair<const char*, const SplitResult*> splits[] = {
        {"one frustum", &single}, {"greedy", &greedy}, {"DP", &dp}};
    for (const auto& [name, split] : splits) {
        std::printf("%-12s Σ e_j/N_j = %.6f:", name, split->realTotal);
        for (const PlannedFrustum& f : split->frusta)
            std::printf("  [%.2f°, %.2f°] plane %.2f° e = %.2f N = %d", f.lsLow * deg,
                        f.lsHigh * deg, LexelPlaneDegFromAxis(f.wsAxis), f.unitError, f.lexels);
        std::printf("\n");
    }

    notebooks::Claims claims;
    claims.Check(dp.realTotal <= greedy.realTotal * (1 + 1e-12),
                 "the DP is no worse than greedy merging: %.9f <= %.9f", dp.realTotal,
                 greedy.realTotal);
    std::vector<double> e;
    for (const PlannedFrustum& f : dp.frusta) e.push_back(f.unitError);
    const int k = dp.exponent;
    std::vector<double> n = AllocateLexelsReal(e, k, scene.lexels);
    double termSum = 0;
    for (double ej : e) termSum += AllocationTerm(ej, k);
    const double closedForm = AllocatedTotal(termSum, k, scene.lexels), atLagrange = Total(e, n, k);
    claims.Check(std::abs(closedForm / atLagrange - 1) < 1e-12 &&
                     std::abs(closedForm / dp.realTotal - 1) < 1e-12,
                 "Lagrange: (Σ e_j^(1/2))² / L = %.9f = Σ e_j/N_j = %.9f", closedForm, atLagrange);
    bool raised = true;
    for (double shift : {-5.0, -0.5, 0.5, 5.0}) {  // lexels moved from frustum 0 to the last
        std::vector<double> moved = n;
        moved.front() -= shift, moved.back() += shift;
        raised = raised && Total(e, moved, k) > atLagrange;
    }
    claims.Check(raised, "moving ±0.5 or ±5 lexels between the frusta raises the total");

    // Every number again at full resolution, measured from scratch (the thesis's tables).
    const std::vector<std::string> methods = {"optimal-l1", "split-greedy", "split-dp"};
    const CaseReport report = RunFlatlandCase(scene, methods, Metric::kL1, nullptr, nullptr,
                                              /*keepFootprints=*/true);
    for (const MethodReport& m : report.methods)
        std::printf("full resolution %-13s average f %.4f  worst %.4f\n", m.method.c_str(),
                    m.stats.average, m.stats.worst());
    std::printf("average footprint, one frustum → split (DP): %.4f → %.4f pixels per lexel\n",
                report.methods[0].stats.average, report.methods[2].stats.average);
    claims.Check(report.methods[2].stats.average < report.methods[0].stats.average,
                 "at full resolution the split beats one frustum: %.4f < %.4f",
                 report.methods[2].stats.average, report.methods[0].stats.average);
    const auto figure = outDir / "06_frustum_split.png";
    cases::WriteCaseFigure(figure.string(), scene, report);
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
