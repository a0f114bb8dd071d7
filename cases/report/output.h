// Writing a command's --out files as one set: every file is written into a private staging
// directory with checked writes, verified, flushed to disk, and only then moved into place, so a
// run leaves all of its files or none of them, never deletes or damages a file it did not create,
// and leaves nothing behind when stopped by a signal.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

// What a command writes into --out, declared before it computes anything: the case files it
// reads (none of them may be replaced by an output) and the names of the files it writes.
struct OutputPlan {
    std::vector<std::filesystem::path> inputs;
    std::function<bool(const std::string& fileName)> isOutput;  // a plain file name in DIR
};

// One run's output files for `--out DIR`. Made before anything is computed, so a DIR that cannot
// take the files is refused at once; the command then writes every file into StagingDir() (text
// through WriteText, images by their writers at Staged(name)) and calls Commit() once all exist.
//
// Refused at construction (InputError "--out: <DIR>: <reason>", nothing created):
//  - an empty DIR, a path component longer than 255 bytes or a path too long for its files, a
//    symbolic link loop, a dangling link, a path through a regular file, DIR not a directory;
//  - an output that would replace one of plan.inputs (directories and links resolved);
//  - in an existing DIR: an output name that is a directory there, an old output whose version
//    cannot be kept for a rollback (link(2) refused: another user's file under Linux's
//    fs.protected_hardlinks, an immutable or append-only file), an old output in an append-only
//    DIR (chattr +a: it cannot be replaced), a DIR whose files cannot be created;
//  - a new DIR whose nearest existing parent is append-only (a failed run could not remove what
//    it made there).
//
// Guarantees:
//  - No two runs share a temporary name: each stages in its own directory (mkdtemp), named
//    `.lexel-staging-XXXXXX`, and holds an flock(2) on it for as long as it lives.
//  - Staging directories that killed runs left where this run stages (inside an existing DIR,
//    beside a new one) are removed first: those of this user that no live process holds locked.
//  - Commit() publishes nothing unless every staged file is complete and declared: text files are
//    written with checked write, fsync and close; PNG files must have the PNG signature and a
//    chunk sequence from IHDR to IEND that fills the file exactly; every file's name must pass
//    plan.isOutput (else std::logic_error: a command writing a file it did not declare).
//  - DIR absent before the run: the set is staged beside it and renamed into place in one step,
//    so DIR appears with all of its files or not at all.
//  - DIR already present (or made by another run meanwhile): the old version of every file to be
//    replaced is first kept as a hard link in the staging directory; if one cannot be kept,
//    nothing is replaced. Then each file replaces its old version by one rename; a failed rename
//    moves the published ones back (old versions restored, new names removed). Readers may see a
//    mix of old and new files while the renames run (milliseconds).
//  - SIGINT, SIGTERM, SIGHUP (with StopCleanlyOnSignals): the staging directory is removed; a
//    Commit in progress finishes first, so a signal never leaves a mix of old and new files.
//  - Destroyed without Commit() (an exception, a refused input): the staging directory and the
//    directories made for DIR's parents are removed; nothing is left behind.
// Only a process killed outright (SIGKILL, power loss) can leave its staging directory behind
// (the next run into DIR removes it) and, if killed during the renames into an existing DIR, a
// mix: the files renamed so far are new, the rest old, and the old versions of the replaced ones
// stay in `DIR/.lexel-staging-XXXXXX/.replaced/` until that next run.
class OutputSet {
  public:
    explicit OutputSet(const std::filesystem::path& outDir, OutputPlan plan);
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // Where the files are staged; a writer given a directory writes into this one.
    const std::filesystem::path& StagingDir() const { return stagingDir_; }
    // The staged path of the output named `fileName` (a plain file name the plan declares;
    // std::logic_error otherwise).
    std::filesystem::path Staged(const std::string& fileName) const;
    // Writes `content` as the staged file `fileName`: every write checked, then fsync and close.
    // Throws std::runtime_error "<DIR>/<fileName>: <reason>".
    void WriteText(const std::string& fileName, const std::string& content);
    // Runs `writer`, which writes files into StagingDir() (an image writer, say), and returns what
    // it returns; a std::runtime_error it throws names the final paths instead of the staged ones
    // (InputError and DomainError pass unchanged).
    template <class Writer>
    auto Writing(Writer&& writer) -> decltype(writer()) {
        try {
            return writer();
        } catch (const InputError&) {
            throw;
        } catch (const DomainError&) {
            throw;
        } catch (const std::runtime_error& e) {
            ThrowWithFinalNames(e.what());
        }
    }
    // Verifies every staged file, syncs it and moves the set into DIR (see the guarantees above).
    // Throws std::runtime_error "<DIR>/<file>: <reason>" and publishes nothing on failure.
    void Commit();

    const std::filesystem::path& OutDir() const { return outDir_; }

    struct Staging;  // the staging directory as the signal thread sees it (output.cpp)

  private:
    [[noreturn]] void ThrowWithFinalNames(const std::string& message) const;
    void CheckExistingOutputs(bool appendOnly) const;
    void ProbeBackups() const;
    void VerifyAndSync() const;
    void CommitWholeDirectory();
    void CommitFileByFile();

    std::filesystem::path outDir_;      // as given, without a trailing '/'
    std::filesystem::path stagingDir_;  // inside outDir_, or beside it (new or append-only DIR)
    OutputPlan plan_;
    bool wholeDirectory_ = false;  // outDir_ did not exist: stagingDir_ becomes it
    std::unique_ptr<Staging> staging_;
    std::map<std::string, std::uintmax_t> textSizes_;  // WriteText's files and their sizes
};

// Makes SIGINT, SIGTERM and SIGHUP (each unless ignored when the process started, as under nohup)
// stop the process cleanly: a thread of its own takes them, waits for a Commit in progress,
// removes every live OutputSet's staging directory, prints one line "lexel: error: interrupted by
// SIGTERM ..." and exits with status 128 + the signal's number. Call once, first thing in main,
// before any other thread starts: the signals are blocked in every thread made after it.
void StopCleanlyOnSignals();

// Why `bytes` are not a complete PNG image, or empty when they are one: the 8-byte signature,
// then chunks (4-byte length, 4-byte type, data, 4-byte CRC) from IHDR to IEND filling them
// exactly (PNG specification, 2nd ed., sections 5.2-5.3). The CRCs are not checked.
std::string PngBytesDefect(const std::string& bytes);

// A file beside an --out that this process holds open as `fd` under a shared flock and removes
// when it is the last holder (the empty journal a SweepExclusion holds): until ForgetOnSignal, a
// signal that StopCleanlyOnSignals takes removes it too, when `path` still names `fd`'s file, it
// is empty, and no other process holds it (an exclusive flock on `fd` is granted).
void RemoveOnSignal(const std::filesystem::path& path, int fd);
void ForgetOnSignal(const std::filesystem::path& path, int fd);

// Removes `path` when it still names the file open as `fd`, that file is empty, and no other
// process holds it (an exclusive flock on `fd` is granted): what the last holder of an empty
// journal does, on its own and on a signal.
void RemoveIfLastEmptyHolder(const std::filesystem::path& path, int fd);

}  // namespace lexel::cases
