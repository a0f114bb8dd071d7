// The sweep record (`sweep-record.json`) and the resume journal's lines: every cell of
// a sweep's share losslessly (doubles in round-trip form, ±inf and NaN as the strings "inf",
// "-inf", "nan") with the sweep's identity, so that `lexel merge` rebuilds the whole sweep's
// files bit for bit. Layout in cases/README.md; read back by sweep_record_reader.h.
#pragma once

#include <string>

#include "lexel/cases/record/sweep_record.h"

namespace lexel::cases {

// The record's format tag and the names of a cell's fields, in the order of its array.
inline constexpr const char* kSweepRecordFormat = "lexel-sweep-record/5";
inline constexpr const char* kSweepJournalFormat = "lexel-sweep-journal/5";
inline constexpr const char* kSweepCellFields[] = {"misclassified",
                                                   "h",
                                                   "h_grazing",
                                                   "winner",
                                                   "footprint_mean",
                                                   "footprint_max",
                                                   "uncovered",
                                                   "cascades",
                                                   "empty_partitions",
                                                   "storage_factor",
                                                   "pages_requested",
                                                   "pages_resident",
                                                   "pages_dropped",
                                                   "lod_bias",
                                                   "misclassified_mean",
                                                   "misclassified_error",
                                                   "e",
                                                   "shimmer",
                                                   "storage_factor_p99",
                                                   "phases"};

// sweep-record.json: the identity and header fields one per line, then one line per light (its
// cells per method, their times apart in "ms", the study's counts per extra k).
std::string SweepRecordText(const SweepRecord& record);

// The journal's lines, each one JSON object and '\n': the header (the identity and the shard),
// a finished light, a finished light of the cascade-count study at one count.
std::string JournalHeaderLine(const SweepIdentity& identity, SweepShard shard);
std::string JournalLightLine(const SweepLightRecord& light);
std::string JournalStudyLine(const StudyLightRecord& light);

}  // namespace lexel::cases
