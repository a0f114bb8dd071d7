// A light matrix from a renderer's depth buffer through the installed package: a floor seen by a
// camera, a box on it lit by a point light, the renderer's shadow mask → Algorithm 1 → the 4×4
// to render the shadow map with. Prints h initial → final; exits 0 when the optimum is no worse.
#include <lexel/flatland.h>
#include <lexel/spatial.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace lexel::spatial;

// Whether the segment a → b crosses the box [lo, hi] (slab test): the renderer's shadow test.
bool Blocked(glm::dvec3 a, glm::dvec3 b, glm::dvec3 lo, glm::dvec3 hi) {
    double t0 = 1e-6, t1 = 1.0 - 1e-6;
    for (int k = 0; k < 3; ++k) {
        const double d = b[k] - a[k], ta = (lo[k] - a[k]) / d, tb = (hi[k] - a[k]) / d;
        t0 = std::max(t0, std::min(ta, tb));
        t1 = std::min(t1, std::max(ta, tb));
    }
    return t0 <= t1;
}

int main() {
    Camera camera;
    camera.position = {0.0, 1.7, 12.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.resolution = {160, 120};
    const Resolution res = camera.resolution;
    const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(res);

    // The renderer's depth buffer: the floor y = 0, |x|, |z| ≤ 20 (the box is left out of the
    // camera pass for brevity; it only casts the shadow).
    std::vector<float> depth(res.Count(), 1.0f);
    for (int y = 0; y < res.height; ++y)
        for (int x = 0; x < res.width; ++x) {
            const glm::dvec3 ray = camera.RayDirection({x + 0.5, y + 0.5}, res);
            const glm::dvec3 wsFloor = camera.position + (-camera.position.y / ray.y) * ray;
            if (ray.y >= 0.0 || std::abs(wsFloor.x) > 20.0 || std::abs(wsFloor.z) > 20.0) continue;
            const glm::dvec4 h = screenFromWorld * glm::dvec4(wsFloor, 1.0);
            depth[static_cast<std::size_t>(y) * res.width + x] = static_cast<float>(h.z / h.w);
        }
    const Readback readback =
        MakeReadback(CameraBufferFromDepth(res, depth, screenFromWorld), screenFromWorld);

    const glm::dvec3 boxLo(-1.0, 0.0, -1.0), boxHi(1.0, 2.0, 1.0);
    Bounds wsBounds;
    for (const glm::dvec3& p : readback.wsRelevant) wsBounds.Add(p);
    wsBounds.Add(boxLo);
    wsBounds.Add(boxHi);
    const LightSpace lightSpace(Light{Light::Type::kPoint, {10.0, 15.0, 6.0}, {}}, wsBounds);

    // The renderer's shadow mask of the readback (from any standard shadow map; here exact).
    std::vector<Shade> shades(res.Count(), Shade::kEmpty);
    for (std::size_t i = 0; i < shades.size(); ++i)
        if (readback.buffer.Covered(i))
            shades[i] =
                Blocked(readback.buffer.wsPosition[i], lightSpace.light().position, boxLo, boxHi)
                    ? Shade::kShadowed
                    : Shade::kLit;
    const LightSamples samples = MakeLightSamples(readback, lightSpace, shades);

    const Resolution map{1024, 1024};
    const glm::dvec3 p4 = InitialLightAxis(lightSpace, wsBounds, readback.wsRelevant);
    const OptimizerResult result = OptimizeLightMatrix(samples, p4, map);
    const glm::dmat4 clipFromWorld =
        ClipFromWorld(lightSpace, result.matrix, map, {1.0, 40.0}, ClipDepth::kZeroToOne);

    std::printf("%zu boundary samples; h %.6g -> %.6g\n", samples.lsX.size(),
                result.hAfterIteration.front(), result.h);
    std::printf("clip from world row 1: %.4f %.4f %.4f %.4f\n", clipFromWorld[0][0],
                clipFromWorld[1][0], clipFromWorld[2][0], clipFromWorld[3][0]);
    // The flatland package links too: the thesis's lexel-plane angle convention.
    std::printf("flatland: axis at 90 degrees is a lexel plane at %.1f degrees\n",
                lexel::flatland::LexelPlaneDegFromAxis(std::acos(0.0)));
    const bool ok = !samples.lsX.empty() && std::isfinite(result.h) &&
                    result.h <= result.hAfterIteration.front() &&
                    std::isfinite(clipFromWorld[3][3]);
    return ok ? 0 : 1;
}
