// Light-hull partitioning with Lagrange lexel allocation (Chong 2003, §3.2, Algorithm 2).
//
// The light's angular range, as seen from the light, is split evenly into `max` wedges. Wedges
// without samples need no shadow map; the others, in angular order, are grouped into contiguous
// frusta. A frustum spans from its first wedge's lower bounding ray to its last wedge's upper one
// (the gaps between frusta hold no visible point), has its own optimal lexel plane, and its
// error with a unit lexel count e_j is that optimum's L1 (Σf) or L2 (Σf²) at N = 1: the thesis's
// "scaled such that the lexel range for that frustum is unit length". Re-expressing l in the
// frustum and scaling dp/dl by the size ratio, as the thesis does, is the same as building the
// frustum's LexelSamples from the samples' (α, g) with the frustum's bounds (lexel_remap.h).
//
// Lagrange allocation (solvers/lagrange_allocation.h) makes the optimal total
//     Σ_j e_j / N_j^k = (Σ_j e_j^(1/(k+1)))^(k+1) / L^k,
// a monotone function of the sum of per-frustum terms e_j^(1/(k+1)). Hence:
//   greedy  the thesis: repeatedly merge the adjacent pair whose merge (re-optimized angle,
//           reallocated lexels) raises the total least, until `budget` frusta remain;
//   dp      exact: minimize Σ terms over all contiguous groupings into at most `budget` frusta,
//           O(budget · W²) over the W non-empty wedges with each group's term computed once.
#pragma once

#include <vector>

#include "lexel/flatland/methods.h"
#include "lexel/flatland/sampling.h"

namespace lexel::flatland {

enum class SplitStrategy { kGreedy, kDynamicProgram };

struct PlannedFrustum {
    double lsLow = 0.0, lsHigh = 0.0;  // bounding rays, light angles relative to the pass's θ0
    double wsAxis = 0.0;               // its optimal optical axis
    double unitError = 0.0;            // e_j
    int lexels = 0;                    // integer Lagrange allocation
};

struct SplitResult {
    std::vector<PlannedFrustum> frusta;
    double realTotal = 0.0;  // Σ e_j / N_j^k at the real-valued Lagrange allocation
    int wedges = 0;          // non-empty wedges at the start
    int exponent = 1;        // k: 1 for L1, 2 for L2
    double wsAxis0 = 0.0;    // the pass's θ0
};

// Plans the split from the decision pass. Throws DomainError (Subject::kLexels) when there are
// fewer lexels than frusta that hold samples; std::invalid_argument for a metric other than
// L1/L2 or max, budget < 1 (a loader checks these).
SplitResult SplitLightFrustum(const SamplingPass& decision, int lexels,
                              const FrustaOptions& options, SplitStrategy strategy);

// Measures a planned split at full resolution: each full-resolution sample goes to the frustum
// whose bounds hold its light angle (one in a gap goes to the nearer frustum, whose bound then
// widens to include it), footprints are computed from scratch in world space. The report keeps
// the per-pixel footprints only with keepFootprints (as RunFlatlandCase).
MethodReport EvaluateSplit(const FlatScene& scene, const SamplingPass& full,
                           const SplitResult& split, bool keepFootprints = false);

}  // namespace lexel::flatland
