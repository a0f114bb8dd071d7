#include "lexel/spatial/multi_start.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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

// The view guard (OptimizerOptions::starveFactor): whether a candidate's mean footprint over the
// prior points exceeds the factor times the least of the competing starts' maps'. Off (never
// starving) for a factor ≤ 0, or where no competing start's footprint is defined.
class ViewGuard {
  public:
    ViewGuard(const LightSamples& samples, std::span<const OptimizerStart> starts, double factor)
        : samples_(samples), factor_(factor) {
        if (!(factor > 0.0)) return;
        for (const OptimizerStart& start : starts)
            if (const std::optional<double> f = RelevantFootprint(start.matrix, samples);
                start.mapCompetes && f)
                least_ = std::min(least_, *f);
    }

    bool Starves(const LightMatrix& matrix) const {
        if (!(factor_ > 0.0) || !std::isfinite(least_)) return false;
        const std::optional<double> f = RelevantFootprint(matrix, samples_);
        return f && *f > factor_ * least_;
    }

  private:
    const LightSamples& samples_;
    double factor_;
    double least_ = std::numeric_limits<double>::infinity();
};

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
    const ViewGuard guard(samples, starts, options.starveFactor);
    // Whether a candidate of energy h beats the best so far and does not starve the view.
    const auto wins = [&](double h, const LightMatrix& matrix) {
        if (!(h < bestH)) return false;
        if (!guard.Starves(matrix)) return true;
        ++out.starving;
        return false;
    };
    for (std::size_t k = 0; k < starts.size(); ++k) {
        const OptimizerStart& start = starts[k];
        out.startH.push_back(Energy(start.matrix, samples, options.energy));
        out.searchH.push_back(std::numeric_limits<double>::infinity());
        if (start.mapCompetes && wins(out.startH[k], start.matrix)) {
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
        if (wins(search.h, search.matrix)) {
            bestH = search.h;
            out.result = std::move(search);
            out.winner = start.name;
            out.startMapWon = false;
        }
    }
    if (!std::isfinite(bestH) && out.starving > 0) {  // the guard passed over every finite one
        OptimizerOptions unguarded = options;
        unguarded.starveFactor = 0.0;
        MultiStartResult chosen = OptimizeFromStarts(samples, starts, map, unguarded);
        chosen.starving = out.starving;
        return chosen;
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
        if (wins(refined.h, refined.matrix)) {
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
