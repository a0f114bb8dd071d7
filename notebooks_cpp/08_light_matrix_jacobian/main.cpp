// 08 — The 3D light matrix P, the Jacobian ∂u/∂x of one pixel, and h of eq. (6).
//
// In light space (origin at the light) P has three rows that matter (Chong & Gortler, §2.1,
// Fig. 1): a point X lands on texel u^i = p_i·X / p4·X (i = 1, 2), p4 the unit optical axis
// (projective freedom), p1 and p2 the 2D affine map of the shadow map (scale, rotate, shear,
// shift). Screen pixel x sees X(x); the composite x → u has the 2×2 Jacobian J = ∂u/∂x, texels
// per pixel, and J⁻¹ = ∂x/∂u is the 3D footprint, pixels per texel (Appendix A, eq. 9):
//     J_ij = (p_i·D_j)/w − (p_i·X)(p4·D_j)/w²,    w = p4·X,    D_j = ∂X/∂x^j from the readback.
// The energy sums the squared footprint over the pixels near shadow boundaries (§2.2, eq. 6):
//     h(P) = Σ_samples Σ_ij (∂x^i/∂u^j)² = Σ ||J⁻¹||_F².
// This program builds P for a standard map of a toy scene, prints J of one boundary pixel against
// finite differences, and h. The checks: eq. 9 is the derivative of u along the readback's D_j
// (1e-7); it matches u through the renderer's exact surface to the depth buffer's float precision
// (1e-3); ||J⁻¹||_F² by hand = SampleBadness; h = Σ SampleBadness; a map with twice the texels
// per side (J doubles) divides h by 4. The figure: ||J⁻¹||_F² at every readback pixel; it is
// largest on the near floor, where one texel covers the most pixels (perspective aliasing).
//
// Public API: lexel::spatial (MakeReadback, LightSpace, MakeLightSamples, FitMapToPoints,
// SampleJacobian, SampleBadness, Energy). The toy renderer and the figure are the programs' own.
//
//   ./build/notebooks_cpp/notebook_08_light_matrix_jacobian [OUT_DIR]   (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "lexel/spatial.h"
#include "notebook.h"
#include "plot.h"
#include "toy_renderer.h"

