#include "lexel/cases/report/sweep_journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "lexel/cases/load/sweep_record_reader.h"
#include "lexel/cases/report/output.h"
#include "lexel/cases/report/sweep_record.h"
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
        if (got < 0) throw std::runtime_error(shown + ": cannot read (" + ErrnoText(errno) + ")");
        if (got == 0) break;
        if (text.size() + static_cast<std::size_t>(got) > kMaxSweepJournalBytes) throw tooLarge();
        text.append(buffer, static_cast<std::size_t>(got));
    }
    return text;
}

// Why the journal's path cannot be opened, in words ("is a symbolic link ...").
std::string OpenRefusal(int reason) {
    if (reason == ELOOP)
        return "is a symbolic link (lexel opens no file beside --out through a link; remove it)";
    if (reason == EISDIR) return "is a directory, not a resume journal (remove it)";
    return "cannot create the resume journal (" + ErrnoText(reason) + ")";
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
    const std::string header = JournalHeaderLine(identity, shard);
    try {
        const std::string text = resume ? ReadFd(fd_, "--resume: " + path_.string()) : "";
        if (text.find('\n') == std::string::npos) {  // none, or a header cut short by a kill
            created_ = true;                         // begun anew: this run's to remove
            StartAnew(header);
        } else {
            ReadFinished(text, identity, shard);
        }
    } catch (...) {
        // A journal of another sweep, or a damaged one, is left as it is.
        if (created_) ::unlink(path_.c_str());
        ::close(fd_);
        fd_ = -1;
        throw;
    }
}

// Opens (or creates) the journal as a regular file, never through a link nor blocking on a FIFO,
// and takes its exclusive lock; retried when another process removed the file meanwhile.
void SweepJournal::Open() {
    const std::string shown = "--out: " + path_.string() + ": ";
    for (int attempt = 0;; ++attempt) {
        fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        created_ = fd_ >= 0;
        if (fd_ < 0 && errno == EEXIST)
            fd_ = ::open(path_.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd_ < 0) throw InputError(shown + OpenRefusal(errno));
        struct stat st {};
        if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(std::exchange(fd_, -1));
            throw InputError(shown + "is " + spatial::FileKind(st.st_mode) +
                             ", not a resume journal");
        }
        if (!Flock(fd_, LOCK_EX | LOCK_NB)) {
            const int reason = errno;
            if (created_) ::unlink(path_.c_str());
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
    ::unlink(path_.c_str());
    ::close(fd_);
}

void SweepJournal::StartAnew(const std::string& header) {
    if (::ftruncate(fd_, 0) != 0 || ::lseek(fd_, 0, SEEK_SET) != 0 || !WriteSynced(fd_, header))
        throw std::runtime_error(path_.string() + ": cannot write the resume journal (" +
                                 ErrnoText(errno) + ")");
    // The journal's name must outlive a power loss too.
    const fs::path dir = path_.parent_path();
    if (const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dirFd >= 0) {
        ::fsync(dirFd);
        ::close(dirFd);
    }
}

// Refuses a journal line for a light outside `shard` of `identity`'s lights, or for a count the
// partitions study does not sweep: a journal of this run holds none.
void CheckInShare(const SweepDone& done, const SweepIdentity& identity, SweepShard shard,
                  const std::string& where) {
    const auto inShare = [&](std::size_t index) {
        return index < identity.lights && index % shard.count == shard.index;
    };
    const auto outside = [&](std::size_t index) {
        return InputError(where + ": light " + std::to_string(index) + " is not in this run's " +
                          "lights (shard " + ShardText(shard) + " of " +
                          std::to_string(identity.lights) + " lights): a damaged journal");
    };
    for (const auto& [index, light] : done.lights)
        if (!inShare(index)) throw outside(index);
    const std::vector<int> counts = CascadeStudyExtraCounts(identity.cascades);
    for (const auto& [key, light] : done.study) {
        if (!inShare(key.second)) throw outside(key.second);
        if (std::find(counts.begin(), counts.end(), key.first) == counts.end())
            throw InputError(where + ": the partitions study has no count k = " +
                             std::to_string(key.first) + ": a damaged journal");
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
    std::size_t line = 1, kept = end + 1;
    for (std::size_t at = end + 1; at < text.size(); at = end + 1) {
        end = text.find('\n', at);
        ++line;
        if (end == std::string::npos) break;  // torn by a kill mid-write: dropped
        const std::string where = shown + ":" + std::to_string(line);
        ParseJournalEntry(text.substr(at, end - at), where, methods, studyMethods, done_);
        CheckInShare(done_, identity, shard, where);
        kept = end + 1;
    }
    if (::ftruncate(fd_, static_cast<::off_t>(kept)) != 0 ||
        ::lseek(fd_, 0, SEEK_END) != static_cast<::off_t>(kept))
        throw std::runtime_error(path_.string() + ": cannot drop the journal's torn line (" +
                                 ErrnoText(errno) + ")");
}

SweepExclusion::SweepExclusion(const fs::path& outDir) : path_(SweepJournal::PathFor(outDir)) {
    for (int attempt = 0; attempt <= 8; ++attempt) {
        fd_ = ::open(path_.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        created_ = false;
        if (fd_ < 0 && errno == ENOENT) {
            fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
            created_ = fd_ >= 0;
        }
        if (fd_ < 0 && errno == EEXIST) continue;  // made by another run meanwhile
        if (fd_ < 0 && errno == ELOOP)
            throw InputError("--out: " + path_.string() + ": " + OpenRefusal(ELOOP));
        if (fd_ < 0) return;  // not creatable here: no sweep can journal here either
        struct stat st {};
        if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
            ::close(std::exchange(fd_, -1));  // no sweep can journal here either
            return;
        }
        if (!Flock(fd_, LOCK_SH | LOCK_NB)) {
            const int reason = errno;
            if (created_) ::unlink(path_.c_str());
            ::close(std::exchange(fd_, -1));
            if (reason == EWOULDBLOCK) throw HeldBy(path_);
            return;  // a file system without locks
        }
        if (StillNamed(fd_, path_)) {
            if (created_) RemoveOnSignal(path_);
            return;
        }
        ::close(std::exchange(fd_, -1));  // removed by its last holder meanwhile: open it anew
    }
    throw HeldBy(path_);
}

SweepExclusion::~SweepExclusion() {
    if (fd_ < 0) return;
    if (created_) ForgetOnSignal(path_);
    struct stat st {};
    // The last holder of an empty journal removes it (a sweep's journal, with lines, is kept).
    if (Flock(fd_, LOCK_EX | LOCK_NB) && ::fstat(fd_, &st) == 0 && st.st_size == 0 &&
        StillNamed(fd_, path_))
        ::unlink(path_.c_str());
    ::close(fd_);
}

void SweepJournal::Append(const std::string& line) {
    const std::lock_guard lock(mutex_);
    if (!WriteSynced(fd_, line))
        throw std::runtime_error(path_.string() + ": cannot write the resume journal (" +
                                 ErrnoText(errno) + ")");
}

}  // namespace lexel::cases
