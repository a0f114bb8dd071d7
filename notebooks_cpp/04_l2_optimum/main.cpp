// 04 — The L2 optimum three ways: the exact quartic, Newton with restarts, Ceres.
//
// L2 = Σ f_i² (Chong 2003, §2.1) penalizes the worst footprints more than L1 does. With the
// remapping of 02 (t = tan x, D(t) = (1 + tT_hi)(1 + tT_lo)),
//     Σ f_i(t)² = Q(t) / D(t)²,    Q(t) = Σ f0_i² (1 + tT_i)⁴ = Σ_k C(4,k) M_k t^k,
// five moments M_k = Σ f0_i² T_i^k. The derivative's numerator Q′D − 2QD′ loses its t⁵ terms: a
// quartic, solved exactly by the eigenvalues of its companion matrix (flatland/angle_solvers.h).
// The thesis found the critical point numerically instead, "too unwieldy to write in closed
// form" (§3.1): its Algorithm 1 runs Newton on dE/dx from guesses i·RandomOffset(), adding
// offsets while the result is invalid. Ceres minimizes ½Σ f_i² over x by automatic
// differentiation. This program runs all three and prints their optimum, iterations and time.
// The check: the three objectives agree to 1e-9 (relative), and L2 falls from initial to final.
//
// Public API: lexel::flatland (SolveL2Exact, SolveL2Newton, SolveL2Ceres), lexel::Stopwatch.
// Figure: the program's own plot helper.
//
//   ./build/notebooks_cpp/notebook_04_l2_optimum [OUT_DIR]        (default out/notebooks/)
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "flat_scene.h"
#include "lexel/flatland.h"
#include "lexel/solvers/stopwatch.h"
#include "notebook.h"
#include "plot.h"

int main(int argc, char** argv) {
    using namespace lexel;
    using namespace lexel::flatland;
    using notebooks::Series;
    const auto outDir = notebooks::OutputDirectory(argc, argv);
    const LexelSamples samples = notebooks::TeachingSamples();
    const double initial = AngleObjective(samples, Metric::kL2, 0.0);
    notebooks::PrintAngle("initial (normal):", samples.wsAxis0, "L2", initial);

    struct Solver {
        const char* name;
        std::function<AngleSolution()> solve;
    };
    const Solver solvers[] = {{"exact quartic", [&] { return SolveL2Exact(samples); }},
                              {"Newton restarts", [&] { return SolveL2Newton(samples); }},
                              {"Ceres", [&] { return SolveL2Ceres(samples); }}};
    const double deg = 180 / std::numbers::pi;
    Series curve("L2 = Σ f²"), optima("optima", Series::Style::kPoints, std::nullopt, 6);
    std::vector<AngleSolution> found;
    for (const Solver& solver : solvers) {
        constexpr int kRepeats = 20;  // a solve takes microseconds to milliseconds: average it
        Stopwatch stopwatch;
        AngleSolution s;
        for (int r = 0; r < kRepeats; ++r) s = solver.solve();
        const double ms = stopwatch.Ms() / kRepeats;
        char note[96];
        std::snprintf(note, sizeof note, "%s: %d iterations, %.4f ms%s%s", solver.name,
                      s.iterations, ms, s.note.empty() ? "" : "; ", s.note.c_str());
        notebooks::PrintAngle("final:", s.wsAxis, "L2", s.objective, note);
        optima.Add(std::atan(s.t) * deg, s.objective);
        found.push_back(s);
    }
    std::printf(
        "(iterations: Newton steps over all restarts, Ceres iterations over all starts,\n"
        " the quartic's candidate roots evaluated)\n");
    std::printf("RMS footprint %.4f → %.4f pixels per lexel\n", std::sqrt(initial / samples.size()),
                std::sqrt(found[0].objective / samples.size()));

    notebooks::Claims claims;
    for (std::size_t k = 1; k < found.size(); ++k) {
        const double rel = std::abs(found[k].objective / found[0].objective - 1);
        claims.Check(rel < 1e-9,
                     "%s agrees with the exact quartic: L2 differs by %.1e (< 1e-9), "
                     "angle by %.1e°",
                     solvers[k].name, rel,
                     std::abs(std::atan(found[k].t) - std::atan(found[0].t)) * deg);
    }
    claims.Check(found[0].objective < initial, "L2 falls from initial to final: %.6f → %.6f",
                 initial, found[0].objective);

    const ValidInterval valid = ValidTInterval(samples);
    for (int k = 1; k < 400; ++k) {
        const double t = valid.lo + (valid.hi - valid.lo) * k / 400.0;
        const double value = AngleObjective(samples, Metric::kL2, t);
        if (value < 1.25 * initial) curve.Add(std::atan(t) * deg, value);
    }
    const auto figure = outDir / "04_l2_optimum.png";
    notebooks::Panel plot("L2 over the valid lexel planes (three solvers, one optimum)",
                          "film turn x from the normal map (degrees)", "Σ f²");
    plot.series = {curve, optima};
    notebooks::WritePlot(figure, {plot});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
