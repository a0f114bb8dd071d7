#include "lexel/cases/report/sweep_journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lexel/cases/load/sweep_record_reader.h"
#include "lexel/cases/report/sweep_record.h"
#include "lexel/solvers/errors.h"

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

std::string ReadFd(int fd) {
    std::string text;
    char buffer[1 << 16];
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
        const ::ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        text.append(buffer, static_cast<std::size_t>(got));
    }
    return text;
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
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0)
        throw std::runtime_error(path_.string() + ": cannot create the resume journal (" +
                                 ErrnoText(errno) + ")");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int reason = errno;
        ::close(fd_);
        fd_ = -1;
        if (reason == EWOULDBLOCK)
            throw InputError(
                "--out: another lexel sweep into this directory is running (it "
                "holds the resume journal " +
                path_.string() + ")");
        throw std::runtime_error(path_.string() + ": cannot lock (" + ErrnoText(reason) + ")");
    }
    const std::string header = JournalHeaderLine(identity, shard);
    try {
        const std::string text = resume ? ReadFd(fd_) : std::string();
        if (text.find('\n') == std::string::npos)  // none, or a header cut short by a kill
            StartAnew(header);
        else
            ReadFinished(text, identity, shard);
    } catch (...) {
        ::close(fd_);  // a journal of another sweep, or a damaged one, is left as it is
        fd_ = -1;
        throw;
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
        ParseJournalEntry(text.substr(at, end - at), shown + ":" + std::to_string(line), methods,
                          studyMethods, done_);
        kept = end + 1;
    }
    if (::ftruncate(fd_, static_cast<::off_t>(kept)) != 0 ||
        ::lseek(fd_, 0, SEEK_END) != static_cast<::off_t>(kept))
        throw std::runtime_error(path_.string() + ": cannot drop the journal's torn line (" +
                                 ErrnoText(errno) + ")");
}

void SweepJournal::Append(const std::string& line) {
    const std::lock_guard lock(mutex_);
    if (!WriteSynced(fd_, line))
        throw std::runtime_error(path_.string() + ": cannot write the resume journal (" +
                                 ErrnoText(errno) + ")");
}

}  // namespace lexel::cases
