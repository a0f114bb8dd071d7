// Scenes for the flatland tests: an example floor with a polyline and seeded random ones. Random
// scenes print their seed and contents through Describe() so a failing sweep can be replayed.
#pragma once

#include <cstdint>
#include <string>

#include "lexel/flatland/scene.h"

namespace lexel::flatland::testing {

// The example of the flatland issue (a floor and a small polyline, light above and behind).
FlatScene ExampleScene();

// A camera looking at one segment (Theorem 1 scenes).
FlatScene SingleSegmentScene(std::uint64_t seed);

// A floor plus 1–3 random polylines in front of the camera, a light above; guaranteed to pass
// the sampling pass (seeds that give an invalid scene are skipped deterministically).
FlatScene RandomScene(std::uint64_t seed, int pixels = 240);

std::string Describe(const FlatScene& scene);

}  // namespace lexel::flatland::testing
