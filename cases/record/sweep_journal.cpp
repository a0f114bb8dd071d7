#include "lexel/cases/record/sweep_journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "lexel/cases/record/sweep_record_reader.h"
#include "lexel/cases/record/sweep_record_text.h"
#include "lexel/cases/report/output.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_file_check.h"

namespace lexel::cases {

namespace fs = std::filesystem;

namespace {

std::string ErrnoText(int error) { return std::strerror(error); }

// Writes all of `text` at the end of `fd` and syncs it; false with errno set on failure.
bool WriteSynced(int fd, const std::string& text) {
    const char* data = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ::ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            if (written == 0) errno = ENOSPC;
            return false;
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    return ::fdatasync(fd) == 0;
}

// Reads the regular file `fd` from its start, at most kMaxSweepJournalBytes (else InputError).
std::string ReadFd(int fd, const std::string& shown) {
    const auto tooLarge = [&] {
        return InputError(shown + ": larger than " + std::to_string(kMaxSweepJournalBytes) +
                          " bytes, the most a resume journal may be");
    };
    struct stat st {};
    if (::fstat(fd, &st) == 0 && static_cast<std::uintmax_t>(st.st_size) > kMaxSweepJournalBytes)
        throw tooLarge();
    std::string text;
    char buffer[1 << 16];
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
        const ::ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            const int reason = errno;
            throw std::runtime_error(shown + ": cannot read (" + ErrnoText(reason) + ")");
        }
        if (got == 0) break;
        if (text.size() + static_cast<std::size_t>(got) > kMaxSweepJournalBytes) throw tooLarge();
        text.append(buffer, static_cast<std::size_t>(got));
    }
    return text;
}

// The mode of what stands at the journal's path when it is not a regular file, found with lstat
// so that nothing there is opened; nullopt for a regular file or nothing.
std::optional<::mode_t> NotRegularAt(const fs::path& path) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return std::nullopt;
    return st.st_mode;
}

// Why a file of `mode` (NotRegularAt's) is no journal, in words ("is a symbolic link ...").
std::string NotAJournal(::mode_t mode) {
    if (S_ISLNK(mode))
        return "is a symbolic link (lexel opens no file beside --out through a link; remove it)";
    if (S_ISDIR(mode)) return "is a directory, not a resume journal (remove it)";
    return "is " + spatial::FileKind(mode) + ", not a resume journal";
}

// Whether open(2) failing with `reason` is the path's fault (exit 2, before computing) rather
// than the machine's (a full disk, too many open files: exit 1).
bool PathsFault(int reason) {
    for (const int path : {ELOOP, EISDIR, EACCES, EPERM, EROFS, ENOENT, ENOTDIR, ENAMETOOLONG})
        if (reason == path) return true;
    return false;
}

// True when `path` still names the file open as `fd` (no one removed or replaced it meanwhile).
bool StillNamed(int fd, const fs::path& path) {
    struct stat open {
    }, named{};
    return ::fstat(fd, &open) == 0 && ::lstat(path.c_str(), &named) == 0 &&
           open.st_dev == named.st_dev && open.st_ino == named.st_ino;
}

// Flocks `fd` with `operation` (LOCK_NB included), retrying on EINTR; errno set when false.
bool Flock(int fd, int operation) {
    int locked;
    do locked = ::flock(fd, operation);
    while (locked != 0 && errno == EINTR);
    return locked == 0;
}

// "--out: another lexel command ..." for a lock another process holds on `path`.
InputError HeldBy(const fs::path& path) {
    return InputError("--out: another lexel command writing into this directory is running (it " +
                      std::string("holds the resume journal ") + path.string() + ")");
}

