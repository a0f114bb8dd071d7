#include "lexel/cases/run/cascade_study.h"

#include <algorithm>

namespace lexel::cases {

namespace {

constexpr int kCounts[] = {1, 2, 4, 8};

double MeanMisclassified(const SweepResult& r, std::size_t method) {
    double sum = 0.0;
    for (const auto& light : r.cells) sum += static_cast<double>(light[method].misclassified);
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

CascadeCountStudy RunCascadeCountStudy(const spatial::Scene& scene, const SweepResult& sweep,
                                       const std::function<void()>& onLightDone,
                                       BackendKind backend) {
    CascadeCountStudy study;
    study.methods = CascadeStudyMethods(sweep.methods);
    study.counts.assign(std::begin(kCounts), std::end(kCounts));
    if (std::find(study.counts.begin(), study.counts.end(), scene.partitions.count) ==
        study.counts.end()) {
        study.counts.push_back(scene.partitions.count);
        std::sort(study.counts.begin(), study.counts.end());
    }
    if (const auto optimal = IndexOf(sweep.methods, "optimal"))
        study.optimalMean = MeanMisclassified(sweep, *optimal);
    study.meanMisclassified.assign(study.methods.size(), {});
    for (int k : study.counts) {
        const SweepResult* r = &sweep;
        SweepResult extra;
        if (k != scene.partitions.count) {
            spatial::Scene atK = scene;
            atK.partitions.count = k;
            extra = RunSweep(atK, study.methods, sweep.lights, onLightDone, backend);
            r = &extra;
        }
        for (std::size_t m = 0; m < study.methods.size(); ++m)
            study.meanMisclassified[m].push_back(
                MeanMisclassified(*r, *IndexOf(r->methods, study.methods[m])));
    }
    return study;
}

}  // namespace lexel::cases