int main(int argc, char** argv) {
    using namespace lexel::spatial;
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const lexel::notebooks::ToyRenderer renderer({160, 120});
    const Resolution res = renderer.resolution();
    const glm::dmat4 screenFromWorld = renderer.ScreenFromWorld();
    const Readback readback = MakeReadback(
        CameraBufferFromDepth(res, renderer.DepthBuffer(), screenFromWorld), screenFromWorld);
    const LightSpace lightSpace(Light{Light::Type::kPoint, renderer.wsLight(), {}},
                                renderer.SceneBounds());
    const LightSamples samples =
        MakeLightSamples(readback, lightSpace, renderer.ShadowMask(readback));
    const glm::dvec3 p4 = InitialLightAxis(lightSpace, renderer.SceneBounds(), readback.wsRelevant);
    const LightMatrix P = *FitMapToPoints(p4, samples.lsRelevant, {1024, 1024}, {0.02});
    std::printf(
        "P (light space, texels): p1 = (%.2f, %.2f, %.2f)  p2 = (%.2f, %.2f, %.2f)  "
        "p4 = (%.4f, %.4f, %.4f)\n",
        P.p1.x, P.p1.y, P.p1.z, P.p2.x, P.p2.y, P.p2.z, P.p4.x, P.p4.y, P.p4.z);

    // One boundary sample: J by eq. 9 from the readback's X and D_j, and by central differences
    // of u along the readback's linear model X + s D_j and through the renderer's exact surface.
    const std::size_t i = samples.lsX.size() / 2;
    const glm::dvec3 X = samples.lsX[i], D1 = samples.dXdx1[i], D2 = samples.dXdx2[i];
    const glm::dvec2 xs(samples.pixel[i] % res.width + 0.5, samples.pixel[i] / res.width + 0.5);
    glm::dvec2 row1, row2;
    SampleJacobian(P, X, D1, D2, &row1, &row2);
    const auto surface = [&](glm::dvec2 x) {
        return P.Map(lightSpace.ToLight(renderer.Trace(x)->wsPoint));
    };
    const auto model = [&](glm::dvec2 x) {
        return P.Map(X + (x.x - xs.x) * D1 + (x.y - xs.y) * D2);
    };
    const auto differences = [&](auto u, double step) {  // step in pixels
        const glm::dvec2 e1(step, 0), e2(0, step);
        return glm::dmat2((u(xs + e1) - u(xs - e1)) / (2 * step),
                          (u(xs + e2) - u(xs - e2)) / (2 * step));
    };
    const glm::dmat2 jModel = differences(model, 1e-4), jSurface = differences(surface, 1e-3);
    const auto gap = [&](const glm::dmat2& j) {  // relative to J's largest entry
        const double scale =
            std::max({std::abs(row1.x), std::abs(row1.y), std::abs(row2.x), std::abs(row2.y)});
        return std::max({std::abs(row1.x - j[0][0]), std::abs(row1.y - j[1][0]),
                         std::abs(row2.x - j[0][1]), std::abs(row2.y - j[1][1])}) /
               scale;
    };
    std::printf("pixel (%.1f, %.1f), one of %zu boundary samples:\n", xs.x, xs.y,
                samples.lsX.size());
    std::printf("  J = ∂u/∂x (eq. 9) = [%9.5f %9.5f; %9.5f %9.5f] texels per pixel\n", row1.x,
                row1.y, row2.x, row2.y);
    std::printf("  exact surface     = [%9.5f %9.5f; %9.5f %9.5f]\n", jSurface[0][0],
                jSurface[1][0], jSurface[0][1], jSurface[1][1]);
    const double det = row1.x * row2.y - row1.y * row2.x;
    const double inv[4] = {row2.y / det, -row1.y / det, -row2.x / det, row1.x / det};
    const double frobenius2 = inv[0] * inv[0] + inv[1] * inv[1] + inv[2] * inv[2] + inv[3] * inv[3];
    std::printf(
        "  J⁻¹ = ∂x/∂u       = [%9.5f %9.5f; %9.5f %9.5f] pixels per texel, ||J⁻¹||² = %.6f\n",
        inv[0], inv[1], inv[2], inv[3], frobenius2);

    double sum = 0;
    for (std::size_t k = 0; k < samples.lsX.size(); ++k)
        sum += SampleBadness(P, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]);
    const double h = Energy(P, samples);
    const double h2048 =
        Energy(*FitMapToPoints(p4, samples.lsRelevant, {2048, 2048}, {0.02}), samples);
    std::printf("h(P) = Σ ||J⁻¹||²_F = %.6f over the samples; map 1024² → 2048²: h %.6f → %.6f\n",
                h, h, h2048);

    lexel::notebooks::Claims claims;
    claims.Check(gap(jModel) < 1e-7, "eq. 9 = differences of u(X + s D_j): %.1e (< 1e-7)",
                 gap(jModel));
    claims.Check(gap(jSurface) < 1e-3,
                 "J = differences through the exact surface: %.1e (< 1e-3; "
                 "the depth buffer holds floats)",
                 gap(jSurface));
    const double badness = SampleBadness(P, samples.lsX[i], samples.dXdx1[i], samples.dXdx2[i]);
    claims.Check(std::abs(frobenius2 / badness - 1) < 1e-12,
                 "||J⁻¹||²_F by hand %.9f = SampleBadness %.9f", frobenius2, badness);
    claims.Check(std::abs(sum / h - 1) < 1e-12, "h = Σ SampleBadness: %.9f = %.9f", h, sum);
    claims.Check(std::abs(h / h2048 - 4) < 1e-9, "twice the texels per pixel: h / h' = %.12f = 4",
                 h / h2048);

    // The figure: log ||J⁻¹||²_F at every reliable readback pixel; boundary samples in red.
    const glm::dmat3 dXdW = lightSpace.LsFromWsLinear();
    std::vector<double> logBadness(res.Count(), NAN);
    for (std::size_t k = 0; k < res.Count(); ++k)
        if (readback.buffer.Covered(k) && readback.smooth[k])
            logBadness[k] =
                std::log10(SampleBadness(P, lightSpace.ToLight(readback.buffer.wsPosition[k]),
                                         dXdW * readback.dWdx1[k], dXdW * readback.dWdx2[k]));
    double lo = INFINITY, hi = -INFINITY;
    for (double v : logBadness)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    std::vector<float> rgb(3 * res.Count(), 0.0f);
    for (std::size_t k = 0; k < res.Count(); ++k) {
        if (!std::isfinite(logBadness[k])) continue;
        const auto c = lexel::notebooks::HeatColour((logBadness[k] - lo) / (hi - lo));
        rgb[3 * k] = c.r, rgb[3 * k + 1] = c.g, rgb[3 * k + 2] = c.b;
    }
    for (std::uint32_t pixel : samples.pixel)
        rgb[3 * pixel] = 1, rgb[3 * pixel + 1] = rgb[3 * pixel + 2] = 0;
    char caption[96];
    std::snprintf(caption, sizeof caption,
                  "||J^-1||^2 from %.2g (purple) to %.2g (yellow), log scale; red: samples",
                  std::pow(10, lo), std::pow(10, hi));
    const auto figure = outDir / "08_light_matrix_jacobian.png";
    lexel::notebooks::WritePictures(figure, {{caption, res.width, res.height, 3, rgb}}, 1, 660);
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
