// Logarithmic perspective shadow maps (D. B. Lloyd, N. K. Govindaraju, C. Quammen, S. E. Molnar,
// D. Manocha, "Logarithmic Perspective Shadow Maps", ACM TOG 27(4), 2008): a perspective warp
// followed by a logarithm of its depth coordinate, the parameterization that reaches the bound
// S̄_opt = ln(f/n) / (2 tanθ) of B. Lloyd, D. Tuft, S. Yoon, D. Manocha, "Warping and
// Partitioning for Low Error Shadow Maps", EGSR 2006 (Appendix C) for an overhead light.
//
// The derivation (Lloyd 2006 Appendix C, re-derived): for an overhead directional light the
// optimal warping frustum is the view frustum itself, so that the lateral texel width grows as
// the eye depth z, like the pixel's (m_x constant); along the view the beam width w_lz = dz/dt
// must also grow as z, so dt/dz ∝ 1/z and t = ln(z/n) / ln(f/n) (m_z constant). In general
// position the perspective warp is LiSPSM's (warping_baselines.cpp): axis f the view direction
// projected perpendicular to the light, point lights through the light's perspective first,
// apex laterally at the eye and n = z_n / sin γ before the body's near face along f (Lloyd 2006's
// η = 1, n' = n, over Wimmer's sin γ as lexel's storage analysis does: LispsmNearRule::kNearDepth;
// the TOG paper's own rule for lights in general position is not among our texts). The warp's
// map coordinates are (x/ζ, A + B/ζ), ζ the distance from the apex along f; the logarithm is
// taken of ζ, which the map's second coordinate b determines: 1/ζ ∝ b − b∞, b∞ the image of the
// points at ζ = ∞ (in light space the directions X ⊥ the normal light axis a: a·X = 0, where the
// light's perspective sends points to infinity — for a directional light X.z = 0). So
//     u = M_x (b_x − c_x) / (2 h_x) + M_x / 2,    v = M_z (ℓ − c_ℓ) / (2 h_ℓ) + M_z / 2,
//     ℓ = σ ln(σ (b_y − b∞)),  σ = the sign of b_y − b∞ over the visible points,
// with (c, h) the centre and half extent, grown by the context's margin, of the visible points'
// b_x and ℓ: a MapWarp with an affine x axis and a logarithmic y axis (map_warp.h).
//
// Resolution. Lloyd's storage factor counts M_x · M_z texels with each axis at its own critical
// resolution (S̄ = M_x M_z / aspect), so LogPSM's map takes its aspect from the same analysis:
// over the visible points, the largest per-axis aliasing A_x, A_z at one texel per axis (the beam
// width along each map axis on the plane ⊥ the light ray over the pixel width 2 tanθ z / H),
// M_x / M_z = A_x / A_z, M_x M_z ≤ W H (the other single maps' texels). At γ = 90° this is the
// S̄_opt split M_x / M_z = 2 a tanθ / ln(f/n).
//
// Fallback: where LiSPSM's warp falls back (the view within ~0.06° of the light direction, a
// body reaching a point light's plane, ...) the map is focused-tight's with an affine y axis (no
// warp to take the logarithm of: every warping method reverts to the unwarped map there, Lloyd
// 2006 §4.4), with the same aspect rule; the reason is in BaselineDiagnostics::fallback.
#pragma once

#include <string>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/map_warp.h"

namespace lexel::spatial {

// The smallest side a LogPSM map is given, texels (its aspect rule could ask for less); a map of
// fewer than kLogPsmMinSide² texels keeps its own sides.
inline constexpr int kLogPsmMinSide = 16;

struct LogPsmMap {
    MapWarp warp;                // base: the perspective warp; x affine, y logarithmic (or affine)
    Resolution resolution;       // M_x × M_z, M_x M_z ≤ context.map's texels
    bool logarithmic = false;    // false: the fallback's affine y axis
    double aliasingRatio = 1.0;  // A_x / A_z, the aspect the analysis asked for
};

// LogPSM for the context's light and visible points (the header comment). Every visible point
// maps into [0, M_x] × [0, M_z]. Throws as the tight baselines do (baselines.h).
LogPsmMap LogPsmLightMap(const BaselineContext& context,
                         BaselineDiagnostics* diagnostics = nullptr);

}  // namespace lexel::spatial
