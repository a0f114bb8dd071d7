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
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        const int reason = errno;
        if (reason == ELOOP)
            throw InputError(shown + ": is a symbolic link (lexel reads no file here through one)");
        if (reason == ENOENT) throw InputError(shown + ": not found" + missingHint);
        throw InputError(shown + ": cannot open (" + std::strerror(reason) + ")");
    }
    struct stat st {};
    std::string bytes;
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    const bool small = regular && static_cast<std::uintmax_t>(st.st_size) <= maxBytes;
    const bool read = small && ReadUpTo(fd, static_cast<std::size_t>(st.st_size), bytes);
    const int readError = errno;
    ::close(fd);
    if (!regular)
        throw InputError(shown + ": is " + spatial::FileKind(st.st_mode) + ", not a regular file");
    if (!small)
        throw InputError(shown + ": larger than " + std::to_string(maxBytes) + " bytes (" +
                         std::to_string(st.st_size) + ")");
    if (!read) throw InputError(shown + ": cannot be read (" + std::strerror(readError) + ")");
    return bytes;
}

}  // namespace lexel::cases
