// 07 — How many pixels does the decision need? (Chong 2003, §4.1.1, Fig. 4.1)
//
// The optimal lexel plane is chosen from an initial low-resolution pass (§3: "a single initial
// low resolution rendering"); the shadows are then seen at full resolution. The thesis measures
// what the shortcut costs: the angle chosen from K pixels, measured at full resolution, against
// the full-resolution optimum, as a percent increase of the error. Error is the average footprint
// for L1, the mean + σ for L2 (L2 "provides concentration around the mean"), and the worst for L∞
// (§4.1.1): "most of the scene configurations gain less than five percent additional error when
// using angles determined from ten samples". This program repeats the study on one scene. The
// checks: no decision beats the full-resolution optimum on the error its metric minimizes
// (L1, L∞: extra ≥ 0), the full-resolution decision costs nothing, and ten pixels cost < 5% in L1.
//
// Public API: lexel::flatland (RunSamplingPass, RunFlatlandCase with a decision pass). Figure:
// lexel's Fig. 4.1 plot (cases/plot/curve_plot.h).
//
//   ./build/notebooks_cpp/notebook_07_lowres_decision [OUT_DIR]        (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "flat_scene.h"
#include "lexel/cases/plot/curve_plot.h"
#include "lexel/flatland.h"
#include "notebook.h"

int main(int argc, char** argv) {
    using namespace lexel;
    using namespace lexel::flatland;
    const auto outDir = notebooks::OutputDirectory(argc, argv);
    const FlatScene scene = notebooks::TeachingScene(true);
    const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "optimal-linf"};
    const char* labels[] = {"L1 (average)", "L2 (mean + σ)", "L∞ (worst)"};
    const auto error = [](const FootprintStats& s, int metric) {
        return metric == 0 ? s.average : metric == 1 ? s.meanPlusSigma : s.worst();
    };
    // The reference: every method decided and measured at full resolution.
    const auto fullPass =
        std::make_shared<const SamplingPass>(RunSamplingPass(scene, scene.camera.pixels));
    const CaseReport reference = RunFlatlandCase(scene, methods, Metric::kL1, fullPass, &*fullPass);
    std::printf("full resolution (%d pixels): average f %.4f, mean + σ %.4f, worst %.4f\n",
                scene.camera.pixels, error(reference.methods[0].stats, 0),
                error(reference.methods[1].stats, 1), error(reference.methods[2].stats, 2));
    std::printf("%16s %14s %14s %14s\n", "decision pixels", labels[0], labels[1], labels[2]);

    std::vector<cases::LowresCurve> curves(3);
    double leastExtra[3] = {INFINITY, INFINITY, INFINITY}, fullExtra[3] = {}, tenPixelsL1 = NAN;
    for (int k : {5, 10, 20, 50, 100, 200, scene.camera.pixels}) {
        FlatScene low = scene;
        low.decisionPixels = k;
        const SamplingPass decision = RunSamplingPass(low, k);
        const CaseReport report = RunFlatlandCase(low, methods, Metric::kL1, fullPass, &decision);
        std::printf("%16d", k);
        for (int m = 0; m < 3; ++m) {
            const double extra =
                100.0 *
                (error(report.methods[m].stats, m) / error(reference.methods[m].stats, m) - 1.0);
            std::printf(" %13.3f%%", extra);
            curves[m].label = labels[m];
            curves[m].pixels.push_back(k);
            curves[m].extraPercent.push_back(std::max(extra, 0.0));  // log-scale plot
            leastExtra[m] = std::min(leastExtra[m], extra);
            if (k == scene.camera.pixels) fullExtra[m] = extra;
            if (k == 10 && m == 0) tenPixelsL1 = extra;
        }
        std::printf("\n");
    }
    std::printf("L1 with 10 decision pixels instead of %d: +%.3f%% average footprint\n",
                scene.camera.pixels, tenPixelsL1);
    std::printf("(L2 minimizes Σf², not mean + σ: a coarse decision may land lower on mean + σ)\n");

    notebooks::Claims claims;
    for (int m : {0, 2})
        claims.Check(leastExtra[m] >= -1e-9,
                     "no decision beats the full optimum in %s (least %+.2e%%)", labels[m],
                     leastExtra[m]);
    claims.Check(fullExtra[0] == 0 && fullExtra[1] == 0 && fullExtra[2] == 0,
                 "the full-resolution decision costs nothing (%g%%, %g%%, %g%%)", fullExtra[0],
                 fullExtra[1], fullExtra[2]);
    claims.Check(tenPixelsL1 < 5.0, "thesis §4.1.1: ten pixels cost less than 5%% in L1 (%.3f%%)",
                 tenPixelsL1);
    const auto figure = outDir / "07_lowres_decision.png";
    cases::WriteLowresPlot(figure.string(), "extra error of a low-resolution decision", curves);
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
