// Sweeps that scale out: `lexel sweep --shard K/N` evaluates its share of the lights
// (light i belongs to shard i mod N; a light's numbers depend on that light alone), `--resume`
// skips the lights a killed run finished, and `lexel merge` joins the shares' records into the
// result of one whole sweep, bit for bit but for the times.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/report/spatial_report.h"
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

// What makes two runs parts of one sweep: the case (its name and the FNV-1a 64 hash of the case
// file's bytes), the methods in order, the backend, the partitioned methods' count, the sub-texel
// phases (at least and at most), the camera_path poses of the shimmer and the whole sweep's lights
// (their number and the hash of their shortest round-trip coordinates).
struct SweepIdentity {
    std::string caseName, caseHash;
    std::vector<std::string> methods;
    std::string backend;
    int cascades = 0;
    int phases = 1;        // Scene::phases
    int maxPhases = 1;     // max(Scene::phases, Scene::maxPhases)
    int shimmerPoses = 0;  // RunSweep's shimmerPoses
    std::size_t lights = 0;
    std::string lightsHash;
    bool operator==(const SweepIdentity&) const = default;
};
// FNV-1a 64 of `bytes` as 16 lower-case hex digits.
std::string Fnv1a64Hex(const std::string& bytes);
// The FNV-1a 64 of the lights' kinds and shortest round-trip coordinates.
std::string LightsHash(const std::vector<spatial::Light>& lights);
// The first field in which `a` and `b` differ, as "<field> (<a's> vs <b's>)"; empty when equal.
std::string IdentityDifference(const SweepIdentity& a, const SweepIdentity& b);

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

// A share's record (`sweep-record.json`, cases/README.md): everything a merge needs to write the
// same files as one whole sweep.
struct SweepRecord {
    SweepIdentity identity;
    SweepShard shard;
    double seconds = 0.0;                  // the share's wall time
    std::vector<SweepLightRecord> lights;  // increasing index
    std::vector<int> studyCounts;          // the study's extra counts; empty without the study
    StudyMisclassified study;              // [count][light][method], lights as `lights`
    // The first light's images when this share holds light 0 and the study ran (the files lie
    // beside the record).
    std::vector<SpatialImageFile> images;
};

// The record of `share` (and `study`, empty without one).
SweepRecord RecordOf(const SweepIdentity& identity, SweepShard shard, const SweepResult& share,
                     const std::vector<int>& studyCounts, const StudyMisclassified& study,
                     const std::vector<SpatialImageFile>& images);

// The whole sweep from shares' records (`sources[i]` names records[i] in errors): the lights in
// index order, seconds the sum of the shares' (the work's time), the study's extra sweeps joined
// likewise; `imagesFrom` is the index of the record holding light 0's images (or -1 when none).
// Throws InputError "merge: ..." when the records are of different sweeps (naming the field),
// when a light is in two of them or in none (naming it), or when they disagree on the study.
struct MergedSweep {
    SweepRecord record;  // shard 0/1
    SweepResult result;
    int imagesFrom = -1;
};
MergedSweep MergeRecords(const std::vector<SweepRecord>& records,
                         const std::vector<std::string>& sources);

// The share's result (SweepResult) rebuilt from a record: what RunSweepShare returned.
SweepResult ResultOf(const SweepRecord& record);

}  // namespace lexel::cases
