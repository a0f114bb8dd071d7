// The scene and the light positions of Chong & Gortler's experiment (report §3): "a few dozen
// objects on or near a floor", a viewer standing slightly above it, and the light "at 500 randomly
// chosen positions uniformly on a distant hemisphere, as might be typical for a sunlit scene".
//
// Both are deterministic for a seed on every platform: they draw from std::mt19937_64 (whose
// output the standard fixes) through our own mappings to [0, 1), not through the standard
// distributions, whose algorithms differ between standard libraries.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// Half the side of the generated floor: the floor is [-20, 20]² at y = 0.
inline constexpr double kFloorHalfSize = 20.0;
// Lights of a sweep keep at least this elevation above the horizontal plane through the centre,
// so a light never lies in (or grazes) the floor plane, where every floor lexel would be edge-on.
inline constexpr double kSweepMinElevationDeg = 5.0;

// A 40 × 40 floor (y = 0, normal +y) and `count` ≥ 0 objects on it: boxes, spheres and cylinders
// whose extents are 0.3–2.5 units, about a third lifted 0.05–1 unit above the floor (the rest
// resting on it), every one turned about y and about a third also tilted up to 30°. Positions
// are rejection-sampled inside [-18, 18]² so footprints rarely overlap; when a crowded floor
// leaves no free spot in 64 tries, the try with the most clearance is kept. Writes the floor plane
// (0, 1, 0, 0) to *floorPlane when it is not null. Throws std::invalid_argument for count < 0.
TriangleMesh FloorObjects(int count, std::uint64_t seed, glm::dvec4* floorPlane);

// `sweep.count` lights of `sweep.type` on the upper hemisphere (y ≥ wsCenter.y) less the band
// below kSweepMinElevationDeg, uniform in area: the unit direction u's y is uniform in [sin 5°, 1]
// (Archimedes: equal heights, equal areas) and its azimuth uniform in [0, 2π). A point light sits
// at wsCenter + radius·u, a directional light shines along -u; the same seed gives the same u for
// both types. Throws std::invalid_argument for a negative count or a radius that is not
// positive and finite.
std::vector<Light> SweepLights(const LightSweep& sweep, const glm::dvec3& wsCenter);

}  // namespace lexel::spatial
