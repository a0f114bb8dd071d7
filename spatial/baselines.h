// The shadow-map baselines of Chong & Gortler, "Scene Optimized Shadow Mapping" (report §3): the
// light matrices they compared their optimizer against, each returned as a LightMatrix (report
// §2.1: rows p1, p2, p4 in light space).
//
//   normal         the light's frustum around the scene bounds (p4 = axis to the bounds centre),
//                  affine part = min-area rectangle of the projected bounds corners (report §2.3,
//                  step 4b-ii).
//   focused        report §3's "frustum limiting step": the projected view frustum intersected with
//                  the normal extent on the light's near plane, min-area rectangle about the
//                  intersection (S. Brabec, T. Annen, H.-P. Seidel, "Practical Shadow Mapping",
//                  JGT 7(4), 2002: a tight light frustum, minimum enclosing rectangle, Fig. 3).
//   lispsm         M. Wimmer, D. Scherzer, W. Purgathofer, "Light Space Perspective Shadow Maps",
//                  EGSR 2004: a perspective warp along the view direction projected perpendicular
//                  to the light, n_opt = (z_n + √(z_f z_n)) / sin γ (their general-γ optimum; the
//                  paper is not among the project's papers; the γ = 90° case is B. Lloyd et al.,
//                  "Warping and Partitioning for Low Error Shadow Maps", EGSR 2006, §4.1 and
//                  Fig. 3: n' = n + √(fn) for an overhead light). lispsm-engine's n is the rule
//                  Filament and OGRE ship (z₁ = z₀ + d·sin γ): LispsmNearRule below.
//   psm            M. Stamminger, G. Drettakis, "Perspective Shadow Maps", SIGGRAPH 2002: the
//                  shadow map taken in the camera's post-perspective space; with S. Kozlov,
//                  "Perspective Shadow Maps: Care and Feeding", GPU Gems ch. 14, 2004 (the light
//                  behind the viewer as an inverted projection, the virtual camera slide back).
//                  Neither text is among the project's papers; Lloyd 2006 §4.1 (n' = n for PSM) and
//                  Chong's 2003 thesis (003: "pulling the view plane back") summarize them.
//   plane-optimal  H. Chong, S. Gortler, "A Lixel for Every Pixel", EGSR 2004: the floor plane
//                  sampled exactly one lexel per pixel (the light map restricted to the plane is an
//                  affine image of the camera's screen restricted to it).
//
// Every function returns a matrix under which every point of wsRelevant is strictly in front
// (InFront) and maps into [0, W] × [0, H] of context.map (up to rounding, far below 1e-6
// texel). Where a method's own construction cannot guarantee that, it falls back as documented at
// the function and reports why in BaselineDiagnostics::fallback.
#pragma once

#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "lexel/spatial/bounds.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// What every baseline is built from: the same information Algorithm 1 gets.
struct BaselineContext {
    const LightSpace* lightSpace = nullptr;  // the light and its frame
    Camera camera;                           // the viewer (view frustum, screen map Q)
    Resolution map;                          // the shadow map, in texels
    Bounds wsBounds;                         // bounds of everything that casts or receives
    std::span<const glm::dvec3> wsRelevant;  // visible receiver points (world)
    std::optional<glm::dvec4> floorPlane;    // plane-optimal's plane n·x + d = 0, |n| = 1
    // The vertices of the visible points' 3D convex hull (Readback::wsRelevantHull), when known:
    // the tight baselines fit to them, which is fitting to every visible point (optimizer.cpp).
    std::span<const glm::dvec3> wsRelevantHull;
    // The boundary samples h (eq. 6) is summed over, when known: plane-optimal then chooses its
    // fallback rotation by least h.
    const LightSamples* samples = nullptr;
    // The fraction the tight fits add to each half extent: Algorithm 1's (report §2.4).
    double margin = 0.02;
};

