// Derivation (lexel_remap.h, R2, taken about the Normal axis).
//
// The Normal axis θ_N bisects the sweep [θ_N − h, θ_N + h] of the visible points, so with
// τ = tan h and T_i = tan(α_i − θ_N) ∈ [−τ, τ], R2 with T_lo = −τ, T_hi = τ gives the footprint of
// pixel i at the axis θ_N + x, t = tan x:
//     f_i(t) = f_N,i (1 + t T_i)² / (1 − t² τ²).
// Averaging over the n visible pixels with the footprint-weighted moments
//     m0 = Σ f_N,i / n,   m1 = Σ f_N,i T_i / n,   m2 = Σ f_N,i T_i² / n
// gives the average at any angle as
//     avg(t) = (m0 + 2 t m1 + t² m2) / (1 − t² τ²).                                     (C1)
// The L1 optimum t* makes avg stationary; differentiating (C1) and clearing the denominator,
//     m1 (1 + t*² τ²) + t* (m2 + τ² m0) = 0.                                            (C2)
// m0 is the Normal row's average; (C1) at t* equals the L1 row's average. For a trial τ, (C1) and
// (C2) are two linear equations in (m1, m2). They are moments of the positive measure f_N on
// [−τ, τ] only if (truncated Hausdorff moment problem, order 2)
//     m1² ≤ m0 m2   and   m2 ≤ τ² m0,
// and the optimum's angle must be valid: |t*| τ < 1. Every τ that passes predicts the average at
// any other angle by (C1). A table whose third row's average falls outside the predicted range
// is inconsistent with lexel's footprint (dp/dl with tight extents) under any geometry; one
// inside is consistent with it. The conditions are necessary, not sufficient, for a scene.
#include "lexel/flatland/studies/table_consistency.h"

#include <algorithm>
#include <cmath>

#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

namespace {

double TanOfOffset(double fromDeg, double toDeg) {
    // Lexel plane angles are defined mod 180°: the offset is taken in (−90°, 90°).
    const double offsetDeg = std::remainder(toDeg - fromDeg, 180.0);
    return std::tan(Radians(offsetDeg));
}

}  // namespace

SweepWindow PredictAverageFromRows(double normalDeg, double normalAverage, double l1Deg,
                                   double l1Average, double otherDeg, int steps) {
    SweepWindow window;
    const double tOpt = TanOfOffset(normalDeg, l1Deg);
    const double tOther = TanOfOffset(normalDeg, otherDeg);
    const double m0 = normalAverage;
    // |t*| τ < 1 keeps the optimum valid; tOpt = 0 leaves τ unbounded and (C2) uninformative.
    if (tOpt == 0.0) return window;
    const double tauMax = 1.0 / std::abs(tOpt);
    for (int k = 1; k < steps; ++k) {
        const double tau = tauMax * k / steps;
        const double tt = tOpt * tOpt * tau * tau;
        // (C1): 2 t* m1 + t*² m2 = avg* (1 − t*² τ²) − m0;  (C2): (1 + t*² τ²) m1 + t* m2 = −t* τ²
        // m0.
        const double a11 = 2.0 * tOpt, a12 = tOpt * tOpt, b1 = l1Average * (1.0 - tt) - m0;
        const double a21 = 1.0 + tt, a22 = tOpt, b2 = -tOpt * tau * tau * m0;
        const double det = a11 * a22 - a12 * a21;  // = t*² (1 − t*² τ²) ≠ 0
        const double m1 = (b1 * a22 - a12 * b2) / det;
        const double m2 = (a11 * b2 - a21 * b1) / det;
        if (m1 * m1 > m0 * m2 || m2 > tau * tau * m0) continue;
        const double predicted =
            (m0 + 2.0 * tOther * m1 + tOther * tOther * m2) / (1.0 - tOther * tOther * tau * tau);
        if (!(predicted > 0.0)) continue;  // the other angle is invalid for this sweep
        const double halfSweepDeg = Degrees(std::atan(tau));
        const double edge = std::abs(m1) / (m0 * tau);
        if (!window.feasible) {
            window = {true, halfSweepDeg, halfSweepDeg, predicted, predicted, edge, edge};
            continue;
        }
        window.halfSweepLoDeg = std::min(window.halfSweepLoDeg, halfSweepDeg);
        window.halfSweepHiDeg = std::max(window.halfSweepHiDeg, halfSweepDeg);
        window.predictedLo = std::min(window.predictedLo, predicted);
        window.predictedHi = std::max(window.predictedHi, predicted);
        window.edgeConcentrationLo = std::min(window.edgeConcentrationLo, edge);
        window.edgeConcentrationHi = std::max(window.edgeConcentrationHi, edge);
    }
    return window;
}

}  // namespace lexel::flatland
