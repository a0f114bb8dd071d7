#include "lexel/cases/load/hostile_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_file_check.h"

namespace lexel::cases {

namespace {

// Reads up to `size` bytes of `fd` (fewer when the file shrank meanwhile); false on a read error.
bool ReadUpTo(int fd, std::size_t size, std::string& bytes) {
    bytes.resize(size);
    std::size_t done = 0;
    while (done < size) {
        const ::ssize_t got = ::read(fd, bytes.data() + done, size - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return false;
        if (got == 0) break;
        done += static_cast<std::size_t>(got);
    }
    bytes.resize(done);
    return true;
}

}  // namespace

std::string ReadHostileFile(const std::filesystem::path& path, std::uintmax_t maxBytes,
                            const std::string& shown, const std::string& missingHint) {
    // What stands there, seen with lstat first, so that a device or a FIFO is never opened.
    struct stat named {};
    if (::lstat(path.c_str(), &named) != 0) {
        const int reason = errno;
        if (reason == ENOENT) throw InputError(shown + ": not found" + missingHint);
        throw InputError(shown + ": cannot be examined (" + std::strerror(reason) + ")");
    }
    if (S_ISLNK(named.st_mode))
        throw InputError(shown + ": is a symbolic link (lexel reads no file here through one)");
    if (!S_ISREG(named.st_mode))
        throw InputError(shown + ": is " + spatial::FileKind(named.st_mode) +
                         ", not a regular file");
    if (static_cast<std::uintmax_t>(named.st_size) > maxBytes)
        throw InputError(shown + ": larger than " + std::to_string(maxBytes) + " bytes (" +
                         std::to_string(named.st_size) + ")");
    // Opened without following a link or blocking, and checked again: it may have been replaced.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        const int reason = errno;
        throw InputError(shown + ": cannot open (" + std::strerror(reason) + ")");
    }
    struct stat opened {};
    std::string bytes;
    const bool same = ::fstat(fd, &opened) == 0 && S_ISREG(opened.st_mode) &&
                      opened.st_dev == named.st_dev && opened.st_ino == named.st_ino &&
                      static_cast<std::uintmax_t>(opened.st_size) <= maxBytes;
    const bool read = same && ReadUpTo(fd, static_cast<std::size_t>(opened.st_size), bytes);
    const int readError = errno;
    ::close(fd);
    if (!same) throw InputError(shown + ": was replaced while it was opened");
    if (!read) throw InputError(shown + ": cannot be read (" + std::strerror(readError) + ")");
    return bytes;
}

}  // namespace lexel::cases
