#include "lexel/cases/report/output.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>
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

// Why the file is not a complete PNG, or empty when it is one: the 8-byte signature, then chunks
// (4-byte length, 4-byte type, data, 4-byte CRC) from IHDR to IEND filling the file exactly
// (PNG specification, 2nd ed., sections 5.2-5.3). A 0-byte or truncated image fails here.
std::string PngDefect(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) return "cannot be read back";
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

}  // namespace

OutputSet::OutputSet(const fs::path& outDir) : outDir_(WithoutTrailingSeparator(outDir)) {
    const std::string shown = "--out: " + outDir_.string() + ": ";
    if (outDir_.empty()) throw InputError("--out: must name a directory");
    std::error_code error;
    const fs::file_status status = fs::status(outDir_, error);
    if (fs::exists(status) && !fs::is_directory(status))
        throw InputError(shown + "not a directory");
    // A missing DIR is staged beside it and renamed into place whole; "." and ".." cannot be.
    wholeDirectory_ =
        !fs::exists(status) && outDir_.filename() != "." && outDir_.filename() != "..";
    fs::path stagingParent = outDir_;
    if (wholeDirectory_) {
        stagingParent = outDir_.has_parent_path() ? outDir_.parent_path() : fs::path(".");
        createdTop_ = TopmostMissing(stagingParent);
    } else if (!fs::exists(status)) {
        createdTop_ = TopmostMissing(outDir_);
    }
    fs::create_directories(stagingParent, error);
    if (error) {
        RemoveEmptyChain(stagingParent, createdTop_);
        throw InputError(shown + "cannot create the directory (" + error.message() + ")");
    }
    std::string pattern = (stagingParent / ".lexel-staging-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        const int reason = errno;
        RemoveEmptyChain(stagingParent, createdTop_);
        throw InputError(shown + "cannot create files there (" + ErrnoText(reason) + ")");
    }
    stagingDir_ = pattern;
}

OutputSet::~OutputSet() {
    if (stagingDir_.empty()) return;
    std::error_code error;
    fs::remove_all(stagingDir_, error);  // after a file-by-file commit: the kept old versions
    if (!committed_)
        RemoveEmptyChain(wholeDirectory_ ? stagingDir_.parent_path() : outDir_, createdTop_);
}

fs::path OutputSet::Staged(const std::string& fileName) const {
    if (fileName.empty() || fileName.find('/') != std::string::npos || fileName == "." ||
        fileName == "..")
        throw std::logic_error("OutputSet: '" + fileName + "' is not a plain file name");
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
    if (committed_) throw std::logic_error("OutputSet: committed twice");
    VerifyAndSync();
    if (!wholeDirectory_) return CommitFileByFile();
    // The staging directory becomes DIR: give it the mode mkdir would have (mkdtemp made 0700).
    ::chmod(stagingDir_.c_str(), 0777 & ~ProcessUmask());
    if (::rename(stagingDir_.c_str(), outDir_.c_str()) == 0) {
        committed_ = true;
        stagingDir_.clear();
        SyncPath(outDir_.has_parent_path() ? outDir_.parent_path() : fs::path("."), true);
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

void OutputSet::CommitFileByFile() {
    const std::vector<std::string> names = StagedFiles(stagingDir_);
    // The old versions are kept as hard links, so that a failed rename can restore them.
    const fs::path keptDir = stagingDir_ / ".replaced";
    fs::create_directory(keptDir);
    std::vector<bool> kept(names.size(), false);
    for (std::size_t i = 0; i < names.size(); ++i) {
        const fs::path target = outDir_ / names[i];
        std::error_code error;
        const fs::file_status old = fs::symlink_status(target, error);
        if (fs::is_directory(old))
            throw std::runtime_error(target.string() + ": is a directory; nothing was replaced");
        if (fs::exists(old)) kept[i] = ::link(target.c_str(), (keptDir / names[i]).c_str()) == 0;
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        const fs::path target = outDir_ / names[i];
        if (::rename((stagingDir_ / names[i]).c_str(), target.c_str()) == 0) continue;
        const int reason = errno;
        for (std::size_t j = 0; j < i; ++j) {
            const fs::path moved = outDir_ / names[j];
            if (kept[j])
                ::rename((keptDir / names[j]).c_str(), moved.c_str());
            else
                ::unlink(moved.c_str());
        }
        throw std::runtime_error(target.string() + ": cannot move into place (" +
                                 ErrnoText(reason) + "); no file was replaced");
    }
    committed_ = true;
    SyncPath(outDir_, true);
}

}  // namespace lexel::cases
