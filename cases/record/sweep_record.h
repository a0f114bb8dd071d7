// A sweep share's record (`sweep-record.json`, cases/README.md): the sweep's identity, the
// share's lights cell by cell and its cascade-count study, from which `lexel merge` joins the
// shares into the result of one whole sweep, bit for bit but for the times. Its text form is
// sweep_record_text.h, read back by sweep_record_reader.h; the resume journal is sweep_journal.h.
#pragma once

#include <string>
#include <vector>

#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/run/sweep_share.h"

namespace lexel::cases {

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
