// 10 — The scene-optimized light matrix in 3D (Chong & Gortler, Algorithm 1).
//
// The light matrix P maps a light-space point X to the shadow map at u^i = p_i·X / p4·X. Its
// fourth row p4 is the optical axis; the first two rows only stretch, shear and shift the map.
// Algorithm 1 reads back a low-resolution view of the scene, keeps the pixels near shadow
// boundaries (the samples), and minimizes the energy
//     h(P) = Σ_samples ||(∂u/∂x)⁻¹||²_F            (report eq. 6)
// — how many screen pixels one texel covers, squared, summed — by rotating p4 against the
// gradient ∂h/∂p4 (Appendix A) and re-fitting the map's rectangle around the visible points after
// every rotation. This program runs it for the walkthrough case's point light from the focused
// map's axis (the report's method, `optimal-report`, at the report's 180² readback), prints h
// after each iteration (initial → final), compares the misclassified pixels with the focused
// map, and writes the report's Fig. 2: the optimized shadow map with the samples in red. The
// checks: h never rises from one iteration to the next, and ends below where it started.
//
// Public API: lexel::spatial (the optimizer behind `optimal-report`). The scene, its rendering,
// exact shadow rays and the image: lexel's test bench (lexel::harness, lexel::cases).
//
//   ./build/notebooks_cpp/notebook_10_algorithm1_3d [OUT_DIR]    (default out/notebooks/)
#include <cstdio>
#include <filesystem>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/images.h"
#include "notebook.h"

int main(int argc, char** argv) {
    using namespace lexel::spatial;
    const std::filesystem::path outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const std::string outPath = (outDir / "10_algorithm1_3d.png").string();
    // The report's set-up: a 180² readback, every sample to the search (the case ships 720²
    // with a budget of 512 samples, for `optimal`).
    const Scene scene = WithReportReadback(lexel::cases::LoadSpatialScene(
        std::filesystem::path(LEXEL_CASES_DIR) / "spatial/walkthrough.json"));
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);  // renders the frame and the 180² readback once

    EvaluationOptions options;
    options.methods = {"focused", "optimal-report"};
    options.keepBuffers = true;
    const LightOutcome o = evaluator.Evaluate(scene.lights.front(), options);
    std::printf("%zu readback pixels see geometry; %zu are boundary samples for this light\n",
                o.samples.lsRelevant.size(), o.samples.lsX.size());

    const MethodOutcome& focused = o.methods[0];
    const MethodOutcome& optimal = o.methods[1];
    std::printf("h per Algorithm 1 iteration (start: the focused axis):\n");
    for (std::size_t i = 0; i < optimal.trace.hAfterIteration.size(); ++i)
        std::printf("  iteration %zu: h = %.6g\n", i, optimal.trace.hAfterIteration[i]);
    std::printf("optical axis p4: (%.4f, %.4f, %.4f) -> (%.4f, %.4f, %.4f)\n", focused.matrix.p4.x,
                focused.matrix.p4.y, focused.matrix.p4.z, optimal.matrix.p4.x, optimal.matrix.p4.y,
                optimal.matrix.p4.z);
    std::printf("misclassified pixels (vs exact shadow rays): focused %lld -> optimal %lld\n",
                static_cast<long long>(focused.metrics.misclassified),
                static_cast<long long>(optimal.metrics.misclassified));

    lexel::notebooks::Claims claims;
    const std::vector<double>& h = optimal.trace.hAfterIteration;
    bool falling = h.size() >= 2;
    for (std::size_t i = 1; i < h.size(); ++i) falling = falling && h[i] <= h[i - 1];
    claims.Check(falling, "h never rises across the %zu iterations", h.size() - 1);
    claims.Check(h.size() >= 2 && h.back() < h.front() && optimal.metrics.h == h.back(),
                 "h falls from initial to final: %.6g → %.6g", h.front(), h.back());
    WriteImage(outPath, ShadowMapImage(optimal.buffers.map, o.samples));
    std::printf("wrote %s (the optimized map; red: samples, green: visible points)\n",
                outPath.c_str());
    return claims.ExitStatus();
}
