// The optimal lexel plane angle for one light frustum (Chong 2003, §3.1, Algorithm 1).
//
// With t = tan x (x = θ − θ0, lexel_remap.h eq. R2) every footprint is
//     f_i(t) = f0_i (1 + tT_i)² / D(t),    D(t) = (1 + tT_hi)(1 + tT_lo) > 0 on the valid interval.
//
// L1.  Σ f_i = N1(t)/D(t) with N1(t) = S0 + 2 S1 t + S2 t², where S_k = Σ f0_i T_i^k are three
//      moments of the samples. d/dt (N1/D) = (N1'D − N1 D')/D²; the t³ terms of the numerator
//      cancel, so the critical points are the roots of one quadratic. Because N1/D → +∞ at both
//      ends of the valid interval and has at most two critical points, it has exactly one interior
//      minimum: the L1 optimum is unique. The thesis's "eight critical points from Mathematica"
//      are these two roots seen through x instead of t: each root t gives x = atan t and x + π
//      (the same film line with its axis flipped), and solving in sin x / cos x (or the half-angle
//      tan(x/2), where t = 2τ/(1−τ²) has two solutions τ per t) doubles them again: 2 × 2 × 2 = 8
//      candidates, of which at most one is a valid minimum.
// L2.  Σ f_i² = Q(t)/D(t)² with Q(t) = Σ f0_i² (1 + tT_i)⁴ = Σ_k C(4,k) M_k t^k, M_k = Σ f0_i²
// T_i^k
//      (five moments). The derivative's numerator is Q'D − 2QD', whose t⁵ terms cancel: a quartic,
//      solved exactly through the eigenvalues of its companion matrix.
// L∞.  max_i f_i = E(t)²/D(t), where E(t) = max_i sqrt(f0_i)(1 + tT_i) is the upper envelope of
//      lines (1 + tT_i > 0 on the valid interval). On each envelope piece E = a + bt, and
//      d/dt[(a+bt)²/D] = 0 reduces to the linear equation (2b − ap) + (bp − 2aq)t = 0 with
//      D = 1 + pt + qt². The global minimum is the least value over the pieces' critical points
//      and breakpoints: exact, with no assumption beyond the envelope.
// All solvers run on a LexelSamples set (the decision pass) and return t; lexel_plane_deg and the
// full-resolution footprints follow from it.
#pragma once

#include <cstdint>
#include <string>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/solvers/footprint_metrics.h"

namespace lexel::flatland {

struct AngleSolution {
    double t = 0.0;          // tan(θ − θ0)
    double wsAxis = 0.0;     // θ, world radians
    double objective = 0.0;  // the solver's metric on its samples
    int iterations = 0;      // Newton iterations, Ceres iterations or objective evaluations
    std::string note;        // non-empty when a fallback was taken
};

// Direct per-sample evaluation of L1 = Σf, L2 = Σf² or L∞ = max f at t (no moments).
double AngleObjective(const LexelSamples& samples, Metric metric, double t);

struct L1Moments {
    double s0 = 0, s1 = 0, s2 = 0;
};
struct L2Moments {
    double m[5] = {0, 0, 0, 0, 0};
};
L1Moments ComputeL1Moments(const LexelSamples& samples);
L2Moments ComputeL2Moments(const LexelSamples& samples);

AngleSolution SolveL1Exact(const LexelSamples& samples);
AngleSolution SolveL2Exact(const LexelSamples& samples);
AngleSolution SolveLinfExact(const LexelSamples& samples);

// Thesis Algorithm 1: for i = 0..k, guess ← i·RandomOffset(); Newton on dE/dx from the guess,
// adding RandomOffset() to the guess while the result is invalid; return the least error.
// Each Newton step sums over all samples (as the thesis's NewtonSolution does).
struct NewtonRestartOptions {
    int restarts = 8;             // k
    std::uint64_t seed = 1;       // RandomOffset() stream
    double maxOffsetDeg = 10.0;   // RandomOffset() is uniform in ±maxOffsetDeg
    int maxTriesPerRestart = 64;  // bounds the thesis's "while result is invalid"
};
AngleSolution SolveL2Newton(const LexelSamples& samples, const NewtonRestartOptions& options = {});

// Ceres least squares over the angle x with one residual r_k = sqrt(Σ f_i(x)²) per chunk of 4096
// samples (so ½Σr² = ½L2, as with a residual per sample, without Ceres's per-residual memory),
// automatic differentiation through the templated remap, x bounded to the valid interval, started
// from x = 0 and from points spread over the valid interval; the least objective wins.
AngleSolution SolveL2Ceres(const LexelSamples& samples);

// Brute-force reference: the metric at `cells` evenly spaced angles over the valid interval, then
// a golden-section refinement inside the best cell's neighbours.
struct SweepOptions {
    int cells = 2048;
    int refineIterations = 120;
};
AngleSolution SolveSweep(const LexelSamples& samples, Metric metric,
                         const SweepOptions& options = {});

}  // namespace lexel::flatland
