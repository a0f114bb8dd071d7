// The standard shadow map of Chong & Gortler's Algorithm 1, step 1 (report §2.3: "we start with a
// standard shadow map"; §2.4: "every couple frames we generate standard shadow maps for step 1
// instead of using the previous frame's"): the map a renderer renders to shade its readback, so
// that MakeLightSamples (samples.h) can find the pixels near shadow boundaries.
//
// It is the focused shadow map fitted to the visible points (S. Brabec, T. Annen, H.-P. Seidel,
// "Practical Shadow Mapping", JGT 7(4), 2002: a light frustum fitted to the visible pixels, the
// minimum-area rectangle): the optical axis toward the scene's centre (InitialLightAxis) and the
// smallest rectangle around the readback's visible points grown by Algorithm 1's margin — exactly
// the map OptimizeLightMatrix starts from, so its h is OptimizerResult::hAfterIteration[0]. Its
// shadow mask, per readback pixel: kShadowed where the map holds a caster nearer to the light than
// the pixel's point, kLit where it does not, kFacingAway where the surface faces away from the
// light (n·l ≤ 0), kEmpty where the pixel sees nothing — the renderer's own shadow test on its
// low-resolution camera pass (spatial/README.md, the embedding guide, and
// tests/spatial/standard_map_test.cpp do it on the CPU).
#pragma once

#include "lexel/spatial/bounds.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/readback.h"

namespace lexel::spatial {

// Algorithm 1's margin: each half extent of the fitted rectangle grows by this fraction (report
// §2.4; OptimizerOptions::margin).
inline constexpr double kStandardMapMargin = 0.02;

// The standard map's light matrix for `map` texels. `wsSceneBounds` bounds everything that casts
// or receives shadows (the light space's bounds). Throws DomainError: kCamera when the readback
// sees nothing, kLight when no optical axis sees every visible point.
LightMatrix StandardLightMatrix(const Readback& readback, const LightSpace& lightSpace,
                                const Bounds& wsSceneBounds, Resolution map);

}  // namespace lexel::spatial
