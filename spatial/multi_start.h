// lexel's `optimal`: Chong & Gortler's Algorithm 1 (report §2.3) from several starts. The search is
// local — it rotates p4 from wherever it starts — so where it starts matters; here it starts from
// every baseline's axis, and most starts' own maps are candidates too (a warped baseline's affine
// part is not the rectangle fit). The least energy wins (e for `optimal`, h of eq. 6 for
// `optimal-h`), so on its own energy `optimal` never loses to a baseline whose map competes.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/optimizer.h"

namespace lexel::spatial {

// A candidate map and the axis a search starts from.
struct OptimizerStart {
    std::string name;  // the baseline it came from
    LightMatrix matrix;
    bool mapCompetes = true;  // false: only the search from its axis competes, not this map
};

// `optimal`'s starts: focused-tight, lispsm-tight, lispsm-engine, psm-tight, normal, and
// plane-optimal when the context has a floor plane (all with the context as given; its samples,
// when set, steer plane-optimal's fallback). plane-optimal's own map does not compete (its search
// does): it is fit to the floor alone, e ranks it above what it measures off the floor, and its
// error swings with the texel grid's phase (RESULTS.md, "plane-optimal's map as a candidate").
// Throws DomainError as the baselines do.
std::vector<OptimizerStart> StandardStarts(const BaselineContext& context);

struct MultiStartResult {
    OptimizerResult result;       // the winner (h, matrix); times summed over every search
    std::string winner;           // the start whose map or search won
    bool startMapWon = false;     // a competing start's own map, not a search, had the least h
    std::vector<double> startH;   // per start: h of its own map (also where it does not compete)
    std::vector<double> searchH;  // per start: h after Algorithm 1 from its axis (+inf: skipped,
                                  // the axis repeats an earlier start's)
    int starving = 0;  // candidates the view guard passed over (OptimizerOptions::starveFactor)
};

// Algorithm 1 (OptimizeLightMatrix, without refinement) from each start's axis; the least energy
// (options.energy: h by default; startH and searchH hold it) among the competing starts' maps
// (mapCompetes) and the searches wins. With options.refine, the best search's axis is also
// refined (optimal-refined) and competes too. With options.starveFactor > 0, a candidate whose
// RelevantFootprint (energy.h) exceeds that factor times the least of the competing starts' maps'
// does not compete (MultiStartResult::starving counts them); where that leaves no candidate with a
// finite energy, the choice is made without the guard. `starts` must not be empty
// (std::invalid_argument).
// With options.maxSamples, everything (startH too) runs on the same thinned samples. Throws
// DomainError as OptimizeLightMatrix does, and when no candidate has a finite energy.
MultiStartResult OptimizeFromStarts(const LightSamples& samples,
                                    std::span<const OptimizerStart> starts, Resolution map,
                                    const OptimizerOptions& options = {});

}  // namespace lexel::spatial
