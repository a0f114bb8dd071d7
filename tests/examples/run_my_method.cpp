// Runs the methods of my_method.cpp on the shipped walkthrough case
// (cases/spatial/walkthrough.json, its first light, a 320 × 240 frame to keep it short) beside
// focused-tight, prints their numbers, and checks them: my-focused is focused-tight bit for bit,
// and focused-wide's h is focused-tight's times s², s = (1 + 4m) / (1 + m) with m the margin: its
// map is focused-tight's scaled down by s about the centre on both axes, and h (report eq. 6, the
// squared Frobenius norm of the inverse Jacobian) scales by s². Exits 1 when a check fails.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/render_backend.h"

int main(int argc, char** argv) {
    using namespace lexel::spatial;
    const std::filesystem::path cases = argc > 1 ? argv[1] : LEXEL_CASES_DIR;
    Scene scene = lexel::cases::LoadSpatialScene(cases / "spatial/walkthrough.json");
    scene.camera.resolution = {320, 240};
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"focused-tight", "my-focused", "focused-wide"};
    const LightOutcome o = evaluator.Evaluate(scene.lights.front(), options);

    std::printf("walkthrough, light 0, %lld counted pixels\n",
                static_cast<long long>(o.receiverPixels));
    std::printf("%-14s %13s %10s %16s\n", "method", "misclassified", "uncovered", "h");
    for (const MethodOutcome& m : o.methods)
        std::printf("%-14s %13lld %10lld %16.10g\n", m.method.c_str(),
                    static_cast<long long>(m.metrics.misclassified),
                    static_cast<long long>(m.metrics.uncovered), m.metrics.h);

    const MethodOutcome &tight = o.methods[0], &mine = o.methods[1], &wide = o.methods[2];
    const double margin = BaselineContext{}.margin;
    const double s = (1.0 + 4.0 * margin) / (1.0 + margin);
    const bool registered = IsSpatialMethod("my-focused") &&
                            SpatialMethodNames().back() == "focused-wide" &&
                            !SpatialMethodDescription("focused-wide").empty();
    const bool same = mine.metrics.misclassified == tight.metrics.misclassified &&
                      mine.metrics.h == tight.metrics.h &&
                      mine.metrics.uncovered == tight.metrics.uncovered;
    const bool scaled = std::abs(wide.metrics.h / (s * s * tight.metrics.h) - 1.0) < 1e-9;
    std::printf("my-focused is focused-tight: %s\n", same ? "yes" : "NO");
    std::printf("focused-wide h / focused-tight h = %.12f, s^2 = %.12f: %s\n",
                wide.metrics.h / tight.metrics.h, s * s, scaled ? "yes" : "NO");
    return registered && same && scaled && o.receiverPixels > 0 ? 0 : 1;
}
