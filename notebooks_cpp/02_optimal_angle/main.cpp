// 02 — The optimal lexel plane, exactly.
//
// Rotating the film by x (t = tan x) rescales every footprint by the same rational function
// (Chong 2003, §3.1; flatland/lexel_remap.h, eq. R2):
//     f_i(t) = f0_i (1 + t T_i)² / ((1 + t T_hi)(1 + t T_lo)),
// so Σ f_i is a ratio of two quadratics whose numerator needs only three moments of the samples
// and whose critical points are the roots of one quadratic. This program takes an
// example (a floor and a small polyline), prints the L1 objective at the initial (normal) angle,
// solves it in closed form, cross-checks with a brute-force sweep, and prints initial → final.
//
//   ./build/notebooks_cpp/notebook_02_optimal_angle
#include <cstdio>

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/sampling.h"

int main() {
    using namespace lexel;
    using namespace lexel::flatland;
    FlatScene scene;
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(1, -0.25).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = 1000;
    scene.wsLight = {-3, 10};
    scene.lexels = 1000;
    scene.geometry = {{{-50, 0}, {200, 0}}, {{6, 0}, {6, 2}, {8, 2.5}}};

    const LexelSamples samples = MakeLexelSamples(RunSamplingPass(scene, 1000), scene.lexels);
    const L1Moments m = ComputeL1Moments(samples);
    std::printf("moments: S0 = %.6f  S1 = %.6f  S2 = %.6f   (extents T_lo = %.4f, T_hi = %.4f)\n",
                m.s0, m.s1, m.s2, samples.tanLow, samples.tanHigh);
    const double initial = AngleObjective(samples, Metric::kL1, 0.0);
    const AngleSolution exact = SolveL1Exact(samples);
    const AngleSolution sweep = SolveSweep(samples, Metric::kL1);
    std::printf("initial (normal): lexel plane %8.4f°  L1 = %.6f\n",
                LexelPlaneDegFromAxis(samples.wsAxis0), initial);
    std::printf("final (exact):    lexel plane %8.4f°  L1 = %.6f  (%d candidate roots evaluated)\n",
                LexelPlaneDegFromAxis(exact.wsAxis), exact.objective, exact.iterations);
    std::printf("sweep check:      lexel plane %8.4f°  L1 = %.6f  (%d objective evaluations)\n",
                LexelPlaneDegFromAxis(sweep.wsAxis), sweep.objective, sweep.iterations);
    std::printf("average footprint %.4f → %.4f pixels per lexel\n", initial / samples.size(),
                exact.objective / samples.size());
}
