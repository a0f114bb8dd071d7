// The partitioned methods against their number of partitions k at the same total texels (issue
// 14's study): mean misclassified pixels over a sweep's lights for k ∈ {1, 2, 4, 8}, with the
// single optimized map (`optimal`) as the reference line.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lexel/cases/run/sweep.h"

namespace lexel::cases {

struct CascadeCountStudy {
    std::vector<int> counts;                             // k, increasing
    std::vector<std::string> methods;                    // pssm, sdsm, sdsm-optimal (those run)
    std::vector<std::vector<double>> meanMisclassified;  // [method][count]
    std::optional<double> optimalMean;                   // optimal's, when the sweep ran it
};

// The methods the study covers among `methods`: pssm, sdsm and sdsm-optimal, in that order.
std::vector<std::string> CascadeStudyMethods(const std::vector<std::string>& methods);

// The counts k of the study for a sweep run at `sweepCount` partitions: 1, 2, 4, 8 and
// sweepCount, increasing; and those of them the study sweeps anew (all but sweepCount).
std::vector<int> CascadeStudyCounts(int sweepCount);
std::vector<int> CascadeStudyExtraCounts(int sweepCount);

// The study methods' misclassified pixels per extra count (CascadeStudyExtraCounts' order), light
// of the sweep and study method (CascadeStudyMethods' order): [count][light][method].
using StudyMisclassified = std::vector<std::vector<std::vector<double>>>;

// The study from `sweep` (run at `sweepCount`) and the extra counts' sweeps: the means are taken
// over the lights in their order, so equal inputs give equal bits.
CascadeCountStudy CascadeStudyOf(const SweepResult& sweep, int sweepCount,
                                 const StudyMisclassified& extra);

// Reuses `sweep` (run at scene.partitions.count) and sweeps the study's methods at the other
// counts over the same lights on `backend`; `onLightDone` after each light of each extra sweep.
// Throws as RunSweep.
CascadeCountStudy RunCascadeCountStudy(const spatial::Scene& scene, const SweepResult& sweep,
                                       const SweepLightDone& onLightDone = {},
                                       BackendKind backend = BackendKind::kCpu);

}  // namespace lexel::cases