// What a baseline did, for tests and reports. Fields a method does not use stay at their default.
struct BaselineDiagnostics {
    // Empty when the method's own construction was used; otherwise which fallback and why.
    std::string fallback;
    // lispsm, in the light-directional space (world units for a directional light): sin γ, the
    // body's near and far distance along the view direction, and n_opt.
    double sinGamma = 0.0, zNear = 0.0, zFar = 0.0, nOpt = 0.0;
    // lispsm*: d, the focus body's extent along the warp axis (same units).
    double warpDepth = 0.0;
    // psm: the homogeneous light in the virtual camera's clip space, and the slide-back distance
    // (world units) of the virtual camera.
    glm::dvec4 clipLight{0.0};
    double slideBack = 0.0;
    // plane-optimal: the great-circle fraction by which p4 was turned toward the focused p4 (0 when
    // the plane-optimal p4 sees every relevant point).
    double rotationFraction = 0.0;
};

// Normal shadow map: p4 = (0, 0, 1), fitted over the eight bounds corners. Fallbacks (a point light
// so close to a long box that a corner is not in front of p4 = (0, 0, 1)): p4 = the normalized mean
// of the unit corner directions; else the axis of the narrowest cone around the corner
// directions (it exists whenever any axis sees every corner); else (a light in the plane of a
// box face) the narrowest cone around the relevant points, fitted over them only. Throws
// DomainError (Subject::kLight) when no axis sees every relevant point (they surround the light:
// no single light matrix sees them). Focused, LiSPSM and PSM start from this same axis.
LightMatrix NormalLightMatrix(const BaselineContext& context,
                              BaselineDiagnostics* diagnostics = nullptr);

// Focused: normal's p4; rectangle about (projected view frustum) ∩ (projected bounds), the
// frustum first cut to p4·X ≥ δ (δ = half the nearest bounds corner or relevant point) because a
// point light may sit inside it. Fallbacks: an empty or flat intersection → normal's matrix; a
// relevant point outside the rectangle (only through rounding, or relevant points outside the
// bounds) → refit over the intersection and the relevant points.
LightMatrix FocusedLightMatrix(const BaselineContext& context,
                               BaselineDiagnostics* diagnostics = nullptr);

// The tight baselines: each gets exactly what Algorithm 1 gets — the visible points (their hull),
// the same margin — instead of the view frustum ∩ scene bounds the report-faithful ones fit.
//   focused-tight  focused's axis (InitialLightAxis), the minimum-area rectangle around the
//                  visible points grown by context.margin (Brabec et al. 2002 fit the light
//                  frustum to the visible pixels): Algorithm 1's own starting map.
//   lispsm-tight   LiSPSM's warp (below) for the tight body (the visible points' hull swept
//                  toward the light to the scene bounds: every possible occluder), with its own
//                  map axes scaled to the visible points' bounds grown by context.margin; n from
//                  Wimmer's rule (LispsmNearRule::Kind::kWimmer).
//   lispsm-engine  lispsm-tight with the engines' n rule (LispsmNearRule::Kind::kEngine, no
//                  virtual planes): the same body, margin, depth test and fallback.
//   psm-tight      PSM's post-perspective light frustum for the tight body, likewise.
// Every point of wsRelevant maps into the map; a warp that fails falls back to focused-tight
// (reason in diagnostics).
LightMatrix FocusedTightLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics = nullptr);
LightMatrix LispsmTightLightMatrix(const BaselineContext& context,
                                   BaselineDiagnostics* diagnostics = nullptr);
LightMatrix LispsmEngineLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics = nullptr);
LightMatrix PsmTightLightMatrix(const BaselineContext& context,
                                BaselineDiagnostics* diagnostics = nullptr);

// LiSPSM (directional lights directly, point lights through the light's perspective first).
// Fallback to focused (reason in diagnostics): |sin γ| < 1e-3 (view along the light, where LiSPSM
// itself reverts to the unwarped map), a body point or the eye behind a point light's plane,
// FromScreenRows rejecting the rows, or the warp's p4 leaving a relevant point behind or outside.
LightMatrix LispsmLightMatrix(const BaselineContext& context,
                              BaselineDiagnostics* diagnostics = nullptr);

