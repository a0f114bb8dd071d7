#include "lexel/cases/report/output.h"

#include <fcntl.h>
#include <linux/fs.h>
#include <pthread.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

namespace lexel::cases {

namespace fs = std::filesystem;

namespace {

std::string ErrnoText(int error) { return std::strerror(error); }

// "results/" and "results" name one directory; the staging and the final rename need its name.
fs::path WithoutTrailingSeparator(fs::path path) {
    while (!path.empty() && !path.has_filename() && path != path.root_path())
        path = path.parent_path();
    return path;
}

// The topmost missing directory on the way to `dir` (empty when `dir` exists).
fs::path TopmostMissing(const fs::path& dir) {
    fs::path top;
    std::error_code error;
    for (fs::path p = dir; !p.empty() && !fs::exists(fs::symlink_status(p, error));
         p = p.parent_path()) {
        top = p;
        if (p == p.parent_path()) break;
    }
    return top;
}

// Removes `dir` and its parents up to and including `top`, each only while it is empty: what a
// failed run created for --out, and nothing another process has put there since.
void RemoveEmptyChain(fs::path dir, const fs::path& top) {
    if (top.empty()) return;
    std::error_code error;
    for (;;) {
        if (!fs::remove(dir, error) || error) return;
        if (dir == top || dir == dir.parent_path()) return;
        dir = dir.parent_path();
    }
}

// fsync of a file or directory by path. Directories: best effort (some file systems refuse it
// with EINVAL, and the renames are done by then).
bool SyncPath(const fs::path& path, bool directory) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0;
    return ::close(fd) == 0 && synced;
}

std::uint32_t BigEndian32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i)
        value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
    return value;
}

std::string PngDefect(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) return "cannot be read back";
    return PngBytesDefect(bytes);
}

// The process's umask, read without changing it (umask(2) can only set it, which would race with
// other threads); 022 where /proc does not say.
::mode_t ProcessUmask() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.starts_with("Umask:"))
            return static_cast<::mode_t>(std::stoul(line.substr(6), nullptr, 8));
    return 022;
}

// The regular files in `dir`, sorted by name.
std::vector<std::string> StagedFiles(const fs::path& dir) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The staging directories' name: lexel removes only what carries it (and is its user's, and no
// live process holds locked).
constexpr std::string_view kStagingPrefix = ".lexel-staging-";
// A staging directory whose rollback could not restore every old version is renamed to this
// prefix, so that no later run removes the old versions it keeps.
constexpr std::string_view kKeptPrefix = ".lexel-kept-";
// A staging directory's name (this run's, another's, or a kept one): never an output's.
bool IsLexelDirectory(const std::string& name) {
    return name.starts_with(kStagingPrefix) || name.starts_with(kKeptPrefix);
}
// The longest file name (NAME_MAX: ext4, xfs, btrfs, tmpfs) and path (PATH_MAX without its NUL)
// the kernel takes, in bytes.
constexpr std::size_t kMaxNameBytes = NAME_MAX, kMaxPathBytes = PATH_MAX - 1;
// The most a staged file's path adds to DIR's: "/.lexel-staging-XXXXXX/.replaced/<name>".
constexpr std::size_t kStagedSuffixBytes = 1 + 21 + 11 + kMaxNameBytes;

// Why `dir` cannot be --out's path, before the file system is asked, or empty: a component no
// file system takes, or a path that with its files' names passes what a system call takes.
std::string PathLengthProblem(const fs::path& dir) {
    for (const fs::path& part : dir)
        if (part.native().size() > kMaxNameBytes)
            return "a path component is " + std::to_string(part.native().size()) +
                   " bytes; a file name has at most " + std::to_string(kMaxNameBytes);
    std::error_code error;
    const std::size_t bytes = fs::absolute(dir, error).native().size();
    if (bytes + kStagedSuffixBytes > kMaxPathBytes)
        return "the path is " + std::to_string(bytes) + " bytes; with its files' names it would " +
               "pass the " + std::to_string(kMaxPathBytes) + " bytes a path may have";
    return {};
}

