// Flatland baselines, each returning the optical axis (world radians) of its lexel plane.
//
// normal         Chong 2003 §3: the axis bisects the angular sweep of the visible points.
// plane-optimal  Theorem 1 (§2.2.1) for the case's first segment: the lexel plane is parallel to
//                the line from the light to q, where that segment's line meets the camera's view
//                plane (the line through the camera perpendicular to its direction). When the
//                segment is parallel to the view plane, q is at infinity and the lexel plane is
//                parallel to the segment.
// psm            Stamminger & Drettakis 2002 in flatland: map the light and the visible points into
//                the camera's post-projective space (PPS, OpenGL depth mapping with the camera's
//                near/far when the case gives them, else the visible points' tight depth range)
//                and set up a "normal" light there: its axis a bisects the sweep of the light's
//                rays at the points, its film is perpendicular to a.
//                Which world lexel plane samples like that? Every light-to-lexel map is projective
//                on the pencil of rays through the light, and a film line is recovered from its
//                pole: the one ray that never meets it (the ray parallel to the film). In PPS the
//                pole is the ray from the light L' parallel to the film; its pre-image is a world
//                ray from L, and the world film is parallel to it. So the world lexel plane is
//                parallel to the pre-image of the PPS line through L' perpendicular to a. The
//                film's offset in PPS (how far the near plane is pushed) does not change the
//                sampling. For a light on the view plane (directional in PPS) the pole is the
//                pre-image of the line at infinity, the view plane itself: the thesis's "ideal
//                performance" case (§2.2.3), where PSM is optimal over a single plane.
// psm-thesis     The thesis's reading of PSM (§2.2.3, §4.1.3, Fig. 2.3), used for its tables: the
//                same PPS light with its near plane pushed as far forward as possible (through the
//                first point the rays reach), that near plane mapped back to world space, and its
//                world orientation taken as the lexel plane. This is what the published
//                "Perspective SM" rows measure; it is not the sampling a PSM shadow map produces
//                (see psm).
#pragma once

#include <string>

#include "lexel/flatland/sampling.h"

namespace lexel::flatland {

struct BaselineAxis {
    double wsAxis = 0.0;
    std::string note;  // why a fallback was taken, if one was
};

BaselineAxis NormalAxis(const SamplingPass& pass);
BaselineAxis PlaneOptimalAxis(const FlatScene& scene, const Vec2& wsA, const Vec2& wsB);
BaselineAxis PlaneOptimalAxis(const FlatScene& scene);  // the first segment of the geometry
BaselineAxis PsmAxis(const FlatScene& scene, const SamplingPass& pass);
BaselineAxis PsmThesisAxis(const FlatScene& scene, const SamplingPass& pass);

}  // namespace lexel::flatland
