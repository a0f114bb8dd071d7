// 14 — Embedding lexel in a renderer: a light matrix from a depth buffer, public API only.
//
// What a renderer does each frame for one shadow-casting light (spatial/README.md, "Use lexel in
// your renderer"; Chong & Gortler Algorithm 1 steps 1–5):
//   1. render the camera's depth buffer at low resolution (about 180², report §2.4) and read it
//      back with the projection · view that made it and its depth convention: DepthBuffer,
//      MakeReadback;
//   2. render the standard map — StandardLightMatrix, the focused map fitted to the visible
//      points, through ClipFromWorld with LightDepthRange — and shade the readback with it: a mask
//      of lit and shadowed pixels, from which MakeLightSamples keeps the pixels at shadow
//      boundaries;
//   3. OptimizeLightMatrix from the standard map's axis → the light matrix P;
//   4. ClipFromWorld(P) with LightDepthRange → the 4×4 the rasterizer renders the shadow map with.
// The renderer here is a toy (notebooks_cpp/common/toy_renderer.h): a floor and a box traced
// exactly, its mask exact where a renderer's would come from the standard map; lexel needs
// nothing from it but the depth buffer, its matrix and the mask. No harness. The checks: h falls
// from the standard map to the optimized one, and through the 4×4 every visible point lands inside
// the shadow map (NDC x, y in [−1, 1], w > 0) at a depth in [0, 1], the farthest at the far end of
// the fitted range, spread over twice the depth a guess of {1, 60} world units gives them.
//
// Public API only: lexel::spatial (<lexel/spatial.h>). Toy renderer and figure: the programs' own.
//
//   ./build/notebooks_cpp/notebook_14_embedding [OUT_DIR]    (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "lexel/spatial.h"
#include "notebook.h"
#include "plot.h"
#include "toy_renderer.h"

using namespace lexel::spatial;

// Boundary samples (red) and every 5th visible point (grey) in the map's texels under `matrix`.
lexel::notebooks::Panel MapPanel(const char* title, const LightMatrix& matrix,
                                 const LightSamples& samples) {
    using lexel::notebooks::Series;
    Series visible("visible points", Series::Style::kPoints, lexel::notebooks::Rgb{0.6, 0.6, 0.6},
                   1);
    Series boundary("boundary samples", Series::Style::kPoints, lexel::notebooks::PaletteColour(0),
                    1.6);
    Series frame("", Series::Style::kPolygon, lexel::notebooks::Rgb{}, 1);
    const double corners[4][2] = {{0, 0}, {1024, 0}, {1024, 1024}, {0, 1024}};  // the map's frame
    for (const auto& c : corners) frame.Add(c[0], c[1]);
    for (std::size_t i = 0; i < samples.lsRelevant.size(); i += 5) {
        const glm::dvec2 u = matrix.Map(samples.lsRelevant[i]);
        visible.Add(u.x, u.y);
    }
    for (const glm::dvec3& lsX : samples.lsX) {
        const glm::dvec2 u = matrix.Map(lsX);
        boundary.Add(u.x, u.y);
    }
    return {title, "u1 (texels)", "u2 (texels)", false, true, {frame, visible, boundary}};
}

// Where `clipFromWorld` puts the points: the least clip w, the largest |NDC x| or |NDC y| and
// the NDC depth interval.
struct NdcSpan {
    double leastW = INFINITY, worstNdc = 0, lowDepth = INFINITY, highDepth = -INFINITY;
    double Depth() const { return highDepth - lowDepth; }
};