// Whether `dir` exists as a directory (through links). Throws InputError `shown` + the reason
// for a symbolic link loop, a dangling link, or anything else that is not a directory. A path
// through a regular file counts as absent here; creating it reports that.
bool ExistingDirectory(const fs::path& dir, const std::string& shown) {
    struct stat st {};
    if (::lstat(dir.c_str(), &st) != 0) {
        const int reason = errno;
        if (reason == ENOENT || reason == ENOTDIR) return false;
        if (reason == ELOOP) throw InputError(shown + "a symbolic link loop on the way");
        throw InputError(shown + "cannot be examined (" + ErrnoText(reason) + ")");
    }
    if (S_ISLNK(st.st_mode) && ::stat(dir.c_str(), &st) != 0) {
        const int reason = errno;
        std::error_code error;
        const std::string target = fs::read_symlink(dir, error).string();
        if (reason == ELOOP) throw InputError(shown + "a symbolic link loop");
        if (reason == ENOENT)
            throw InputError(shown + "a dangling symbolic link (to " + target +
                             ", which does not exist)");
        throw InputError(shown + "a symbolic link that cannot be followed (" + ErrnoText(reason) +
                         ")");
    }
    if (!S_ISDIR(st.st_mode)) throw InputError(shown + "not a directory");
    return true;
}

// Whether the directory carries the append-only attribute (chattr +a): files can be made in it
// but none removed, renamed away or replaced. False where the file system has no attributes.
bool IsAppendOnly(const fs::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return false;
    int flags = 0;
    const bool appendOnly = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0 && (flags & FS_APPEND_FL);
    ::close(fd);
    return appendOnly;
}

// An exclusive flock(2) on a directory, held while this lives (or handed over by Release).
// Not held where the file system refuses locks (then nothing relies on it: see RemoveDebris).
// `wait`: block until it is free; else give up at once. `follow`: lock what a link names.
class DirectoryLock {
  public:
    DirectoryLock(const fs::path& dir, bool wait, bool follow = false)
        : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | (follow ? 0 : O_NOFOLLOW))) {
        int locked;
        do locked = ::flock(fd_, LOCK_EX | (wait ? 0 : LOCK_NB));
        while (locked != 0 && errno == EINTR);
        if (fd_ >= 0 && locked != 0) ::close(std::exchange(fd_, -1));
    }
    ~DirectoryLock() {
        if (fd_ >= 0) ::close(fd_);
    }
    DirectoryLock(const DirectoryLock&) = delete;
    DirectoryLock& operator=(const DirectoryLock&) = delete;
    bool Held() const { return fd_ >= 0; }
    int Release() { return std::exchange(fd_, -1); }

  private:
    int fd_;
};

// Removes the staging directories that killed runs left in `dir`: real directories named
// kStagingPrefix..., this user's, that no process holds locked (a run locks its own from the
// moment it makes it until it removes it; the kernel drops the lock of a dead process). The
// caller holds `dir`'s lock, which every run holds while it makes and locks its own, so none is
// caught between the two.
void RemoveDebris(const fs::path& dir) {
    std::vector<fs::path> candidates;
    std::error_code error;
    for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
        if (it->path().filename().native().starts_with(kStagingPrefix))
            candidates.push_back(it->path());
    for (const fs::path& candidate : candidates) {
        struct stat st {};
        if (::lstat(candidate.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) ||
            st.st_uid != ::geteuid())
            continue;
        const DirectoryLock lock(candidate, false);
        if (lock.Held()) fs::remove_all(candidate, error);
    }
}

// Guards the live staging directories: a signal's cleanup and every change to them (making,
// removing, publishing) hold it, so a signal waits for a Commit in progress.
// Never destroyed: the signal thread may take them while the process exits.
std::mutex& LiveMutex() {
    static auto* mutex = new std::mutex;
    return *mutex;
}
std::vector<OutputSet::Staging*>& LiveStagings() {
    static auto* live = new std::vector<OutputSet::Staging*>;
    return *live;
}
// RemoveOnSignal's files and their descriptors, under LiveMutex.
std::vector<std::pair<fs::path, int>>& SignalRemovals() {
    static auto* removals = new std::vector<std::pair<fs::path, int>>;
    return *removals;
}