// Refuses a journal line's entry (`one`: one light or one light of the study) for a light outside
// `shard` of `identity`'s lights, or for a count not among `studyCounts` (the partitions study's,
// CascadeStudyExtraCounts): a journal of this run holds none.
void CheckInShare(const SweepDone& one, const SweepIdentity& identity, SweepShard shard,
                  const std::vector<int>& studyCounts, const std::string& where) {
    const auto inShare = [&](std::size_t index) {
        return index < identity.lights && index % shard.count == shard.index;
    };
    const auto outside = [&](std::size_t index) {
        return InputError(where + ": light " + std::to_string(index) + " is not in this run's " +
                          "lights (shard " + ShardText(shard) + " of " +
                          std::to_string(identity.lights) + " lights): a damaged journal");
    };
    for (const auto& [index, light] : one.lights)
        if (!inShare(index)) throw outside(index);
    for (const auto& [key, light] : one.study) {
        if (!inShare(key.second)) throw outside(key.second);
        if (std::find(studyCounts.begin(), studyCounts.end(), key.first) == studyCounts.end())
            throw InputError(where + ": the partitions study has no count k = " +
                             std::to_string(key.first) + ": a damaged journal");
    }
}

}  // namespace

fs::path SweepJournal::PathFor(const fs::path& outDir) {
    fs::path dir = fs::absolute(outDir).lexically_normal();
    if (!dir.has_filename()) dir = dir.parent_path();
    if (!dir.has_filename()) return dir / ".lexel-sweep-journal";  // the root directory
    return dir.parent_path() / ("." + dir.filename().string() + ".lexel-sweep-journal");
}

SweepJournal::SweepJournal(const fs::path& path, const SweepIdentity& identity, SweepShard shard,
                           bool resume)
    : path_(path) {
    Open();
    try {
        const std::string header = JournalHeaderLine(identity, shard);
        const std::string text = resume ? ReadFd(fd_, "--resume: " + path_.string()) : "";
        if (text.find('\n') == std::string::npos) {  // none, or a header cut short by a kill
            created_ = true;                         // begun anew: this run's to remove
            StartAnew(header);
        } else {
            ReadFinished(text, identity, shard);
        }
    } catch (...) {
        // A journal of another sweep, or a damaged one, is left as it is.
        if (created_ && StillNamed(fd_, path_)) ::unlink(path_.c_str());
        ::close(std::exchange(fd_, -1));
        throw;
    }
}

