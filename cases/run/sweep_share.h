// Sweeps that scale out: `lexel sweep --shard K/N` evaluates its share of the lights
// (light i belongs to shard i mod N; a light's numbers depend on that light alone), and
// `--resume` skips the lights a killed run finished. The share's record, its journal and the
// merge of records are cases/record/.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/run/backend.h"
#include "lexel/cases/run/cascade_study.h"
#include "lexel/cases/run/sweep.h"

namespace lexel::cases {

// Shard K of N: the lights i with i mod N = K. The whole sweep is 0/1.
struct SweepShard {
    std::size_t index = 0;  // K, 0 ≤ K < N
    std::size_t count = 1;  // N ≥ 1
    bool operator==(const SweepShard&) const = default;
};
std::string ShardText(SweepShard shard);  // "K/N"

// The indices of shard `shard`'s lights among `lights`, increasing.
std::vector<std::size_t> ShardLights(std::size_t lights, SweepShard shard);

// One evaluated light as a share keeps it: in its journal, its record, a merge.
struct SweepLightRecord {
    std::size_t index = 0;  // in the whole sweep
    spatial::Light light;
    std::int64_t receiverPixels = 0;
    std::vector<SweepCell> cells;  // per method
};

// One light of the cascade-count study at one of its extra counts (CascadeStudyExtraCounts).
struct StudyLightRecord {
    int count = 0;
    std::size_t index = 0;              // the light's, in the whole sweep
    std::vector<double> misclassified;  // per study method (CascadeStudyMethods): phase means
};

// The lights a killed run finished (its journal).
struct SweepDone {
    std::map<std::size_t, SweepLightRecord> lights;
    std::map<std::pair<int, std::size_t>, StudyLightRecord> study;  // by (count, index)
};

// Evaluates the lights `indices` of `allLights` that `done` lacks (RunSweep), calling
// `onLightDone` (any thread) with each new one, and returns the share's result: done and new
// lights in the order of `indices`, r.indices their indices in the whole sweep, r.seconds this
// run's wall time. `shimmerPoses` as RunSweep's. Throws as RunSweep.
SweepResult RunSweepShare(const spatial::Scene& scene, const std::vector<std::string>& methods,
                          const std::vector<spatial::Light>& allLights,
                          const std::vector<std::size_t>& indices, const SweepDone& done,
                          const std::function<void(const SweepLightRecord&)>& onLightDone,
                          BackendKind backend, int shimmerPoses = 0);

// The cascade-count study's extra sweeps over `share`'s lights (RunCascadeCountStudy), skipping
// those in `done`; `onLightDone` after each new light (any thread). Returns [count][light][method]
// for CascadeStudyExtraCounts(scene.partitions.count) and the share's lights in order.
StudyMisclassified RunStudyShare(const spatial::Scene& scene, const SweepResult& share,
                                 const SweepDone& done,
                                 const std::function<void(const StudyLightRecord&)>& onLightDone,
                                 BackendKind backend);

}  // namespace lexel::cases