// Removes a staging directory that another thread of this process may still be writing into (a
// signal's cleanup while the run writes its files): renamed first, to a name that still carries
// kStagingPrefix, so that no path the writers form reaches it any more, then removed until it is
// gone (a file whose creation was under way at the rename can appear after the first pass). The
// directory's flock follows it through the rename. A directory that still cannot be removed stays
// for the next run's RemoveDebris.
void RemoveStagingDirectory(const fs::path& dir) {
    fs::path target = dir;
    fs::path removing = dir;
    removing += "-removed";
    if (::rename(dir.c_str(), removing.c_str()) == 0) target = removing;
    std::error_code error;
    constexpr int kPasses = 100;
    for (int pass = 0; pass < kPasses; ++pass) {
        fs::remove_all(target, error);
        if (!fs::exists(fs::symlink_status(target, error))) return;
    }
}

}  // namespace

struct OutputSet::Staging {
    fs::path dir;                  // the staging directory; empty once published or removed
    fs::path chainFrom, chainTop;  // RemoveEmptyChain's: the directories made for DIR's parents
    bool committed = false;
    int lockFd = -1;  // holds the directory's flock (RemoveDebris)

    // Removes the directory (then drops its lock) and, unless the set was committed, the parent
    // directories made for it. With LiveMutex held.
    void Discard() {
        if (!dir.empty()) RemoveStagingDirectory(dir);
        dir.clear();
        if (lockFd >= 0) ::close(std::exchange(lockFd, -1));
        if (!committed) RemoveEmptyChain(chainFrom, chainTop);
        chainTop.clear();
    }
    ~Staging() {
        const std::lock_guard live(LiveMutex());
        Discard();
        std::erase(LiveStagings(), this);
    }
};

namespace {

// Makes the staging directory in `parent` (and `parent` with the directories above it that are
// missing; `createdTop` is the topmost of them), after removing the debris of killed runs there.
// Throws InputError `shown` + the reason, leaving nothing.
std::unique_ptr<OutputSet::Staging> MakeStaging(const fs::path& parent, const fs::path& createdTop,
                                                const std::string& shown,
                                                const std::string& where) {
    auto staging = std::make_unique<OutputSet::Staging>();
    staging->chainFrom = parent;
    staging->chainTop = createdTop;
    const std::lock_guard live(LiveMutex());  // a signal waits until the directory is registered
    LiveStagings().push_back(staging.get());
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) throw InputError(shown + "cannot create the directory (" + error.message() + ")");
    const DirectoryLock parentLock(parent, true, true);  // --out may name it through a link
    if (parentLock.Held()) RemoveDebris(parent);
    std::string pattern = (parent / (std::string(kStagingPrefix) + "XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        const int reason = errno;
        throw InputError(shown + "cannot create files " + where + " (" + ErrnoText(reason) + ")");
    }
    staging->dir = pattern;
    staging->lockFd = DirectoryLock(staging->dir, false).Release();
    return staging;
}

// The directory beside an append-only DIR where its files are staged (DIR's parent, on DIR's
// file system and not append-only itself, so that the staging directory can be removed).
fs::path AppendOnlyStagingParent(const fs::path& outDir, const std::string& shown) {
    std::error_code error;
    const fs::path resolved = fs::canonical(outDir, error);
    const fs::path parent = resolved.parent_path();
    struct stat dirStat {
    }, parentStat{};
    if (error || ::stat(resolved.c_str(), &dirStat) != 0 ||
        ::stat(parent.c_str(), &parentStat) != 0 || dirStat.st_dev != parentStat.st_dev ||
        IsAppendOnly(parent))
        throw InputError(shown +
                         "is append-only (chattr +a), and its parent cannot hold the staging "
                         "directory (another file system, or append-only too)");
    return parent;
}

// The nearest existing directory at or above `dir` (whose topmost missing one is `createdTop`).
fs::path NearestExisting(const fs::path& dir, const fs::path& createdTop) {
    const fs::path at = createdTop.empty() ? dir : createdTop.parent_path();
    return at.empty() ? fs::path(".") : at;
}

// Throws InputError "--out: writing <file> would overwrite the case file <input>" when a file
// that `isOutput` accepts (a file name inside outDir) is, once directories and links are
// resolved, one of `inputs`.
void RefuseOverwritingInputs(const fs::path& outDir, const std::vector<fs::path>& inputs,
                             const std::function<bool(const std::string& fileName)>& isOutput) {
    std::error_code error;
    const fs::path outAt = fs::weakly_canonical(fs::absolute(outDir), error);
    if (error) return;  // an --out that cannot be resolved is refused when it is made
    for (const fs::path& input : inputs) {
        const fs::path path = fs::absolute(input);
        // Where the input's name lies (a link there is replaced by the output) and the file it
        // resolves to (the link's target would be replaced through a directory link).
        const fs::path named = fs::weakly_canonical(path.parent_path(), error) / path.filename();
        const fs::path resolved = fs::weakly_canonical(path, error);
        for (const fs::path& at : {named, resolved})
            if (at.parent_path() == outAt && isOutput(at.filename().string()))
                throw InputError("--out: writing " + (outDir / at.filename()).string() +
                                 " would overwrite the case file " + input.string());
    }
}

// Why link(2) refused to keep an old file, in words.
std::string LinkRefusal(int reason) {
    std::string text = "link: " + ErrnoText(reason);
    if (reason == EPERM)
        text +=
            ": another user's file (fs.protected_hardlinks), or an immutable or append-only one";
    return text;
}

}  // namespace