// Opens (or creates) the journal as a regular file, never through a link nor blocking on a FIFO,
// and takes its exclusive lock; retried when another process removed the file meanwhile. A file
// this run made and could not lock is left to the holder of the lock, which removes it.
void SweepJournal::Open() {
    const std::string shown = "--out: " + path_.string() + ": ";
    for (int attempt = 0;; ++attempt) {
        if (const std::optional<::mode_t> mode = NotRegularAt(path_))
            throw InputError(shown + NotAJournal(*mode));
        fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        created_ = fd_ >= 0;
        int reason = errno;
        if (fd_ < 0 && reason == EEXIST) {
            fd_ = ::open(path_.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
            reason = errno;
            if (fd_ < 0 && reason == ENOENT && attempt < 8) continue;  // removed in between
        }
        if (fd_ < 0) {
            const std::optional<::mode_t> mode =
                reason == ELOOP ? NotRegularAt(path_) : std::nullopt;
            const std::string text =
                mode ? NotAJournal(*mode)
                     : "cannot create the resume journal (" + ErrnoText(reason) + ")";
            if (PathsFault(reason)) throw InputError(shown + text);
            throw std::runtime_error(path_.string() + ": " + text);
        }
        struct stat st {};
        if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {  // replaced after the lstat
            ::close(std::exchange(fd_, -1));
            throw InputError(shown + "is not a regular file, not a resume journal");
        }
        if (!Flock(fd_, LOCK_EX | LOCK_NB)) {
            const int reason = errno;
            ::close(std::exchange(fd_, -1));
            if (reason == EWOULDBLOCK) throw HeldBy(path_);
            throw std::runtime_error(path_.string() + ": cannot lock (" + ErrnoText(reason) + ")");
        }
        if (StillNamed(fd_, path_)) return;
        ::close(std::exchange(fd_, -1));  // removed by the run that held it: open it anew
        if (attempt == 8) throw HeldBy(path_);
    }
}

SweepJournal::~SweepJournal() {
    if (fd_ < 0) return;
    if (StillNamed(fd_, path_)) ::unlink(path_.c_str());
    ::close(fd_);
}

void SweepJournal::StartAnew(const std::string& header) {
    if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0 || !WriteSynced(fd_, header)) {
        const int reason = errno;
        throw std::runtime_error(path_.string() + ": cannot write the resume journal (" +
                                 ErrnoText(reason) + ")");
    }
    // The journal's name must outlive a power loss too.
    const fs::path dir = path_.parent_path();
    if (const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
}

void SweepJournal::ReadFinished(const std::string& text, const SweepIdentity& identity,
                                SweepShard shard) {
    const std::string shown = "--resume: " + path_.string();
    std::size_t end = text.find('\n');
    const JournalHeader header = ParseJournalHeader(text.substr(0, end), shown + ":1");
    std::string diff = IdentityDifference(header.identity, identity);
    if (diff.empty() && !(header.shard == shard))
        diff = "shard ('" + ShardText(header.shard) + "' vs '" + ShardText(shard) + "')";
    if (!diff.empty())
        throw InputError(shown + ": is the journal of another sweep: it differs from this run in " +
                         diff + "; run without --resume to start over");
    const std::size_t methods = identity.methods.size();
    const std::size_t studyMethods = CascadeStudyMethods(identity.methods).size();
    const std::vector<int> studyCounts = CascadeStudyExtraCounts(identity.cascades);
    std::size_t line = 1, kept = end + 1;
    for (std::size_t at = end + 1; at < text.size(); at = end + 1) {
        end = text.find('\n', at);
        ++line;
        if (end == std::string::npos) break;  // torn by a kill mid-write: dropped
        const std::string where = shown + ":" + std::to_string(line);
        SweepDone one;  // this line's entry, checked alone; a later line replaces an earlier one
        ParseJournalEntry(text.substr(at, end - at), where, methods, studyMethods, one);
        CheckInShare(one, identity, shard, studyCounts, where);
        for (auto& [index, light] : one.lights) done_.lights[index] = std::move(light);
        for (auto& [key, light] : one.study) done_.study[key] = std::move(light);
        kept = end + 1;
    }
    if (::ftruncate(fd_, static_cast<::off_t>(kept)) != 0 ||
        ::lseek(fd_, 0, SEEK_END) != static_cast<::off_t>(kept)) {
        const int reason = errno;
        throw std::runtime_error(path_.string() + ": cannot drop the journal's torn line (" +
                                 ErrnoText(reason) + ")");
    }
}

SweepExclusion::SweepExclusion(const fs::path& outDir) : path_(SweepJournal::PathFor(outDir)) {
    for (int attempt = 0; attempt <= 8; ++attempt) {
        if (const std::optional<::mode_t> mode = NotRegularAt(path_)) {
            if (S_ISLNK(*mode))
                throw InputError("--out: " + path_.string() + ": " + NotAJournal(*mode));
            return;  // a directory, a FIFO, ...: no sweep can journal here either
        }
        fd_ = ::open(path_.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd_ < 0 && errno == ENOENT)
            fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd_ < 0 && (errno == EEXIST || errno == ELOOP)) continue;  // changed meanwhile
        if (fd_ < 0) return;  // not creatable here (a missing or read-only parent): nor by a sweep
        struct stat st {};
        if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(std::exchange(fd_, -1));  // no sweep can journal here either
            return;
        }
        if (!Flock(fd_, LOCK_SH | LOCK_NB)) {
            const int reason = errno;
            ::close(std::exchange(fd_, -1));  // a file made here is the lock holder's to remove
            if (reason == EWOULDBLOCK) throw HeldBy(path_);
            return;  // a file system without locks
        }
        if (StillNamed(fd_, path_)) {
            try {
                RemoveOnSignal(path_, fd_);
            } catch (...) {
                ::close(std::exchange(fd_, -1));
                throw;
            }
            return;
        }
        ::close(std::exchange(fd_, -1));  // removed by its last holder meanwhile: open it anew
    }
    throw HeldBy(path_);
}

SweepExclusion::~SweepExclusion() {
    if (fd_ < 0) return;
    ForgetOnSignal(path_, fd_);
    RemoveIfLastEmptyHolder(path_, fd_);  // a sweep's journal, with lines, is kept
    ::close(fd_);
}

void SweepJournal::Append(const std::string& line) {
    const std::lock_guard lock(mutex_);
    if (!WriteSynced(fd_, line)) {
        const int reason = errno;
        throw std::runtime_error(path_.string() + ": cannot write the resume journal (" +
                                 ErrnoText(reason) + ")");
    }
}

}  // namespace lexel::cases
