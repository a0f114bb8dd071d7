#include "flat_scene.h"

#include <cstdio>

#include "lexel/flatland/sampling.h"

namespace lexel::notebooks {

flatland::FlatScene TeachingScene(bool withStep) {
    using flatland::Vec2;
    flatland::FlatScene scene;
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(1, -0.25).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = 1000;
    scene.wsLight = {-3, 10};
    scene.lexels = 1000;
    scene.geometry = {{{-50, 0}, {200, 0}}};
    if (withStep) scene.geometry.push_back({{6, 0}, {6, 2}, {8, 2.5}});
    return scene;
}

flatland::LexelSamples TeachingSamples() {
    const flatland::FlatScene scene = TeachingScene(true);
    return flatland::MakeLexelSamples(flatland::RunSamplingPass(scene, scene.camera.pixels),
                                      scene.lexels);
}

void PrintAngle(const char* label, double wsAxis, const char* metric, double value,
                const std::string& note) {
    std::printf("%-18s lexel plane %13.9f°  %s = %.9f%s%s%s\n", label,
                flatland::LexelPlaneDegFromAxis(wsAxis), metric, value, note.empty() ? "" : "  (",
                note.c_str(), note.empty() ? "" : ")");
}

}  // namespace lexel::notebooks