OutputSet::OutputSet(const fs::path& outDir, OutputPlan plan)
    : outDir_(WithoutTrailingSeparator(outDir)), plan_(std::move(plan)) {
    if (!plan_.isOutput) throw std::logic_error("OutputSet: the plan names no outputs");
    if (outDir_.empty()) throw InputError("--out: must name a directory, got an empty string");
    const std::string shown = "--out: " + outDir_.string() + ": ";
    if (const std::string problem = PathLengthProblem(outDir_); !problem.empty())
        throw InputError(shown + problem);
    const bool exists = ExistingDirectory(outDir_, shown);
    RefuseOverwritingInputs(outDir_, plan_.inputs, plan_.isOutput);
    fs::path stagingParent = outDir_, createdTop;
    if (exists) {
        const bool appendOnly = IsAppendOnly(outDir_);
        CheckExistingOutputs(appendOnly);
        if (appendOnly) stagingParent = AppendOnlyStagingParent(outDir_, shown);
    } else {
        // A missing DIR is staged beside it and renamed into place whole; "." and ".." cannot be.
        wholeDirectory_ = outDir_.filename() != "." && outDir_.filename() != "..";
        if (wholeDirectory_)
            stagingParent = outDir_.has_parent_path() ? outDir_.parent_path() : fs::path(".");
        createdTop = TopmostMissing(stagingParent);
        const fs::path existing = NearestExisting(stagingParent, createdTop);
        if (IsAppendOnly(existing))
            throw InputError(shown + existing.string() +
                             " is append-only (chattr +a): a failed run could not remove what it "
                             "made there (make the directory first)");
    }
    staging_ = MakeStaging(stagingParent, createdTop, shown,
                           stagingParent == outDir_ || wholeDirectory_
                               ? "there"
                               : "in " + stagingParent.string() +
                                     ", where an append-only --out "
                                     "is staged");
    stagingDir_ = staging_->dir;
    if (exists) ProbeBackups();
}

OutputSet::~OutputSet() = default;

