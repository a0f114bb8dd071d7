// 02 — The lexel remapping dl/dl′(x): every footprint at every film angle from one pass.
//
// One sampling pass at the initial axis θ0 records, per pixel, its light angle α and g = |dp/dα|.
// Turning the film by x (t = tan x) changes each footprint by one factor (Chong 2003, §3.1; the
// thesis's dl/dl′(x), re-derived in flatland/lexel_remap.h, eq. R2):
//     f(t) = f0 · dl/dl′,    dl/dl′ = (1 + tT)² / ((1 + tT_hi)(1 + tT_lo)),    T = tan(α − θ0),
// with T_lo, T_hi the extreme samples' T. The film is valid while every visible point is in front
// of it, t ∈ (−1/T_hi, −1/T_lo); at either end the factor blows up. This program remaps the pass
// to several angles and compares with footprints recomputed from scratch in world space (film
// coordinates, tight extents, dl/dλ along each segment). The check: they agree to 1e-9 relative
// at every pixel of every valid angle, and the invalid angle is rejected by both.
//
// Public API: lexel::flatland (MakeLexelSamples, RemappedFootprints, FootprintsFromScratch).
// Figure: the program's own plot helper.
//
//   ./build/notebooks_cpp/notebook_02_lexel_remap [OUT_DIR]        (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "flat_scene.h"
#include "lexel/flatland.h"
#include "notebook.h"
#include "plot.h"

int main(int argc, char** argv) {
    using namespace lexel::flatland;
    using lexel::notebooks::Series;
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const FlatScene scene = lexel::notebooks::TeachingScene(true);
    const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
    const LexelSamples samples = MakeLexelSamples(pass, scene.lexels);
    const ValidInterval valid = ValidTInterval(samples);
    const double deg = 180 / std::numbers::pi;
    std::printf("%zu visible pixels; initial lexel plane %.4f°; valid turns x ∈ (%.3f°, %.3f°)\n",
                samples.size(), LexelPlaneDegFromAxis(samples.wsAxis0), std::atan(valid.lo) * deg,
                std::atan(valid.hi) * deg);
    const std::size_t mid = samples.size() / 2;
    std::printf("%8s %12s %14s %14s %26s\n", "turn x", "lexel plane", "dl/dl' at mid", "f at mid",
                "max |remapped/scratch - 1|");

    lexel::notebooks::Panel factors("the remapping dl/dl'(x) across the lexels", "lexel l at x = 0",
                                    "dl/dl'", true);
    lexel::notebooks::Panel footprints("remapped (lines) and recomputed (dots) footprints",
                                       "pixel p", "f (pixels per lexel)", true);
    lexel::notebooks::Claims claims;
    double worst = 0;
    bool agreeOnValidity = true;
    for (double xDeg : {-30.0, -15.0, 0.0, 15.0, 30.0, 60.0, 80.0}) {
        const double t = std::tan(xDeg / deg);
        const std::vector<double> remapped = RemappedFootprints(samples, t);
        const auto scratch =
            FootprintsFromScratch(pass, scene.wsLight, WsAxisFromT(samples, t), scene.lexels);
        agreeOnValidity = agreeOnValidity && valid.Contains(t) == scratch.has_value();
        if (!scratch) {
            std::printf("%7.1f° %12s   invalid: a visible point is behind the film\n", xDeg, "");
            continue;
        }
        double maxRel = 0;
        const auto colour = lexel::notebooks::PaletteColour(factors.series.size());
        Series factor(std::to_string(int(xDeg)) + "°", Series::Style::kLine, colour);
        Series line(factor.label, Series::Style::kLine, colour);
        Series dots("", Series::Style::kPoints, colour);
        for (std::size_t i = 0; i < samples.size(); ++i) {
            maxRel = std::max(maxRel, std::abs(remapped[i] / (*scratch)[i] - 1));
            factor.Add(LexelCoordinate(samples, i),
                       RemapFactor(samples.tanOffset[i], t, samples.tanLow, samples.tanHigh));
            line.Add(PixelCenter(pass.samples[i]), remapped[i]);
            if (i % 40 == 0) dots.Add(PixelCenter(pass.samples[i]), (*scratch)[i]);
        }
        worst = std::max(worst, maxRel);
        std::printf("%7.1f° %11.4f° %14.6f %14.6f %26.2e\n", xDeg,
                    LexelPlaneDegFromAxis(WsAxisFromT(samples, t)), factor.y[mid], remapped[mid],
                    maxRel);
        factors.series.push_back(factor);
        footprints.series.push_back(line);
        footprints.series.push_back(dots);
    }
    std::printf("initial → final at the middle pixel: f = %.6f (x = 0) → %.6f (x = 30°)\n",
                samples.footprint0[mid], RemappedFootprints(samples, std::tan(30 / deg))[mid]);
    claims.Check(agreeOnValidity, "the valid interval and the world-space film agree at every x");
    claims.Check(worst < 1e-9, "remapped = recomputed: max relative difference %.2e < 1e-9", worst);
    const auto figure = outDir / "02_lexel_remap.png";
    lexel::notebooks::WritePlot(figure, {factors, footprints});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
