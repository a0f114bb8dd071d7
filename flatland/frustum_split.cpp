#include "lexel/flatland/frustum_split.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/lexel_remap.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"
#include "lexel/solvers/lagrange_allocation.h"

namespace lexel::flatland {

namespace {

struct Group {
    double lsLow, lsHigh, wsAxis, unitError, term;
};

}  // namespace

SplitResult SplitLightFrustum(const SamplingPass& decision, int lexels,
                              const FrustaOptions& options, SplitStrategy strategy) {
    if (options.metric == Metric::kLinf)
        throw std::invalid_argument(
            "frustum split: the metric must be L1 or L2 (the Lagrange allocation needs a sum)");
    if (options.max < 1 || options.budget < 1)
        throw std::invalid_argument("frustum split: max and budget must be at least 1");
    const int exponent = options.metric == Metric::kL1 ? 1 : 2;
    const auto& samples = decision.samples;
    const double lo = decision.lsLow, hi = decision.lsHigh;  // the samples' extreme lsAngle
    const int wedges = options.max;
    const double width = (hi - lo) / wedges;
    // Bucket the samples by wedge (a counting sort: one 4-byte index per sample,
    // flatland/memory.h).
    const auto wedgeOf = [&](const FlatSample& s) {
        return std::clamp(static_cast<int>(std::floor((s.lsAngle - lo) / width)), 0, wedges - 1);
    };
    std::vector<std::size_t> bucketStart(wedges + 1, 0);  // bucket w is [start[w], start[w+1])
    for (const auto& s : samples) ++bucketStart[wedgeOf(s) + 1];
    for (int w = 0; w < wedges; ++w) bucketStart[w + 1] += bucketStart[w];
    std::vector<std::uint32_t> byWedge(samples.size());
    {
        std::vector<std::size_t> next(bucketStart.begin(), bucketStart.end() - 1);
        for (std::size_t i = 0; i < samples.size(); ++i)
            byWedge[next[wedgeOf(samples[i])]++] = static_cast<std::uint32_t>(i);
    }
    std::vector<int> occupied;
    for (int w = 0; w < wedges; ++w)
        if (bucketStart[w + 1] > bucketStart[w]) occupied.push_back(w);
    const int n = static_cast<int>(occupied.size());

    // A group of occupied wedges [a, b] (indices into `occupied`), optimized at N = 1 and cached.
    std::map<std::pair<int, int>, Group> cache;
    auto group = [&](int a, int b) -> const Group& {
        auto it = cache.find({a, b});
        if (it != cache.end()) return it->second;
        // The wedges between occupied[a] and occupied[b] are contiguous in byWedge, in wedge
        // order and, within a wedge, in sample order.
        const std::size_t first = bucketStart[occupied[a]], last = bucketStart[occupied[b] + 1];
        std::vector<double> angle, g;
        angle.reserve(last - first), g.reserve(last - first);
        for (std::size_t k = first; k < last; ++k) {
            const FlatSample& s = samples[byWedge[k]];
            angle.push_back(s.lsAngle), g.push_back(PixelsPerRadian(decision, s));
        }
        // Outer bounds are the samples' own extremes, exactly; inner ones are wedge edges.
        const double gLow = occupied[a] == 0 ? lo : lo + occupied[a] * width;
        const double gHigh = occupied[b] == wedges - 1 ? hi : lo + (occupied[b] + 1) * width;
        const LexelSamples ls =
            MakeLexelSamples(std::move(angle), std::move(g), decision.wsAxis0, 1.0, gLow, gHigh);
        const AngleSolution sol = exponent == 1 ? SolveL1Exact(ls) : SolveL2Exact(ls);
        Group out{gLow, gHigh, sol.wsAxis, sol.objective, AllocationTerm(sol.objective, exponent)};
        return cache.emplace(std::make_pair(a, b), out).first->second;
    };

    std::vector<std::pair<int, int>> chosen;  // groups as [a, b]
    if (strategy == SplitStrategy::kGreedy) {
        for (int k = 0; k < n; ++k) chosen.push_back({k, k});
        while (static_cast<int>(chosen.size()) > options.budget) {
            // The total is increasing in Σ terms, so the cheapest merge lowers Σ terms least.
            std::size_t best = 0;
            double bestDelta = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i + 1 < chosen.size(); ++i) {
                const double delta = group(chosen[i].first, chosen[i + 1].second).term -
                                     group(chosen[i].first, chosen[i].second).term -
                                     group(chosen[i + 1].first, chosen[i + 1].second).term;
                if (delta < bestDelta) bestDelta = delta, best = i;
            }
            chosen[best].second = chosen[best + 1].second;
            chosen.erase(chosen.begin() + best + 1);
        }
    } else {
        // best[m][j]: least Σ terms covering occupied wedges [0, j) with m frusta.
        const int budget = std::min(options.budget, n);
        const double inf = std::numeric_limits<double>::infinity();
        std::vector<std::vector<double>> best(budget + 1, std::vector<double>(n + 1, inf));
        std::vector<std::vector<int>> from(budget + 1, std::vector<int>(n + 1, -1));
        best[0][0] = 0.0;
        for (int m = 1; m <= budget; ++m)
            for (int j = 1; j <= n; ++j)
                for (int i = m - 1; i < j; ++i) {
                    if (!std::isfinite(best[m - 1][i])) continue;
                    const double value = best[m - 1][i] + group(i, j - 1).term;
                    if (value < best[m][j]) best[m][j] = value, from[m][j] = i;
                }
        int m = 1;
        for (int k = 1; k <= budget; ++k)
            if (best[k][n] < best[m][n]) m = k;
        for (int j = n; j > 0; --m) {
            const int i = from[m][j];
            chosen.insert(chosen.begin(), {i, j - 1});
            j = i;
        }
    }