// In an existing DIR, the old files the outputs will replace: none may be a directory, and an
// append-only DIR lets none be replaced.
void OutputSet::CheckExistingOutputs(bool appendOnly) const {
    std::error_code error;
    for (fs::directory_iterator it(outDir_, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (IsLexelDirectory(name) || !plan_.isOutput(name)) continue;
        const std::string shown = "--out: " + (outDir_ / name).string() + ": ";
        struct stat st {};
        if (::lstat(it->path().c_str(), &st) == 0 && S_ISDIR(st.st_mode))
            throw InputError(shown + "is a directory, and an output file has its name");
        if (appendOnly)
            throw InputError("--out: " + outDir_.string() + ": is append-only (chattr +a), so " +
                             "its old " + name + " cannot be replaced");
    }
}

// In an existing DIR, each old file an output replaces must be one whose old version can be kept
// as a hard link (CommitFileByFile restores it from there if publishing fails): tried here, before
// anything is computed, and again at Commit.
void OutputSet::ProbeBackups() const {
    const fs::path probe = stagingDir_ / ".probe";
    std::error_code error;
    for (fs::directory_iterator it(outDir_, error), end; !error && it != end; it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (IsLexelDirectory(name) || !plan_.isOutput(name)) continue;
        if (::link(it->path().c_str(), probe.c_str()) == 0) {
            ::unlink(probe.c_str());
            continue;
        }
        const int reason = errno;
        if (reason == ENOENT) continue;  // gone meanwhile
        throw InputError("--out: " + (outDir_ / name).string() +
                         ": cannot keep the old file to restore it if publishing fails (" +
                         LinkRefusal(reason) + ")");
    }
}

fs::path OutputSet::Staged(const std::string& fileName) const {
    if (fileName.empty() || fileName.find('/') != std::string::npos || fileName == "." ||
        fileName == "..")
        throw std::logic_error("OutputSet: '" + fileName + "' is not a plain file name");
    if (!plan_.isOutput(fileName))
        throw std::logic_error("OutputSet: '" + fileName + "' is not among the declared outputs");
    return stagingDir_ / fileName;
}

void OutputSet::WriteText(const std::string& fileName, const std::string& content) {
    const fs::path path = Staged(fileName);
    const std::string shown = (outDir_ / fileName).string();
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw std::runtime_error(shown + ": cannot create (" + ErrnoText(errno) + ")");
    const auto fail = [&](const char* what, int reason) {
        ::close(fd);
        throw std::runtime_error(shown + ": " + what + " (" + ErrnoText(reason) + ")");
    };
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ::ssize_t written = ::write(fd, data, left);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) fail("write failed", written < 0 ? errno : ENOSPC);
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    if (::fsync(fd) != 0) fail("fsync failed", errno);
    if (::close(fd) != 0)
        throw std::runtime_error(shown + ": close failed (" + ErrnoText(errno) + ")");
    textSizes_[fileName] = content.size();
}

void OutputSet::ThrowWithFinalNames(const std::string& message) const {
    std::string text = message;
    const std::string staged = stagingDir_.string(), final = outDir_.string();
    for (std::size_t at = text.find(staged); at != std::string::npos;
         at = text.find(staged, at + final.size()))
        text.replace(at, staged.size(), final);
    throw std::runtime_error(text);
}

void OutputSet::VerifyAndSync() const {
    for (const std::string& name : StagedFiles(stagingDir_)) {
        if (!plan_.isOutput(name))
            throw std::logic_error("OutputSet: the staged '" + name +
                                   "' is not among the declared outputs");
        const fs::path path = stagingDir_ / name;
        const std::string shown = (outDir_ / name).string();
        if (const auto text = textSizes_.find(name); text != textSizes_.end()) {
            std::error_code error;
            const std::uintmax_t size = fs::file_size(path, error);
            if (error) throw std::runtime_error(shown + ": " + error.message());
            if (size != text->second)
                throw std::runtime_error(shown + ": " + std::to_string(size) + " bytes on disk, " +
                                         std::to_string(text->second) + " written");
        } else if (path.extension() == ".png") {
            if (const std::string defect = PngDefect(path); !defect.empty())
                throw std::runtime_error(shown + ": not a complete PNG image (" + defect + ")");
        }
        if (!SyncPath(path, false))
            throw std::runtime_error(shown + ": fsync failed (" + ErrnoText(errno) + ")");
    }
}

void OutputSet::Commit() {
    if (staging_->committed) throw std::logic_error("OutputSet: committed twice");
    VerifyAndSync();
    const std::lock_guard live(LiveMutex());  // a signal now waits until the set is published
    if (wholeDirectory_)
        CommitWholeDirectory();
    else
        CommitFileByFile();
}

