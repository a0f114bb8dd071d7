// libFuzzer target: what `lexel merge` and `lexel sweep --resume` read back (cases/load/
// sweep_record_reader.h): the bytes as a sweep record (ParseSweepRecord, then MergeRecords as a
// one-shard merge), and line by line as a resume journal (ParseJournalHeader on the first line,
// ParseJournalEntry on the rest with the counts its identity implies). A bad input must be
// refused with an InputError of one line; any other exception, a crash, a sanitizer report or a
// hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "lexel/cases/record/sweep_record.h"
#include "lexel/cases/record/sweep_record_reader.h"
#include "lexel/cases/run/sweep_share.h"
#include "lexel/solvers/errors.h"

namespace {

void AsRecord(const std::string& text) {
    try {
        const lexel::cases::SweepRecord record =
            lexel::cases::ParseSweepRecord(text, "sweep-record.json");
        lexel::cases::MergeRecords({record}, {"shard"});
    } catch (const lexel::InputError& e) {
        lexel::fuzz::CheckRefusalMessage(e);
    }
}

void AsJournal(const std::string& text) {
    try {
        std::size_t end = text.find('\n');
        const lexel::cases::JournalHeader header =
            lexel::cases::ParseJournalHeader(text.substr(0, end), "journal:1");
        const std::size_t methods = header.identity.methods.size();
        const std::size_t studyMethods =
            lexel::cases::CascadeStudyMethods(header.identity.methods).size();
        lexel::cases::SweepDone done;
        for (std::size_t line = 2; end != std::string::npos; ++line) {
            const std::size_t at = end + 1;
            end = text.find('\n', at);
            if (end == std::string::npos) break;  // a torn last line is dropped
            lexel::cases::ParseJournalEntry(text.substr(at, end - at),
                                            "journal:" + std::to_string(line), methods,
                                            studyMethods, done);
        }
    } catch (const lexel::InputError& e) {
        lexel::fuzz::CheckRefusalMessage(e);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    AsRecord(text);
    AsJournal(text);
    return 0;
}
