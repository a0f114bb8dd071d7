// The resume journal of `lexel sweep --out DIR` (issue 28, `--resume`): each finished light is
// appended as one line and synced to disk (write, fdatasync) as it completes, so that a run
// killed outright (SIGKILL, power loss, a batch system's preemption) can be continued from the
// lights it finished. The journal lies beside DIR as `.<DIR's name>.lexel-sweep-journal` (so
// DIR still appears with all of its files or none; OutputSet's cleanup of killed runs' staging
// never touches it), is locked (flock) while a run uses it, and is removed when the run ends
// without being killed: committed, or failed with its one-line error. A run stopped by SIGINT,
// SIGTERM or SIGHUP (StopCleanlyOnSignals), or killed, leaves it for `--resume`.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>

#include "lexel/cases/run/sweep_share.h"

namespace lexel::cases {

class SweepJournal {
  public:
    // Where the journal of `outDir` lies: `<parent>/.<name>.lexel-sweep-journal`.
    static std::filesystem::path PathFor(const std::filesystem::path& outDir);

    // Opens or creates the journal at `path` for a run of `identity` and `shard`, holding an
    // exclusive flock on it. With `resume`, the lights a former run finished are read (a torn
    // last line, as a kill mid-write leaves, is dropped) and kept; without, or when there is no
    // journal, it starts anew. Throws InputError "--resume: <path>: ..." for a journal of another
    // sweep (naming what differs) or a damaged line, "--out: ..." when another run holds the
    // lock, std::runtime_error when it cannot be created or written.
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
    void StartAnew(const std::string& header);
    void ReadFinished(const std::string& text, const SweepIdentity& identity, SweepShard shard);

    std::filesystem::path path_;
    int fd_ = -1;
    std::mutex mutex_;
    SweepDone done_;
};

}  // namespace lexel::cases