namespace {

// Syncs the directory that now names the published files: a directory this user cannot open
// (EACCES, EPERM) or a file system that cannot sync one (EINVAL, EROFS, ENOTSUP) is passed over,
// any other failure (EIO: the disk lost the renames) throws std::runtime_error, so that the run
// fails rather than report files that a power loss may take.
void SyncPublished(const fs::path& dir) {
    if (SyncPath(dir, true)) return;
    const int reason = errno;
    for (const int passed : {EACCES, EPERM, EINVAL, EROFS, ENOTSUP})
        if (reason == passed) return;
    throw std::runtime_error(dir.string() + ": the files are in place, but syncing the directory " +
                             "failed (" + ErrnoText(reason) +
                             "): they may not survive a power loss");
}

}  // namespace

void OutputSet::CommitWholeDirectory() {
    // The staging directory becomes DIR: give it the mode mkdir would have (mkdtemp made 0700).
    ::chmod(stagingDir_.c_str(), 0777 & ~ProcessUmask());
    if (::rename(stagingDir_.c_str(), outDir_.c_str()) == 0) {
        staging_->committed = true;
        staging_->dir.clear();
        // The lock was the staging directory's; DIR must not stay locked (a next run locks it).
        if (staging_->lockFd >= 0) ::close(std::exchange(staging_->lockFd, -1));
        SyncPublished(outDir_.has_parent_path() ? outDir_.parent_path() : fs::path("."));
        return;
    }
    const int reason = errno;
    std::error_code error;
    // Another run made DIR meanwhile: join it file by file.
    if ((reason == ENOTEMPTY || reason == EEXIST) && fs::is_directory(outDir_, error))
        return CommitFileByFile();
    throw std::runtime_error(outDir_.string() + ": cannot move the staged files into place (" +
                             ErrnoText(reason) + ")");
}

