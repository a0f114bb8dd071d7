// Writing a command's --out files as one set: every file is written into a private staging
// directory with checked writes, verified, flushed to disk, and only then moved into place, so a
// run leaves all of its files or none of them (issue 16, "atomic output, really").
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

// One run's output files for `--out DIR`. Made before anything is computed, so a DIR that cannot
// take files is refused at once; the command then writes every file into StagingDir() (text
// through WriteText, images by their writers at Staged(name)) and calls Commit() once all exist.
//
// Guarantees:
//  - No two runs share a temporary name: each stages in its own directory (mkdtemp).
//  - Commit() publishes nothing unless every staged file is complete: text files are written with
//    checked write, fsync and close; PNG files must have the PNG signature and a chunk sequence
//    from IHDR to IEND that fills the file exactly (a 0-byte or truncated image is refused).
//  - DIR absent before the run: the set is staged beside it and renamed into place in one step,
//    so DIR appears with all of its files or not at all.
//  - DIR already present: each file replaces its old version by one rename, after all files are
//    staged complete; a failed rename moves the already published ones back (their old versions
//    were kept as hard links) or removes them. Readers may see a mix of old and new files while
//    the renames run, and a crash in that window leaves such a mix.
//  - Destroyed without Commit() (an exception, a refused input): the staging directory and the
//    directories made for DIR's parents are removed; nothing is left behind.
// A process killed outright (SIGKILL, power loss) can leave its staging directory, named
// `.lexel-staging-XXXXXX`, beside or inside DIR.
class OutputSet {
  public:
    // Throws InputError "--out: <DIR>: <reason>" when DIR is not a directory or no file can be
    // created there (a path through a regular file, a read-only file system, no permission).
    explicit OutputSet(const std::filesystem::path& outDir);
    ~OutputSet();
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;

    // Where the files are staged; a writer given a directory writes into this one.
    const std::filesystem::path& StagingDir() const { return stagingDir_; }
    // The staged path of the output named `fileName` (a plain file name, no directories).
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

  private:
    [[noreturn]] void ThrowWithFinalNames(const std::string& message) const;
    void VerifyAndSync() const;
    void CommitWholeDirectory();
    void CommitFileByFile();

    std::filesystem::path outDir_;      // as given, without a trailing '/'
    std::filesystem::path stagingDir_;  // inside outDir_, or beside it when it did not exist
    std::filesystem::path createdTop_;  // the topmost parent directory this run created, if any
    bool wholeDirectory_ = false;       // outDir_ did not exist: stagingDir_ becomes it
    bool committed_ = false;
    std::map<std::string, std::uintmax_t> textSizes_;  // WriteText's files and their sizes
};

}  // namespace lexel::cases
