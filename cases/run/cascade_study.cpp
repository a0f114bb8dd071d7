#include "lexel/cases/run/cascade_study.h"

#include <algorithm>
#include <iterator>

#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {

namespace {

constexpr int kCounts[] = {1, 2, 4, 8};

double MeanMisclassified(const SweepResult& r, std::size_t method) {
    double sum = 0.0;
    for (const auto& light : r.cells) sum += light[method].misclassifiedMean;
    return r.cells.empty() ? 0.0 : sum / static_cast<double>(r.cells.size());
}

std::optional<std::size_t> IndexOf(const std::vector<std::string>& names, const std::string& m) {
    const auto it = std::find(names.begin(), names.end(), m);
    if (it == names.end()) return std::nullopt;
    return static_cast<std::size_t>(it - names.begin());
}

}  // namespace

std::vector<std::string> CascadeStudyMethods(const std::vector<std::string>& methods) {
    std::vector<std::string> out;
    for (const char* m : {"pssm", "sdsm", "sdsm-optimal"})
        if (IndexOf(methods, m)) out.emplace_back(m);
    return out;
}

std::vector<int> CascadeStudyCounts(int sweepCount) {
    std::vector<int> counts(std::begin(kCounts), std::end(kCounts));
    if (std::find(counts.begin(), counts.end(), sweepCount) == counts.end()) {
        counts.push_back(sweepCount);
        std::sort(counts.begin(), counts.end());
    }
    return counts;
}

std::vector<int> CascadeStudyExtraCounts(int sweepCount) {
    std::vector<int> counts = CascadeStudyCounts(sweepCount);
    counts.erase(std::find(counts.begin(), counts.end(), sweepCount));
    return counts;
}

CascadeCountStudy CascadeStudyOf(const SweepResult& sweep, int sweepCount,
                                 const StudyMisclassified& extra) {
    CascadeCountStudy study;
    study.methods = CascadeStudyMethods(sweep.methods);
    study.counts = CascadeStudyCounts(sweepCount);
    if (const auto optimal = IndexOf(sweep.methods, spatial::kOptimalMethod))
        study.optimalMean = MeanMisclassified(sweep, *optimal);
    study.meanMisclassified.assign(study.methods.size(), {});
    std::size_t next = 0;  // the next of `extra`
    for (int k : study.counts) {
        for (std::size_t m = 0; m < study.methods.size(); ++m) {
            if (k == sweepCount) {
                study.meanMisclassified[m].push_back(
                    MeanMisclassified(sweep, *IndexOf(sweep.methods, study.methods[m])));
                continue;
            }
            double sum = 0.0;
            for (const auto& light : extra.at(next)) sum += static_cast<double>(light.at(m));
            study.meanMisclassified[m].push_back(
                extra[next].empty() ? 0.0 : sum / static_cast<double>(extra[next].size()));
        }
        if (k != sweepCount) ++next;
    }
    return study;
}

CascadeCountStudy RunCascadeCountStudy(const spatial::Scene& scene, const SweepResult& sweep,
                                       const SweepLightDone& onLightDone, BackendKind backend) {
    const std::vector<std::string> methods = CascadeStudyMethods(sweep.methods);
    StudyMisclassified extra;
    for (int k : CascadeStudyExtraCounts(scene.partitions.count)) {
        spatial::Scene atK = scene;
        atK.partitions.count = k;
        const SweepResult r = RunSweep(atK, methods, sweep.lights, onLightDone, backend);
        auto& perLight = extra.emplace_back();
        for (const auto& cells : r.cells) {
            perLight.emplace_back();
            for (const SweepCell& c : cells) perLight.back().push_back(c.misclassifiedMean);
        }
    }
    return CascadeStudyOf(sweep, scene.partitions.count, extra);
}

}  // namespace lexel::cases
