// The shadow decision's depth test, one for every method and backend: the stored depth of a
// texel against the depth of the receiver's own plane along the ray through that texel's centre
// ("receiver plane depth", Schüler, "Eliminating Surface Acne with Gradient Shadow Mapping",
// ShaderX4 2006; Isidoro, "Shadow Mapping: GPU-based Tips and Techniques", GDC 2006). The map
// stores the nearest surface along exactly that ray, so a lit plane compares equal with itself
// whatever the texel size and slope, and acne cannot appear.
//
// The GLSL twin is LEXEL_RECEIVER_PLANE_TEST in spatial/gl/shaders.h; a GL test
// (receiver_plane_test.cpp) evaluates both on the same receivers and holds them equal.
#pragma once

#include <glm/glm.hpp>

#include "lexel/spatial/light_space.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// Shadowed iff stored < receiverDepth · (1 − kRelativeBias): dimensionless, about 170 float
// roundings of the stored depth.
inline constexpr double kRelativeBias = 1e-5;

// The linear depth (LightSpace::Depth) at which the light ray through lsTexelCentre — the light-
// space point of a texel centre c: lsFromMap (c, 1) for a matrix's map, warp.Inverse(c) for a
// warped one — meets the plane through wsPoint with normal wsNormal. Both ray kinds start at depth
// 0 with a unit direction, so the ray parameter is the depth. Where the ray runs parallel to the
// plane or meets it behind its start: the receiver's own depth, LightSpace::Depth(wsPoint).
double ReceiverPlaneDepth(const LightSpace& lightSpace, const glm::dvec3& lsTexelCentre,
                          const glm::dvec3& wsPoint, const glm::dvec3& wsNormal);

// The comparison itself: kShadowed iff storedDepth < receiverDepth · (1 − kRelativeBias).
inline Shade CompareWithTexel(double storedDepth, double receiverDepth) {
    return storedDepth < receiverDepth * (1.0 - kRelativeBias) ? Shade::kShadowed : Shade::kLit;
}

}  // namespace lexel::spatial
