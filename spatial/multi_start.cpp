#include "lexel/spatial/multi_start.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"

namespace lexel::spatial {

std::vector<OptimizerStart> StandardStarts(const BaselineContext& context) {
    std::vector<OptimizerStart> starts = {
        {"focused-tight", FocusedTightLightMatrix(context)},
        {"lispsm-tight", LispsmTightLightMatrix(context)},
        {"lispsm-engine", LispsmEngineLightMatrix(context)},
        {"psm-tight", PsmTightLightMatrix(context)},
        {"normal", NormalLightMatrix(context)},
    };
    if (context.floorPlane)
        starts.push_back({"plane-optimal", PlaneOptimalLightMatrix(context), false});
    return starts;
}

namespace {

// Whether an earlier start already searched from this axis (normal and focused share theirs).
bool Searched(std::span<const OptimizerStart> starts, std::size_t k) {
    for (std::size_t j = 0; j < k; ++j)
        if (starts[j].matrix.p4 == starts[k].matrix.p4) return true;
    return false;
}

void Accumulate(const OptimizerResult& search, OptimizerResult* total) {
    total->hullMs += search.hullMs;
    total->searchMs += search.searchMs;
    total->refineMs += search.refineMs;
    total->candidatesTried += search.candidatesTried;
    total->candidatesRejected += search.candidatesRejected;
}

}  // namespace

MultiStartResult OptimizeFromStarts(const LightSamples& samples,
                                    std::span<const OptimizerStart> starts, Resolution map,
                                    const OptimizerOptions& options) {
    if (starts.empty()) throw std::invalid_argument("OptimizeFromStarts: no starts");
    if (options.maxSamples != 0 && samples.lsX.size() > options.maxSamples) {
        OptimizerOptions every = options;  // thinned once: every start is judged on the same
        every.maxSamples = 0;
        return OptimizeFromStarts(SamplesWithinBudget(samples, options), starts, map, every);
    }
    MultiStartResult out;
    OptimizerOptions searchOptions = options;
    searchOptions.refine = false;
    double bestH = std::numeric_limits<double>::infinity();
    std::size_t bestSearch = starts.size();  // the start whose search did best
    double bestSearchH = std::numeric_limits<double>::infinity();
    OptimizerResult totals;
    for (std::size_t k = 0; k < starts.size(); ++k) {
        const OptimizerStart& start = starts[k];
        out.startH.push_back(Energy(start.matrix, samples, options.energy));
        out.searchH.push_back(std::numeric_limits<double>::infinity());
        if (start.mapCompetes && out.startH[k] < bestH) {
            bestH = out.startH[k];
            out.result = OptimizerResult{};
            out.result.matrix = start.matrix;
            out.result.h = bestH;
            out.result.hAfterIteration = {bestH};
            out.winner = start.name;
            out.startMapWon = true;
        }
        if (Searched(starts, k)) continue;
        OptimizerResult search = OptimizeLightMatrix(samples, start.matrix.p4, map, searchOptions);
        Accumulate(search, &totals);
        out.searchH[k] = search.h;
        if (search.h < bestSearchH) bestSearchH = search.h, bestSearch = k;
        if (search.h < bestH) {
            bestH = search.h;
            out.result = std::move(search);
            out.winner = start.name;
            out.startMapWon = false;
        }
    }
    if (!std::isfinite(bestH))  // no competing map and no search has a finite energy
        throw DomainError(Subject::kLight,
                          "OptimizeFromStarts: no competing start's map and no search from a "
                          "start's axis has a finite energy");
    const double bestBeforeRefine = bestH;
    if (options.refine && bestSearch < starts.size()) {
        OptimizerResult refined =
            OptimizeLightMatrix(samples, starts[bestSearch].matrix.p4, map, options);
        totals.refineMs += refined.refineMs;
        if (refined.h < bestH) {
            bestH = refined.h;
            out.result = std::move(refined);
            out.winner = starts[bestSearch].name;
            out.startMapWon = false;
        }
    }
    out.result.hBeforeRefine = bestBeforeRefine;
    out.result.hullMs = totals.hullMs;
    out.result.searchMs = totals.searchMs;
    out.result.refineMs = totals.refineMs;
    out.result.candidatesTried = totals.candidatesTried;
    out.result.candidatesRejected = totals.candidatesRejected;
    return out;
}

}  // namespace lexel::spatial
