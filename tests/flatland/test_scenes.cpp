#include "test_scenes.h"

#include <cmath>
#include <random>
#include <sstream>

#include "lexel/flatland/sampling.h"
#include "lexel/solvers/errors.h"

namespace lexel::flatland::testing {

FlatScene ExampleScene() {
    FlatScene scene;
    scene.name = "example";
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(1, -0.25).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = 1000;
    scene.wsLight = {-3, 10};
    scene.lexels = 1000;
    scene.geometry = {{{-50, 0}, {200, 0}}, {{6, 0}, {6, 2}, {8, 2.5}}};
    return scene;
}

namespace {
bool Samples(const FlatScene& scene) {
    try {
        CheckSceneGeometry(scene);
        RunSamplingPass(scene, scene.camera.pixels);
        RunSamplingPass(scene, scene.DecisionPixels());
        return true;
    } catch (const DomainError&) {
        return false;
    }
}
}  // namespace

FlatScene SingleSegmentScene(std::uint64_t seed) {
    for (std::uint64_t attempt = 0;; ++attempt) {
        std::mt19937_64 rng(seed * 7919 + attempt);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        FlatScene scene;
        scene.name = "single_segment_" + std::to_string(seed);
        scene.camera.wsPosition = {0, 1 + 3 * u(rng)};
        scene.camera.wsDirection = Vec2(1, -0.1 - 0.5 * u(rng)).normalized();
        scene.camera.fovDeg = 30 + 50 * u(rng);
        scene.camera.pixels = 150 + static_cast<int>(200 * u(rng));
        scene.wsLight = {-10 + 25 * u(rng), 5 + 15 * u(rng)};
        scene.lexels = 100 + static_cast<int>(900 * u(rng));
        const double tilt = -0.3 + 0.6 * u(rng);
        scene.geometry = {{{-5, -5 * tilt}, {40, 40 * tilt}}};
        if (Samples(scene)) return scene;
    }
}

FlatScene RandomScene(std::uint64_t seed, int pixels) {
    for (std::uint64_t attempt = 0;; ++attempt) {
        std::mt19937_64 rng(seed * 104729 + attempt);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        FlatScene scene;
        scene.name = "random_" + std::to_string(seed);
        scene.camera.wsPosition = {0, 1 + 2 * u(rng)};
        scene.camera.wsDirection = Vec2(1, -0.1 - 0.4 * u(rng)).normalized();
        scene.camera.fovDeg = 30 + 60 * u(rng);
        scene.camera.pixels = pixels;
        scene.wsLight = {-15 + 35 * u(rng), 4 + 16 * u(rng)};
        scene.lexels = 200 + static_cast<int>(1800 * u(rng));
        scene.geometry = {{{-20, 0}, {100, 0}}};
        const int objects = 1 + static_cast<int>(3 * u(rng));
        for (int k = 0; k < objects; ++k) {
            std::vector<Vec2> polyline;
            Vec2 p{2 + 12 * u(rng), 0};
            polyline.push_back(p);
            const int points = 1 + static_cast<int>(3 * u(rng));
            for (int j = 0; j < points; ++j) {
                p += Vec2(-1 + 3 * u(rng), -1 + 3 * u(rng));
                p.y() = std::max(p.y(), 0.05);
                polyline.push_back(p);
            }
            scene.geometry.push_back(polyline);
        }
        if (Samples(scene)) return scene;
    }
}

std::string Describe(const FlatScene& scene) {
    std::ostringstream out;
    out.precision(17);
    out << scene.name << ": camera " << scene.camera.wsPosition.transpose() << " dir "
        << scene.camera.wsDirection.transpose() << " fov " << scene.camera.fovDeg << " pixels "
        << scene.camera.pixels << " light " << scene.wsLight.transpose() << " lexels "
        << scene.lexels << " geometry";
    for (const auto& polyline : scene.geometry) {
        out << " [";
        for (const auto& p : polyline) out << " (" << p.x() << "," << p.y() << ")";
        out << " ]";
    }
    return out.str();
}

}  // namespace lexel::flatland::testing