// PSM in the camera's post-perspective space (slid-back virtual camera, Kozlov's inverted
// projection for a light behind the viewer, an orthographic NDC map for a light on the camera
// plane). Fallback to focused (reason in diagnostics): no light frustum in NDC holds the whole
// body (the light's NDC point surrounded by it), FromScreenRows rejecting the rows, or the warp's
// p4 leaving a relevant point behind or outside.
LightMatrix PsmLightMatrix(const BaselineContext& context,
                           BaselineDiagnostics* diagnostics = nullptr);

// Plane-optimal for context.floorPlane (DomainError, Subject::kGeometry, when there is none),
// refitted over wsRelevant. When a relevant point is not safely in front of the plane-optimal p4
// (off the plane, its shadow on the plane behind the camera), p4 is turned toward the focused p4
// along the great circle: of the fractions t = t0 + (1 - t0)·i/16, i = 0..16 (t0 the smallest
// fraction that sees every point, by bisection), those whose fitted map keeps every visible point
// at least one texel's angle above the horizon p4·X = 0 are candidates (kHorizonTexels), and the
// one of least h over context.samples wins (the smallest when there are no samples; diagnostics'
// rotationFraction). Fallback to focused: the light on the floor plane, no relevant points, or no
// candidate.
LightMatrix PlaneOptimalLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics = nullptr);

// How far the points are above the horizon p4·X = 0 in texels: the least angle above it over the
// points, over the angle one texel subtends at the map's centre. Below 1 a point sits within one
// texel of the horizon, where the map's texels stretch without bound.
double HorizonClearanceTexels(const LightMatrix& m, std::span<const glm::dvec3> lsPoints,
                              Resolution map);
// plane-optimal's least clearance (dimensionless, in texels).
inline constexpr double kHorizonTexels = 1.0;

// The plane-optimal matrix before the affine refit: for A = identity, a floor point seen at
// screen point x (pixels of context.map's size) maps to u = x. nullopt, with the reason in
// *failure, when there is no floor plane or the light lies on it (no plane-optimal matrix exists).
std::optional<LightMatrix> PlaneOptimalProjectiveMatrix(const BaselineContext& context,
                                                        std::string* failure = nullptr);

// The optical axis Algorithm 1 starts from (report §2.3: "we start with a standard shadow map";
// focused's axis, which normal's is): in the frame of `lightSpace`, the axis toward the centre of
// wsBounds, or NormalLightMatrix's fallbacks when a bounds corner is behind it. Unit length.
// Throws DomainError (Subject::kLight) when no axis sees every visible point.
glm::dvec3 InitialLightAxis(const LightSpace& lightSpace, const Bounds& wsBounds,
                            std::span<const glm::dvec3> wsRelevant);

// Wimmer et al.'s optimal distance from the warp's projection centre to the body's near face:
// n_opt = (z_n + √(z_f z_n)) / sin γ; z_n + √(z_f z_n) when γ = 90° (Lloyd 2006 §4.1).
double LispsmOptimalNear(double zNear, double zFar, double sinGamma);

