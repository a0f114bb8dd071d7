// Internal to lexel::spatial (not installed): what the shadow-map baselines (baselines.h) share —
// the normal axis, the focus body (view frustum ∩ scene bounds, clipped with solvers/clipping.h),
// the narrowest cone around directions, and the validity test every baseline must pass (report
// §2.1: relevant points strictly in front of p4 and inside [0, W] × [0, H]).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/solvers/clipping.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial::baseline_detail {

// How far outside [0, W] × [0, H] a relevant point may map, in texels: the rectangle fit is exact
// up to rounding, which is ~1e-12 texel at these resolutions.
inline constexpr double kMapToleranceTexels = 1e-6;

// The world half-space p4 · X(x) ≥ delta as a plane (n, d) with n·x + d ≥ 0 (X is affine in x).
glm::dvec4 WorldPlaneOfLightPlane(const LightSpace& lightSpace, const glm::dvec3& p4, double delta);

std::vector<glm::dvec3> ToLightAll(const LightSpace& lightSpace,
                                   std::span<const glm::dvec3> wsPoints);

// Central projection of X onto the plane p4·X = 1, in PlaneBasis(p4) coordinates (the same
// coordinates FitMapToPlanePoints expects). X must be in front.
glm::dvec2 ProjectToPlane(const glm::dvec3& p4, const glm::dvec3& lsX);

// Whether every point is InFront of m.p4 and maps into [0, W] × [0, H] within kMapToleranceTexels,
// and m is finite.
bool CoversAll(const LightMatrix& m, std::span<const glm::dvec3> lsPoints, Resolution map);

// A glm matrix from four rows (glm is column-major: m[c][r]).
glm::dmat4 FromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2,
                    const glm::dvec4& r3);

// The axis a of the narrowest cone around unit directions (max over unit a of min_i a·d_i), or
// nullopt when no open half-space holds them all (or there are none). See the .cpp for the method.
std::optional<glm::dvec3> NarrowestConeAxis(const std::vector<glm::dvec3>& directions);

// The normal baseline's optical axis and whether it had to fall back (see NormalLightMatrix).
struct NormalAxis {
    glm::dvec3 p4{0.0, 0.0, 1.0};
    bool cornersInFront = true;  // every bounds corner is InFront of p4
    std::string fallback;
};
NormalAxis ChooseNormalAxis(const BaselineContext& context);

// The "body" of LiSPSM / PSM: world vertices of view frustum ∩ scene bounds ∩ {p4·X ≥ δ} with
// the normal axis p4 and δ half the smallest p4·X of the in-front bounds corners and relevant
// points (so no point the map must see is cut), followed by the relevant points themselves.
std::vector<glm::dvec3> FocusBody(const BaselineContext& context, const NormalAxis& axis);
// The body of the tight warps: the visible points' hull vertices (context.wsRelevantHull, or every
// visible point) together with, for each, the point where the ray from it toward the light leaves
// the scene bounds — a convex set holding every occluder that can shadow a visible point (it lies
// on a segment from such a point to the light), so the warp built around it clips none.
std::vector<glm::dvec3> TightBody(const BaselineContext& context);
// The visible points the tight fits cover, in light space: the hull vertices when known (the same
// bounds and rectangle as all points: optimizer.cpp), else every visible point.
std::vector<glm::dvec3> RelevantLight(const BaselineContext& context);

// δ above: the light-space depth along p4 below which nothing relevant lies (> 0).
double LightPlaneOffset(const BaselineContext& context, const NormalAxis& axis);

// Throws std::invalid_argument without a light space, DomainError for empty bounds.
void CheckContext(const BaselineContext& context);

}  // namespace lexel::spatial::baseline_detail
