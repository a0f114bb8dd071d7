// 01 — Why shadows alias: the footprint dp/dl.
//
// A flatland camera sees a floor; a point light above it renders a 1D shadow map of N lexels.
// Pixel p sees floor point X(p); the light stores X in lexel l(X). The footprint f = |dp/dl| is
// how many pixels one lexel covers (Chong 2003, §2.1): f > 1 means blocky shadows there (many
// pixels share a lexel), f < 1 means lexels wasted on supersampling. Turning the light's film
// (the lexel plane) changes which pixels get the lexels: this program prints f at a few pixels
// for three film angles, and the L1/L∞ norms over all visible pixels. Theorem 1 (§2.2.1): with
// the film parallel to the line from the light to q, where the floor meets the camera's view
// plane, f is the same at every pixel. The check: max f / min f − 1 < 1e-9 at that angle.
//
// Public API: lexel::flatland (sampling pass, FootprintsFromScratch, PlaneOptimalAxis). Figure:
// the program's own plot helper.
//
//   ./build/notebooks_cpp/notebook_01_footprint [OUT_DIR]        (default out/notebooks/)
#include <algorithm>
#include <cstdio>
#include <numbers>

#include "flat_scene.h"
#include "lexel/flatland.h"
#include "notebook.h"
#include "plot.h"

int main(int argc, char** argv) {
    using namespace lexel::flatland;
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const FlatScene scene = lexel::notebooks::TeachingScene(false);

    const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
    std::printf("%zu of %d pixels see the floor\n\n", pass.samples.size(), pass.pixels);
    std::printf("%12s", "film angle");
    for (std::size_t i = 0; i < pass.samples.size(); i += pass.samples.size() / 5)
        std::printf("  f(p=%4d)", pass.samples[i].pixel);
    std::printf("  %10s  %8s\n", "L1 = Σf", "L∞");
    // The normal shadow map (axis bisecting the light's view), Theorem 1's angle, and a bad one.
    const double normal = pass.wsAxis0;
    const double theorem1 =
        std::atan2(-10.0, 2.5) + std::numbers::pi / 2;  // film ∥ light → (−0.5, 0)
    const char* names[] = {"normal", "Theorem 1", "normal - 34°"};
    lexel::notebooks::Panel plot("footprint f = |dp/dl| across the image", "pixel p",
                                 "f (pixels per lexel)", true);
    std::vector<double> theoremF;
    int k = 0;
    for (double axis : {normal, theorem1, normal - 0.6}) {
        const auto f = FootprintsFromScratch(pass, scene.wsLight, axis, scene.lexels);
        std::printf("%10.2f° ", LexelPlaneDegFromAxis(axis));
        double l1 = 0, linf = 0;
        for (double v : *f) l1 += v, linf = std::max(linf, v);
        for (std::size_t i = 0; i < f->size(); i += f->size() / 5) std::printf("  %9.4f", (*f)[i]);
        std::printf("  %10.2f  %8.4f\n", l1, linf);
        lexel::notebooks::Series series(names[k++]);
        for (std::size_t i = 0; i < f->size(); ++i)
            series.Add(PixelCenter(pass.samples[i]), (*f)[i]);
        plot.series.push_back(series);
        if (axis == theorem1) theoremF = *f;
    }
    std::printf(
        "\nAt Theorem 1's angle the footprint is the same at every pixel: the floor is\n"
        "sampled by the light exactly as densely as the camera needs it.\n");

    lexel::notebooks::Claims claims;
    const auto [fMin, fMax] = std::minmax_element(theoremF.begin(), theoremF.end());
    claims.Check(*fMax / *fMin - 1 < 1e-9, "Theorem 1: f is constant, max/min - 1 = %.2e < 1e-9",
                 *fMax / *fMin - 1);
    // The library's plane-optimal baseline finds the same film (an axis is defined modulo π).
    const double planeOptimal = LexelPlaneDegFromAxis(PlaneOptimalAxis(scene).wsAxis);
    claims.Check(std::abs(planeOptimal - LexelPlaneDegFromAxis(theorem1)) < 1e-9,
                 "PlaneOptimalAxis gives the same film: %.9f° vs %.9f°", planeOptimal,
                 LexelPlaneDegFromAxis(theorem1));
    const auto figure = outDir / "01_footprint.png";
    lexel::notebooks::WritePlot(figure, {plot});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