    SplitResult result;
    result.wedges = n;
    result.exponent = exponent;
    result.wsAxis0 = decision.wsAxis0;
    std::vector<double> errors;
    double termSum = 0.0;
    for (const auto& [a, b] : chosen) {
        const Group& g = group(a, b);
        result.frusta.push_back({g.lsLow, g.lsHigh, g.wsAxis, g.unitError, 0});
        errors.push_back(g.unitError);
        termSum += g.term;
    }
    const auto holding =
        std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0; });
    if (holding > lexels)
        throw DomainError(Subject::kLexels, std::to_string(lexels) + " lexels cannot serve " +
                                                std::to_string(holding) +
                                                " frusta that hold samples");
    const std::vector<int> alloc = AllocateLexelsInteger(errors, exponent, lexels);
    for (std::size_t j = 0; j < alloc.size(); ++j) result.frusta[j].lexels = alloc[j];
    result.realTotal = AllocatedTotal(termSum, exponent, lexels);
    return result;
}

MethodReport EvaluateSplit(const FlatScene& scene, const SamplingPass& full,
                           const SplitResult& split, bool keepFootprints) {
    const std::size_t count = split.frusta.size();
    // Full-pass indices of each frustum's samples: 4 bytes per sample (flatland/memory.h).
    std::vector<std::vector<std::uint32_t>> partIndex(count);
    std::vector<double> low(count), high(count);
    for (std::size_t j = 0; j < count; ++j)
        low[j] = split.frusta[j].lsLow, high[j] = split.frusta[j].lsHigh;
    for (std::size_t i = 0; i < full.samples.size(); ++i) {
        const FlatSample& s = full.samples[i];
        const double rel = WrapAngle(full.wsAxis0 + s.lsAngle - split.wsAxis0);
        std::size_t owner = 0;
        double distance = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < count; ++j) {
            const double d = rel < split.frusta[j].lsLow    ? split.frusta[j].lsLow - rel
                             : rel > split.frusta[j].lsHigh ? rel - split.frusta[j].lsHigh
                                                            : 0.0;
            if (d < distance) distance = d, owner = j;
        }
        partIndex[owner].push_back(static_cast<std::uint32_t>(i));
        low[owner] = std::min(low[owner], rel);
        high[owner] = std::max(high[owner], rel);
    }
    MethodReport report;
    report.footprints.assign(full.samples.size(), 0.0);
    for (std::size_t j = 0; j < count; ++j) {
        const PlannedFrustum& planned = split.frusta[j];
        FrustumReport fr;
        fr.wsRayLowDeg = Degrees(split.wsAxis0 + low[j]);
        fr.wsRayHighDeg = Degrees(split.wsAxis0 + high[j]);
        fr.lexels = planned.lexels;
        double axis = planned.wsAxis;
        auto f = FootprintsFromScratch(full, partIndex[j], scene.wsLight, axis, planned.lexels,
                                       split.wsAxis0 + low[j], split.wsAxis0 + high[j]);
        if (!f) {  // widened bounds left the planned axis invalid: use the widened bisector
            axis = split.wsAxis0 + 0.5 * (low[j] + high[j]);
            f = FootprintsFromScratch(full, partIndex[j], scene.wsLight, axis, planned.lexels,
                                      split.wsAxis0 + low[j], split.wsAxis0 + high[j]);
            report.note = "a frustum's axis was reset to its bisector after widening";
        }
        fr.lexelPlaneDeg = LexelPlaneDegFromAxis(axis);
        fr.wsAxis = axis;
        for (std::size_t k = 0; k < f->size(); ++k) report.footprints[partIndex[j][k]] = (*f)[k];
        fr.stats = SummarizeFootprintsInPlace(*f);
        std::vector<std::uint32_t>().swap(partIndex[j]);  // released as soon as it is measured
        report.frusta.push_back(fr);
    }
    if (keepFootprints)
        report.stats = SummarizeFootprints(report.footprints);
    else
        report.stats = SummarizeFootprintsInPlace(report.footprints), report.footprints = {};
    report.lexelPlaneDeg = report.frusta.empty() ? 0.0 : report.frusta.front().lexelPlaneDeg;
    report.wsAxis = report.frusta.empty() ? 0.0 : report.frusta.front().wsAxis;
    return report;
}

}  // namespace lexel::flatland
