// spatial/README.md (the embedding guide) quotes this file from the first marker line to the second
// verbatim (tests/install/readme_snippet_test.cmake checks it); main.cpp calls it with a toy
// renderer, built against the installed package by install_tests.
#pragma once
// [readme]
#include <lexel/spatial.h>

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

using namespace lexel::spatial;

// Your shadow test of the readback's pixels against a shadow map you render with
// `lightClipFromWorld` ([0, 1] clip depth): per pixel, in the readback's order, kShadowed where
// the map holds something nearer the light than readback.buffer.wsPosition[i], kLit where not,
// kFacingAway where the surface faces away from the light (n·l ≤ 0), kEmpty where
// readback.buffer.Covered(i) is false.
using ShadowMask = std::function<std::vector<Shade>(std::size_t light, const Readback& readback,
                                                    const glm::dmat4& lightClipFromWorld)>;

struct OptimizedShadow {
    glm::dmat4 clipFromWorld{1.0};    // render the light's shadow map with this ([0, 1] depth)
    double hStandard = 0.0, h = 0.0;  // eq. (6) of the standard map and of the optimized one
    std::size_t samples = 0;          // the boundary samples h sums over
};

// Once per frame. `cameraDepth`: your camera pass's depth buffer in its own convention (reversed
// or not, [-1, 1] or [0, 1] clip depth, either row order), any size: it is sampled down to at
// most 180 pixels a side, Algorithm 1's readback. `wsSceneBounds`: everything that casts or
// receives shadows. `map`: the shadow maps' size in texels.
inline std::vector<OptimizedShadow> OptimizeShadows(const DepthBuffer& cameraDepth,
                                                    std::span<const Light> lights,
                                                    const Bounds& wsSceneBounds, Resolution map,
                                                    const ShadowMask& shadowMask) {
    // Steps 1-2: the low-resolution readback, shared by every light.
    const DepthImage lowRes = DownsampleDepth(cameraDepth, kReadbackSide);
    const Readback readback = MakeReadback(lowRes.View());
    std::vector<OptimizedShadow> shadows;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightSpace lightSpace(lights[l], wsSceneBounds);
        // Step 1's standard map, its depth range fitted to the casters and the visible points.
        const LightMatrix standard = StandardLightMatrix(readback, lightSpace, wsSceneBounds, map);
        const DepthRange standardDepth =
            LightDepthRange(lightSpace, standard, map, wsSceneBounds, readback.wsRelevant);
        const glm::dmat4 standardClip =
            ClipFromWorld(lightSpace, standard, map, standardDepth, ClipDepth::kZeroToOne);
        // Step 3: the pixels at shadow boundaries under your shadow test.
        const LightSamples samples =
            MakeLightSamples(readback, lightSpace, shadowMask(l, readback, standardClip));
        // Steps 4-5: Algorithm 1 from the standard map's axis, and the 4×4 of its result.
        const OptimizerResult optimal = OptimizeLightMatrix(samples, standard.p4, map);
        const DepthRange depth =
            LightDepthRange(lightSpace, optimal.matrix, map, wsSceneBounds, readback.wsRelevant);
        shadows.push_back(
            {ClipFromWorld(lightSpace, optimal.matrix, map, depth, ClipDepth::kZeroToOne),
             optimal.hAfterIteration.front(), optimal.h, samples.lsX.size()});
    }
    return shadows;
}
// [readme]