NdcSpan SpanOf(const glm::dmat4& clipFromWorld, const std::vector<glm::dvec3>& wsPoints) {
    NdcSpan span;
    for (const glm::dvec3& wsPoint : wsPoints) {
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(wsPoint, 1.0);
        span.leastW = std::min(span.leastW, clip.w);
        span.worstNdc =
            std::max({span.worstNdc, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
        span.lowDepth = std::min(span.lowDepth, clip.z / clip.w);
        span.highDepth = std::max(span.highDepth, clip.z / clip.w);
    }
    return span;
}

void PrintRows(const char* name, const glm::dmat4& m) {
    std::printf("%s (rows):\n", name);
    for (int r = 0; r < 4; ++r)
        std::printf("  %10.5f %10.5f %10.5f %10.5f\n", m[0][r], m[1][r], m[2][r], m[3][r]);
}

int main(int argc, char** argv) {
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const lexel::notebooks::ToyRenderer renderer({160, 120});

    // 1. The camera pass: its depth buffer, the matrix that drew it and its convention (OpenGL's
    // clip depth, standard Z, the top row first: DepthConvention's defaults).
    const Resolution res = renderer.resolution();
    const std::vector<float> depth = renderer.DepthBuffer();
    const Camera& camera = renderer.camera();
    const Readback readback =
        MakeReadback(DepthBuffer{.resolution = res,
                                 .depth = depth,
                                 .clipFromWorld = camera.ClipFromView() * camera.ViewFromWorld(),
                                 .convention = {}});

    // 2. The light's frame over the scene's bounds, the standard map and the renderer's mask.
    const Bounds wsBounds = renderer.SceneBounds();
    const LightSpace lightSpace(Light{Light::Type::kPoint, renderer.wsLight(), {}}, wsBounds);
    const Resolution map{1024, 1024};
    const LightMatrix standard = StandardLightMatrix(readback, lightSpace, wsBounds, map);
    const LightSamples samples =
        MakeLightSamples(readback, lightSpace, renderer.ShadowMask(readback));

    // 3. Algorithm 1 from the standard map's axis.
    const OptimizerResult optimal = OptimizeLightMatrix(samples, standard.p4, map);

    // 4. The 4×4 for the rasterizer, depth in [0, 1] over the range that holds every caster of a
    // visible shadow and every visible point.
    const DepthRange range =
        LightDepthRange(lightSpace, optimal.matrix, map, wsBounds, readback.wsRelevant);
    const glm::dmat4 clipFromWorld =
        ClipFromWorld(lightSpace, optimal.matrix, map, range, ClipDepth::kZeroToOne);
    const glm::dmat4 guessed =
        ClipFromWorld(lightSpace, optimal.matrix, map, {1.0, 60.0}, ClipDepth::kZeroToOne);

    std::printf("%zu of %zu readback pixels see the scene; %zu boundary samples for the light\n",
                readback.wsRelevant.size(), res.Count(), samples.lsX.size());
    std::printf("h, standard map → optimized: %.6g → %.6g (%zu iterations)\n",
                optimal.hAfterIteration.front(), optimal.h, optimal.hAfterIteration.size() - 1);
    std::printf("optical axis p4 (light space): (%.4f, %.4f, %.4f) → (%.4f, %.4f, %.4f)\n",
                standard.p4.x, standard.p4.y, standard.p4.z, optimal.matrix.p4.x,
                optimal.matrix.p4.y, optimal.matrix.p4.z);
    PrintRows("clip from world", clipFromWorld);

    const NdcSpan fitted = SpanOf(clipFromWorld, readback.wsRelevant);
    const NdcSpan guess = SpanOf(guessed, readback.wsRelevant);
    std::printf(
        "light depth range {%.4g, %.4g}: visible points at NDC z %.4f–%.4f (a guess of "
        "{1, 60}: %.4f–%.4f)\n",
        range.near, range.far, fitted.lowDepth, fitted.highDepth, guess.lowDepth, guess.highDepth);
    lexel::notebooks::Claims claims;
    claims.Check(
        optimal.h < optimal.hAfterIteration.front() &&
            std::abs(Energy(standard, samples) / optimal.hAfterIteration.front() - 1) < 1e-9,
        "h falls from the standard map's %.6g to %.6g", optimal.hAfterIteration.front(), optimal.h);
    claims.Check(fitted.leastW > 0 && fitted.worstNdc <= 1 + 1e-9 && fitted.lowDepth >= 0 &&
                     fitted.highDepth <= 1,
                 "every visible point in the map: w >= %.3g > 0, |NDC x, y| <= %.9f, depth in "
                 "[%.4f, %.4f]",
                 fitted.leastW, fitted.worstNdc, fitted.lowDepth, fitted.highDepth);
    claims.Check(fitted.highDepth >= 0.99 && fitted.Depth() > guess.Depth(),
                 "the fitted range ends at the farthest visible point (NDC z %.4f) and spreads "
                 "the visible points over %.3f of [0, 1], the guess over %.3f",
                 fitted.highDepth, fitted.Depth(), guess.Depth());
    const auto figure = outDir / "14_embedding.png";
    lexel::notebooks::WritePlot(figure,
                                {MapPanel("standard map (the start)", standard, samples),
                                 MapPanel("optimized map (Algorithm 1)", optimal.matrix, samples)});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