namespace {

// Keeps the old version of each of `names` in DIR as a hard link in `keptDir`; true where there
// was one. Throws std::runtime_error "...; nothing was replaced" for an old file that is a
// directory or cannot be kept: publishing then stops before any file is replaced.
std::vector<bool> KeepOldVersions(const fs::path& outDir, const std::vector<std::string>& names,
                                  const fs::path& keptDir) {
    std::vector<bool> kept(names.size(), false);
    for (std::size_t i = 0; i < names.size(); ++i) {
        const fs::path target = outDir / names[i];
        struct stat st {};
        if (::lstat(target.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
            throw std::runtime_error(target.string() + ": is a directory; nothing was replaced");
        if (::link(target.c_str(), (keptDir / names[i]).c_str()) == 0) {
            kept[i] = true;
        } else if (errno != ENOENT) {
            throw std::runtime_error(target.string() +
                                     ": cannot keep the old file to restore it if publishing "
                                     "fails (" +
                                     LinkRefusal(errno) + "); nothing was replaced");
        }
    }
    return kept;
}

}  // namespace

void OutputSet::CommitFileByFile() {
    const std::vector<std::string> names = StagedFiles(stagingDir_);
    const fs::path keptDir = stagingDir_ / ".replaced";
    if (::mkdir(keptDir.c_str(), 0700) != 0)
        throw std::runtime_error(outDir_.string() + ": cannot stage the old versions (" +
                                 ErrnoText(errno) + "); nothing was replaced");
    const std::vector<bool> kept = KeepOldVersions(outDir_, names, keptDir);
    for (std::size_t i = 0; i < names.size(); ++i) {
        const fs::path target = outDir_ / names[i];
        if (::rename((stagingDir_ / names[i]).c_str(), target.c_str()) == 0) continue;
        const int reason = errno;
        // Roll back: the old versions return, the new names go.
        std::size_t unrestored = 0;
        for (std::size_t j = 0; j < i; ++j) {
            const fs::path moved = outDir_ / names[j];
            if (!kept[j])
                ::unlink(moved.c_str());
            else if (::rename((keptDir / names[j]).c_str(), moved.c_str()) != 0)
                ++unrestored;
        }
        std::string outcome = "no file was replaced";
        if (unrestored > 0) {
            // Keep the old versions out of every later run's cleanup.
            std::string keptName = stagingDir_.filename().string();
            keptName.replace(0, kStagingPrefix.size(), kKeptPrefix);
            const fs::path keptAt = stagingDir_.parent_path() / keptName;
            if (::rename(stagingDir_.c_str(), keptAt.c_str()) == 0) staging_->dir.clear();
            outcome = std::to_string(unrestored) +
                      " replaced files could not be restored; their old versions are in " +
                      ((staging_->dir.empty() ? keptAt : stagingDir_) / ".replaced").string();
        }
        throw std::runtime_error(target.string() + ": cannot move into place (" +
                                 ErrnoText(reason) + "); " + outcome);
    }
    staging_->committed = true;
    SyncPublished(outDir_);
}

namespace {

const char* SignalName(int signal) {
    switch (signal) {
        case SIGINT:
            return "SIGINT";
        case SIGTERM:
            return "SIGTERM";
        case SIGHUP:
            return "SIGHUP";
        default:
            return "a signal";
    }
}

// The signal thread's work: waits for one of `signals`, removes every staging directory (a
// Commit in progress holds LiveMutex and finishes first; the lock is then kept, so no set is
// published after) and ends the process.
[[noreturn]] void StopOnSignal(sigset_t signals) {
    int signal = 0;
    while (::sigwait(&signals, &signal) != 0) {
    }
    LiveMutex().lock();  // never unlocked: the process ends here
    bool discarded = false;
    for (OutputSet::Staging* staging : LiveStagings()) {
        discarded = discarded || (!staging->dir.empty() && !staging->committed);
        staging->Discard();
    }
    for (const auto& [path, fd] : SignalRemovals()) RemoveIfLastEmptyHolder(path, fd);
    std::string line = std::string(::isatty(STDERR_FILENO) ? "\n" : "") +
                       "lexel: error: interrupted by " + SignalName(signal) +
                       (discarded ? "; no --out file was written" : "") + "\n";
    for (std::size_t at = 0; at < line.size();) {
        const ::ssize_t written = ::write(STDERR_FILENO, line.data() + at, line.size() - at);
        if (written <= 0) break;
        at += static_cast<std::size_t>(written);
    }
    ::_exit(128 + signal);
}

}  // namespace

std::string PngBytesDefect(const std::string& bytes) {
    static const char kSignature[] = "\x89PNG\r\n\x1a\n";
    if (bytes.size() < 8 || bytes.compare(0, 8, kSignature, 8) != 0)
        return std::to_string(bytes.size()) + " bytes without the PNG signature";
    constexpr std::size_t kChunkOverhead = 12;  // length, type, CRC
    std::size_t at = 8;
    for (bool first = true; at + kChunkOverhead <= bytes.size(); first = false) {
        const std::uint64_t length = BigEndian32(bytes, at);
        const std::string type = bytes.substr(at + 4, 4);
        if (first && type != "IHDR") return "the first chunk is not IHDR";
        at += kChunkOverhead + length;
        if (at > bytes.size()) break;
        if (type == "IEND") return at == bytes.size() ? "" : "bytes follow the IEND chunk";
    }
    return "truncated: " + std::to_string(bytes.size()) + " bytes end before the IEND chunk";
}

void RemoveIfLastEmptyHolder(const fs::path& path, int fd) {
    struct stat open {
    }, named{};
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0 && ::fstat(fd, &open) == 0 &&
        ::lstat(path.c_str(), &named) == 0 && open.st_dev == named.st_dev &&
        open.st_ino == named.st_ino && open.st_size == 0)
        ::unlink(path.c_str());
}

void RemoveOnSignal(const fs::path& path, int fd) {
    const std::lock_guard live(LiveMutex());
    SignalRemovals().emplace_back(path, fd);
}

void ForgetOnSignal(const fs::path& path, int fd) {
    const std::lock_guard live(LiveMutex());
    std::erase(SignalRemovals(), std::pair(path, fd));
}

void StopCleanlyOnSignals() {
    sigset_t signals;
    sigemptyset(&signals);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler != SIG_IGN)
            sigaddset(&signals, signal);
    }
    if (sigisemptyset(&signals) || ::pthread_sigmask(SIG_BLOCK, &signals, nullptr) != 0) return;
    std::thread(StopOnSignal, signals).detach();
}

}  // namespace lexel::cases
