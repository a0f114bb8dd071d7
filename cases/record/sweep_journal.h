// The resume journal of `lexel sweep --out DIR`: each finished light is
// appended as one line and synced to disk (write, fdatasync) as it completes, so that a run
// killed outright (SIGKILL, power loss, a batch system's preemption) can be continued from the
// lights it finished. The journal lies beside DIR as `.<DIR's name>.lexel-sweep-journal` (so
// DIR still appears with all of its files or none; OutputSet's cleanup of killed runs' staging
// never touches it), is locked (flock) while a run uses it, and is removed when the run ends
// without being killed: committed, or failed with its one-line error. A run stopped by SIGINT,
// SIGTERM or SIGHUP (StopCleanlyOnSignals), or killed, leaves it for `--resume`.
//
// The journal is opened as the output set opens its files: never through a symbolic link, only
// a regular file (a FIFO, a device or a directory at its path is refused without blocking), and
// read up to kMaxSweepJournalBytes. Every refusal found before computing is an InputError.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>

#include "lexel/cases/record/sweep_record.h"

namespace lexel::cases {

// The largest journal `--resume` reads (bytes): a journal holds what the record holds, one line a
// light, so the record's cap (kMaxSweepRecordBytes) bounds it too.
inline constexpr std::size_t kMaxSweepJournalBytes = std::size_t{1} << 30;

class SweepJournal {
  public:
    // Where the journal of `outDir` lies: `<parent>/.<name>.lexel-sweep-journal`.
    static std::filesystem::path PathFor(const std::filesystem::path& outDir);

    // Opens or creates the journal at `path` for a run of `identity` and `shard`, holding an
    // exclusive flock on it. With `resume`, the lights a former run finished are read (a torn
    // last line, as a kill mid-write leaves, is dropped) and kept; without, or when there is no
    // journal, it starts anew. Throws InputError "--resume: <path>: ..." for a journal of another
    // sweep (naming what differs), a damaged line, a line for a light outside this shard, or a
    // journal larger than kMaxSweepJournalBytes; "--out: <path>: ..." when another run holds the
    // lock, the path is a link, a directory or another kind of file that is not a regular one
    // (found with lstat: nothing there is opened), or it cannot be created (a read-only or missing
    // parent); std::runtime_error when the machine fails it (a full disk, too many open files).
    // A journal this constructor created or began anew is removed when it throws.
    SweepJournal(const std::filesystem::path& path, const SweepIdentity& identity, SweepShard shard,
                 bool resume);
    ~SweepJournal();  // removes the journal (a killed process never gets here)
    SweepJournal(const SweepJournal&) = delete;
    SweepJournal& operator=(const SweepJournal&) = delete;

    const SweepDone& Done() const { return done_; }
    const std::filesystem::path& Path() const { return path_; }

    // Appends `line` (one JSON object and '\n') and syncs it; from any thread. Throws
    // std::runtime_error "<path>: <reason>".
    void Append(const std::string& line);

  private:
    void Open();
    void StartAnew(const std::string& header);
    void ReadFinished(const std::string& text, const SweepIdentity& identity, SweepShard shard);

    std::filesystem::path path_;
    int fd_ = -1;
    bool created_ = false;  // this run made the file (or began it anew): removed if it fails
    std::mutex mutex_;
    SweepDone done_;
};

// What `lexel run`, `merge` and `storage` hold while they write into `--out DIR`, so that they and
// a sweep into DIR never run at once: refuses (InputError "--out: ...") while a sweep holds DIR's
// journal, and holds a shared lock on the journal's path for as long as it lives, so that a sweep
// into DIR started meanwhile is refused. Where there is no journal it makes an empty one to hold
// (removed again by the last holder, on SIGINT, SIGTERM and SIGHUP too; a command killed outright
// leaves it, and a sweep takes an empty journal for none). Where none can be made (a read-only
// parent) or the path holds something other than a regular file or a link, no sweep can journal
// there either, and nothing is held; a link there is refused (InputError). Make it after the
// OutputSet, which makes --out's missing parents, and destroy it before.
class SweepExclusion {
  public:
    explicit SweepExclusion(const std::filesystem::path& outDir);
    ~SweepExclusion();
    SweepExclusion(const SweepExclusion&) = delete;
    SweepExclusion& operator=(const SweepExclusion&) = delete;

  private:
    std::filesystem::path path_;
    int fd_ = -1;
};

}  // namespace lexel::cases
