// 05 — The L∞ optimum and the upper envelope of lines.
//
// L∞ = max_i f_i, the worst pixel (Chong 2003, §2.1). The thesis set it aside because the max
// is not differentiable; it is nonetheless exact. With the remapping of 02,
//     f_i(t) = (√f0_i (1 + tT_i))² / D(t),    so    max_i f_i(t) = E(t)² / D(t),
// where E(t) = max_i √f0_i (1 + tT_i) is the upper envelope of straight lines in t (each line is
// positive on the valid interval). On one piece of the envelope, E = a + bt, and the minimum of
// (a + bt)² / (1 + pt + qt²) solves a linear equation; the global minimum is the least value over
// the pieces' critical points and breakpoints (flatland/angle_solvers.h). This program draws the
// lines and their envelope, and compares the exact optimum with a brute-force sweep. The checks:
// E²/D equals the per-sample max at every plotted t (1e-12), and the exact angle equals the
// sweep's to 1e-6° with an objective no worse.
//
// Public API: lexel::flatland (SolveLinfExact, SolveSweep, AngleObjective). Figure: the
// program's own plot helper.
//
//   ./build/notebooks_cpp/notebook_05_linf_envelope [OUT_DIR]        (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "flat_scene.h"
#include "lexel/flatland.h"
#include "notebook.h"
#include "plot.h"

int main(int argc, char** argv) {
    using namespace lexel;
    using namespace lexel::flatland;
    using notebooks::Series;
    const auto outDir = notebooks::OutputDirectory(argc, argv);
    const LexelSamples samples = notebooks::TeachingSamples();
    const double initial = AngleObjective(samples, Metric::kLinf, 0.0);
    const AngleSolution exact = SolveLinfExact(samples);
    const AngleSolution sweep = SolveSweep(samples, Metric::kLinf);
    const double deg = 180 / std::numbers::pi;
    notebooks::PrintAngle("initial (normal):", samples.wsAxis0, "worst f", initial);
    notebooks::PrintAngle("final (envelope):", exact.wsAxis, "worst f", exact.objective,
                          std::to_string(exact.iterations) + " candidates");
    notebooks::PrintAngle("sweep check:", sweep.wsAxis, "worst f", sweep.objective,
                          std::to_string(sweep.iterations) + " evaluations");

    // The lines √f0_i (1 + tT_i), a few of them drawn, and their envelope over all samples.
    const ValidInterval valid = ValidTInterval(samples);
    const double tLo = valid.lo + 0.02 * (valid.hi - valid.lo),
                 tHi = valid.hi - 0.02 * (valid.hi - valid.lo);
    notebooks::Panel lines("lines √f0_i (1 + t T_i) and their upper envelope E(t)", "t = tan x",
                           "√f0 (1 + tT)");
    notebooks::Panel worst("L∞ = E(t)² / D(t) over the valid lexel planes",
                           "film turn x from the normal map (degrees)", "max f", true);
    for (std::size_t i = 0; i < samples.size(); i += samples.size() / 24) {
        const double a = std::sqrt(samples.footprint0[i]);
        Series line("", Series::Style::kLine, notebooks::Rgb{0.6, 0.6, 0.6}, 1.0);
        line.Add(tLo, a * (1 + tLo * samples.tanOffset[i]));
        line.Add(tHi, a * (1 + tHi * samples.tanOffset[i]));
        lines.series.push_back(line);
    }
    Series envelope("E(t)", Series::Style::kLine, notebooks::PaletteColour(0), 3.0), curve("max f");
    double maxRel = 0;
    for (int k = 0; k <= 400; ++k) {
        const double t = tLo + (tHi - tLo) * k / 400.0;
        double e = 0;
        for (std::size_t i = 0; i < samples.size(); ++i)
            e = std::max(e, std::sqrt(samples.footprint0[i]) * (1 + t * samples.tanOffset[i]));
        const double viaEnvelope = e * e / ((1 + t * samples.tanHigh) * (1 + t * samples.tanLow));
        const double direct = AngleObjective(samples, Metric::kLinf, t);
        maxRel = std::max(maxRel, std::abs(viaEnvelope / direct - 1));
        envelope.Add(t, e);
        curve.Add(std::atan(t) * deg, direct);
    }
    lines.series.push_back(envelope);
    Series optima("initial, optimum", Series::Style::kPoints, std::nullopt, 6.0);
    optima.Add(0.0, initial);
    optima.Add(std::atan(exact.t) * deg, exact.objective);
    worst.series = {curve, optima};

    notebooks::Claims claims;
    claims.Check(maxRel < 1e-12, "max f = E(t)²/D(t) at 401 angles: max relative difference %.1e",
                 maxRel);
    const double exactDeg = LexelPlaneDegFromAxis(exact.wsAxis);
    const double sweepDeg = LexelPlaneDegFromAxis(sweep.wsAxis);
    claims.Check(
        std::abs(exactDeg - sweepDeg) <= 1e-6 && exact.objective <= sweep.objective * (1 + 1e-12),
        "envelope optimum %.9f° = sweep's %.9f° to 1e-6°, worst f %.9f <= %.9f", exactDeg, sweepDeg,
        exact.objective, sweep.objective);
    std::printf("worst footprint %.4f → %.4f pixels per lexel\n", initial, exact.objective);
    const auto figure = outDir / "05_linf_envelope.png";
    notebooks::WritePlot(figure, {lines, worst});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
