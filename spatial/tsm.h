// Trapezoidal shadow maps (T. Martin, T.-S. Tan, "Anti-aliasing and Continuity with Trapezoidal
// Shadow Maps", EGSR 2004, §6; N_T as in the authors' "TSM recipe"): in the light's image plane,
// the region the camera sees is bounded by a trapezoid whose parallel edges are perpendicular to
// the centre line l (the image of the view axis, from its near point to its far point), and the
// projective map N_T sending that trapezoid onto the square [-1, 1]² is the shadow map's warp.
//
// The construction (§6), in any plane coordinates:
//   1. top line ⊥ l touching the points' hull on the near side, base line ⊥ l on the far side;
//      λ their distance;
//   2. the 80% rule: the focus point (the view axis at the focus depth) lies δ' from the top line
//      along l; the projection centre q sits η before the top line on l, with
//          η = λ δ' (1 + ξ) / (λ (1 − ξ) − 2 δ'),   ξ = −0.6,
//      so that N_T puts the focus point on the line y = ξ: 80% of the way from the top edge
//      (y = +1) to the base (y = −1). Re-derived: along a line through q at distance a from q,
//      N_T's y is A + B/a (a projective map with its pole at q), and y(η) = 1, y(η + λ) = −1,
//      y(η + δ') = ξ give that η (and A = −1 − 2η/λ, B = 2η(η + λ)/λ);
//   3. the side lines: from q, the two lines through the hull points at the largest angles on
//      either side of l; the trapezoid's corners are where they cut the top and base lines.
// N_T is written in closed form rather than as the recipe's chain T1 R T2 H S1 N T3 S2 (the two
// agree: a projective map of the plane is fixed by four corners; tsm_test.cpp checks it): with
// a = l·(y − q) and b = l⊥·(y − q), s = b/a the slope of the ray from q, s₋ < s₊ the side lines'
// slopes,
//     x' = (s − (s₊ + s₋)/2) / ((s₊ − s₋)/2),   y' = A + B/a   (homogeneous: denominator a).
//
// As a light matrix: the plane is p4·X = 1 (the light's central projection, light_space.h), so
// u = N_T (y, 1) with y = (b1·X, b2·X)/(p4·X) is a projective map of X — the rows of a
// LightMatrix (light_matrix.h), and a 4×4 that rasterizes exactly (ClipFromWorld, clip_matrix.h).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/light_matrix.h"

namespace lexel::spatial {

// ξ of the 80% rule: the focus point's y in N_T's square, 1 − 2 · 0.8 (the top edge is +1).
inline constexpr double kTsmFocusLine = -0.6;

struct Trapezoid {
    // The paper's corner order: t0, t1 on the base (far) line, t2, t3 on the top (near) line;
    // N_T sends them to (−1, −1), (1, −1), (1, 1), (−1, 1).
    std::array<glm::dvec2, 4> t;
    glm::dvec2 q{0.0};        // the projection centre: where the side lines meet
    glm::dvec2 l{0.0, 1.0};   // unit centre-line direction, near to far
    double lambda = 0.0;      // from the top line to the base line, along l
    double deltaPrime = 0.0;  // from the top line to the focus point, along l
    double eta = 0.0;         // from q to the top line, along l
    // N_T on the plane: (y, 1) ↦ homogeneous (x'w, y'w, w), w = l·(y − q) > 0 inside.
    glm::dmat3 squareFromPlane{1.0};

    // N_T(y): in [−1, 1]² for every point of the trapezoid; y' = +1 on the top line.
    glm::dvec2 ToSquare(const glm::dvec2& y) const;
};

// The trapezoid of §6 around `planePoints` (any number ≥ 1; their convex hull is what matters),
// for a centre line through nearPoint → farPoint and the 80% rule's focus point `focusPoint`
// (ξ = focusLine). nullopt, with the reason in *failure, when the centre line is shorter than
// 1e-3 of the points' extent (the view along the light: no trapezoid, §6), the points span no
// height along it or no width across it, or the focus point does not lie strictly between the
// top line and the line 1 − (1 + ξ)/2 of the way to the base (then η would be ≤ 0 or infinite:
// the focus already lies beyond the 80% line without a warp).
std::optional<Trapezoid> FitTrapezoid(std::span<const glm::dvec2> planePoints,
                                      const glm::dvec2& nearPoint, const glm::dvec2& farPoint,
                                      const glm::dvec2& focusPoint,
                                      double focusLine = kTsmFocusLine,
                                      std::string* failure = nullptr);

// Which body a TSM is fitted to.
enum class TsmBody {
    kVisible,  // tsm: the readback's visible points (their hull) and the context's margin
    kFrustum,  // tsm-report: the paper's, the view frustum ∩ scene bounds (FocusBody), no margin
};

struct TsmOptions {
    // Where the focus point sits on the view axis, as a fraction of the body's planar eye depth
    // range [z_n, z_f] from z_n. The paper leaves the focus region to the user; ours is the
    // middle (an assumption: NVIDIA's PracticalPSM sample sets δ' = 0.52 λ in the same spirit).
    double focusDepth = 0.5;
};

// What FitTsm built: the matrix, and when the construction succeeded its trapezoid in the plane
// p4·X = 1 (PlaneBasis(p4) coordinates) and the depths of its centre line and focus point.
struct TsmFit {
    LightMatrix matrix;
    std::optional<Trapezoid> trapezoid;            // nullopt when it fell back
    glm::dvec3 planeAxis{0.0, 0.0, 1.0};           // p4 of the light's image plane (focused's axis)
    double zNear = 0.0, zFar = 0.0, zFocus = 0.0;  // planar eye depths of l's points
    std::string fallback;                          // empty when the trapezoid was used
};

// The trapezoid in the light's image plane about focused's axis (InitialLightAxis for kVisible,
// the normal axis for kFrustum), the centre line through the view axis at the body's nearest and
// farthest planar eye depth, N_T onto the map with the square's half sides grown by
// context.margin (kVisible). Falls back (reason in `fallback`) to focused-tight (kVisible) or
// focused (kFrustum) when FitTrapezoid fails, a centre-line point is behind the light's plane,
// or the matrix leaves a visible point behind or outside. Throws as the baselines do.
TsmFit FitTsm(const BaselineContext& context, TsmBody body, const TsmOptions& options = {});

// FitTsm's matrix, with its fallback noted in diagnostics: tsm and tsm-report.
LightMatrix TsmLightMatrix(const BaselineContext& context,
                           BaselineDiagnostics* diagnostics = nullptr);
LightMatrix TsmReportLightMatrix(const BaselineContext& context,
                                 BaselineDiagnostics* diagnostics = nullptr);

}  // namespace lexel::spatial
