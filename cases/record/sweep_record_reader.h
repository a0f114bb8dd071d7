// Reading back what sweep_record_text.h writes: a share's `sweep-record.json` (for
// `lexel merge`) and the lines of a sweep's resume journal (for `lexel sweep --resume`). Strict
// like the case loader: a field that is missing, of the wrong type or out of range is an
// InputError "<source>: <JSON pointer>: <reason>".
#pragma once

#include <filesystem>
#include <string>

#include "lexel/cases/record/sweep_record.h"

namespace lexel::cases {

// The largest record read (bytes): about 5 KiB per light of 25 methods.
inline constexpr std::size_t kMaxSweepRecordBytes = std::size_t{1} << 30;

// Reads `<dir>/sweep-record.json`. Throws InputError naming the file (a missing one: "...: not
// found (is <dir> the --out directory of a lexel sweep?)").
SweepRecord ReadSweepRecord(const std::filesystem::path& dir);
// The same from the record's text; `source` names it in errors.
SweepRecord ParseSweepRecord(const std::string& text, const std::string& source);

// A journal's first line: the identity and shard of the run that wrote it.
struct JournalHeader {
    SweepIdentity identity;
    SweepShard shard;
};
JournalHeader ParseJournalHeader(const std::string& line, const std::string& source);

// A later line: a finished light (into done.lights) or a finished light of the study (into
// done.study). `methods` and `studyMethods` are the cells' counts the identity implies.
void ParseJournalEntry(const std::string& line, const std::string& source, std::size_t methods,
                       std::size_t studyMethods, SweepDone& done);

}  // namespace lexel::cases
