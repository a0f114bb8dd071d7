// 12 — Cascades: SDSM's partitions of the view, and Algorithm 1 on each partition's own map.
//
// One map must serve every visible pixel; k maps can each serve one slice of the view. A
// z-partitioning cuts the view by planar eye depth z = (X − eye)·v (Lloyd et al. 2006 §5); SDSM
// (Lauritzen et al. 2011 §3–4) takes the visible depth range [z_min, z_max] from the readback and
// splits it logarithmically, C_i = z_min (z_max/z_min)^(i/k), so each slice spans the same ratio
// of depths and a texel covers about the same number of pixels in every slice. Each cascade is
// then fitted to its own visible points: SDSM with the light-space box, `sdsm-optimal` with
// Algorithm 1 (10) from that box and the other standard starts, on the partition's own boundary
// samples, minimizing `optimal`'s edge energy e = Σ‖n̂ᵀJ⁻¹‖^(5/8) plus its footprint prior. The
// budget is fair: k maps of (W/√k)×(H/√k), the single map's texels in all.
//
// This program prints each cascade's interval, map, points, pixels and e for `sdsm` and
// `sdsm-optimal`, and writes one figure: the four maps of each (rows 1–2; green: the visible
// points a cascade serves, red: its boundary samples) and the error images of optimal (one map),
// sdsm and sdsm-optimal (row 3; red: false shadow, blue: missed shadow). The checks: the intervals
// tile the camera's depth range, each cascade's e under Algorithm 1 is at most SDSM's (it starts
// from SDSM's box; it judges maps on the case's 512 kept samples, so over every sample, as here,
// this is a check rather than a theorem), and the cascades' texels add up to at most the single
// map's.
//
// Public API: lexel::spatial (partitions.h, cascades.h). The scene, rendering, exact shadow rays
// and images: lexel's test bench (lexel::harness, lexel::cases).
//
//   ./build/notebooks_cpp/notebook_12_cascades [OUT_DIR]    (default out/notebooks/)
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/images.h"
#include "lexel/spatial/partitions.h"
#include "notebook.h"
#include "plot.h"

using namespace lexel::spatial;

namespace {

std::vector<Cascade> CascadesOf(const MethodOutcome& m) {
    std::vector<Cascade> cascades;
    for (const CascadeOutcome& c : m.cascades) cascades.push_back(c.cascade);
    return cascades;
}

// Each cascade's e (kEdgeEnergy) over the samples and prior points it serves.
std::vector<double> CascadeEnergies(const MethodOutcome& m, const LightOutcome& o,
                                    const Evaluator& evaluator, const Camera& camera) {
    const std::vector<Cascade> cascades = CascadesOf(m);
    std::vector<double> e;
    for (std::size_t i = 0; i < cascades.size(); ++i)
        e.push_back(Energy(
            cascades[i].matrix,
            SamplesOfCascade(o.samples, evaluator.readback().wsRelevant, camera, cascades, i),
            kEdgeEnergy));
    return e;
}

void PrintCascades(const MethodOutcome& m, const std::vector<double>& e) {
    std::printf("%s: %lld misclassified, e %.6g\n", m.method.c_str(),
                static_cast<long long>(m.metrics.misclassified), m.metrics.e);
    for (std::size_t i = 0; i < m.cascades.size(); ++i) {
        const CascadeOutcome& c = m.cascades[i];
        std::printf("  z in [%8.4g, %8.4g)  %3d×%-3d  %6zu points  %7lld pixels  e %.6g\n",
                    c.cascade.zNear, c.cascade.zFar, c.cascade.map.width, c.cascade.map.height,
                    c.cascade.visiblePoints, static_cast<long long>(c.pixels), e[i]);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    const Scene scene = lexel::cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) /
                                                       "spatial/walkthrough.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"optimal", "sdsm", "sdsm-optimal"};
    options.keepBuffers = true;
    const LightOutcome o = evaluator.Evaluate(scene.lights.front(), options);
    const LightSpace lightSpace(o.light, evaluator.bounds());
    const MethodOutcome& optimal = o.methods[0];
    const MethodOutcome& sdsm = o.methods[1];
    const MethodOutcome& sdsmOptimal = o.methods[2];
    std::printf("optimal (one %d×%d map): %lld misclassified, e %.6g\n", scene.shadowMap.width,
                scene.shadowMap.height, static_cast<long long>(optimal.metrics.misclassified),
                optimal.metrics.e);
    const std::vector<double> eSdsm = CascadeEnergies(sdsm, o, evaluator, scene.camera);
    const std::vector<double> eOptimal = CascadeEnergies(sdsmOptimal, o, evaluator, scene.camera);
    PrintCascades(sdsm, eSdsm);
    PrintCascades(sdsmOptimal, eOptimal);
    std::printf("e, sdsm → sdsm-optimal: %.6g → %.6g; misclassified %lld → %lld\n", sdsm.metrics.e,
                sdsmOptimal.metrics.e, static_cast<long long>(sdsm.metrics.misclassified),
                static_cast<long long>(sdsmOptimal.metrics.misclassified));

    lexel::notebooks::Claims claims;
    const std::vector<Cascade> cascades = CascadesOf(sdsm);
    bool tiles = cascades.front().zNear == scene.camera.nearPlane &&
                 cascades.back().zFar >= scene.camera.farPlane;
    for (std::size_t i = 0; i + 1 < cascades.size(); ++i)
        tiles = tiles && cascades[i].zFar == cascades[i + 1].zNear;
    claims.Check(tiles, "sdsm's %zu intervals tile [near %g, far %g) without gap or overlap",
                 cascades.size(), scene.camera.nearPlane, scene.camera.farPlane);
    bool lower = true;
    long long texels = 0;
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        lower = lower && eOptimal[i] <= eSdsm[i];
        texels += sdsm.cascades[i].cascade.map.Count();
    }
    claims.Check(lower, "Algorithm 1 lowers or keeps every cascade's e (total %.6g <= %.6g)",
                 sdsmOptimal.metrics.e, sdsm.metrics.e);
    claims.Check(texels <= static_cast<long long>(scene.shadowMap.Count()),
                 "the cascades use %lld of the %lld texels", texels,
                 static_cast<long long>(scene.shadowMap.Count()));

    std::vector<Image> images;
    std::vector<std::string> captions;
    for (const MethodOutcome* m : {&sdsm, &sdsmOptimal}) {
        const std::vector<double>& e = m == &sdsm ? eSdsm : eOptimal;
        for (std::size_t c = 0; c < m->buffers.cascadeMaps.size(); ++c) {
            const LightSamples served = SamplesOfCascade(o.samples, evaluator.readback().wsRelevant,
                                                         scene.camera, CascadesOf(*m), c);
            images.push_back(ShadowMapImage(m->buffers.cascadeMaps[c], served));
            captions.push_back(m->method + " " + std::to_string(c) + ": e " +
                               std::to_string(static_cast<long long>(e[c])));
        }
    }
    for (const MethodOutcome* m : {&optimal, &sdsm, &sdsmOptimal}) {
        images.push_back(
            MisclassificationImage(evaluator.frame(), lightSpace, m->buffers.shades, o.truth));
        captions.push_back(m->method + ": " + std::to_string(m->metrics.misclassified) + " wrong");
    }
    std::vector<lexel::notebooks::Picture> pictures;
    for (std::size_t k = 0; k < images.size(); ++k)
        pictures.push_back(
            {captions[k], images[k].width, images[k].height, images[k].channels, images[k].pixels});
    const auto figure = outDir / "12_cascades.png";
    lexel::notebooks::WritePictures(figure, pictures, static_cast<int>(cascades.size()));
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