// How the tight LiSPSM chooses n, the distance from the warp's projection centre to the body's
// near face along the warp axis f (the view direction projected perpendicular to the light). The
// depths are those of LispsmWarp's light-directional space (world units for a directional light;
// see warping_baselines.cpp): z_n, z_f the body's nearest and farthest view depth, d its extent
// along f.
//   kWimmer  Wimmer, Scherzer & Purgathofer, EGSR 2004: n = (z_n + √(z_n z_f)) / sin γ
//            (LispsmOptimalNear), the body's real far depth.
//   kEngine  the far depth taken along the warp axis, z₁ = z₀ + d·sin γ with z₀ = z_n, as Filament
//            (filament/src/ShadowMap.cpp, ShadowMap::applyLISPSM) and OGRE's full rule
//            (OgreMain/src/OgreShadowCameraSetupLiSPSM.cpp, calculateNOpt) do; n in Filament's
//            form, n = (z₀ + √(z₀ · min(z₁, z_f))) / sin γ (Filament caps z₁ at z_f). Equal to
//            Wimmer's at γ = 90°, where d = z_f − z_n; below, smaller: a stronger warp.
//            Optionally Filament's virtual planes (ShadowOptions::shadowNearHint, shadowFarHint):
//            the root becomes √(vz₀ vz₁), vz₀ = max(z₀, virtualNear), vz₁ = min(z₁, z_f,
//            virtualFar), and n is at least dzn / (2 − 3 dzn / (z_f − z_n)), dzn = max(0,
//            virtualNear − camera near); where 3 dzn ≥ 2 (z_f − z_n) no warp helps and Filament
//            reverts to the orthographic map (LispsmNear: nullopt).
// Not taken from Filament: its orthographic map below sin γ = 0.02 (γ < 1.146°). Both rules keep
// warping down to lexel's cutoff sin γ = 1e-3 and fall back as lispsm-tight does below it; n is
// continuous in γ down to there.
//   kNearDepth  n = z_n / sin γ: Lloyd et al. 2006's η = 1 (n' = n) over Wimmer's sin γ, the
//            warping frustum of the optimal logarithmic parameterization for an overhead light
//            (their Appendix C: the view frustum itself); LogPSM's perspective warp (logpsm.h).
struct LispsmNearRule {
    enum class Kind { kWimmer, kEngine, kNearDepth };
    Kind kind = Kind::kWimmer;
    // kEngine only: Filament's virtual near and far planes, view depths in world units (Filament's
    // defaults are 1 m and 100 m). 0 and +∞: none.
    double virtualNear = 0.0;
    double virtualFar = std::numeric_limits<double>::infinity();
};

// The body's depths n is computed from (LispsmNearRule): 0 < zNear ≤ zFar, warpDepth ≥ 0.
struct LispsmDepths {
    double zNear = 0.0;      // z_n
    double zFar = 0.0;       // z_f
    double warpDepth = 0.0;  // d
};

// n for `rule`, sinGamma in (0, 1]; cameraNear (world units) enters only through the virtual near
// plane. nullopt where the virtual near plane leaves no warp (above), and for depths or a sinGamma
// outside their domain (never NaN).
std::optional<double> LispsmNear(const LispsmNearRule& rule, const LispsmDepths& depths,
                                 double sinGamma, double cameraNear);

// The tight LiSPSM (lispsm-tight's body, margin, depth test and fallback to focused-tight) with n
// from `rule`: LispsmTightLightMatrix is rule {kWimmer}, LispsmEngineLightMatrix rule {kEngine}.
LightMatrix LispsmRuleLightMatrix(const BaselineContext& context, const LispsmNearRule& rule,
                                  BaselineDiagnostics* diagnostics = nullptr);

// PSM's virtual camera (Kozlov's slide back): `camera` slid back along its view direction by
// `slideBack` world units, its near and far planes moved to [zNear, zFar] + slideBack (zNear, zFar:
// the depths of the focus body from the real eye). Same field of view, so its frustum contains the
// body.
Camera PsmVirtualCamera(const Camera& camera, double zNear, double zFar, double slideBack);

// The slide-back distance PSM uses for a body spanning view depths [zNear, zFar]: the smallest
// δ ≥ 0 with (zNear + δ) / (zFar + δ) ≥ kPsmMinNearFarRatio.
double PsmSlideBack(double zNear, double zFar);
// Our choice (not a value from the papers): the virtual near plane at least 1/20 of the virtual
// far plane, so that post-perspective depth keeps a usable range.
inline constexpr double kPsmMinNearFarRatio = 0.05;

}  // namespace lexel::spatial
