// Reading a file that lexel did not just write (a shard's record or image beside another run's
// --out), as hostile: never through a symbolic link, only a regular file (a FIFO or a device is
// refused without being opened), and never more than a stated number of bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace lexel::cases {

// All bytes of `path`, a regular file (not a link to one) of at most maxBytes. Examined with lstat
// before it is opened, so that nothing else there is opened; opened with O_NOFOLLOW and checked
// again to be the same file. Throws InputError "<shown>: <reason>": "not found" (with
// `missingHint` appended when given), "is a symbolic link (...)", "is a FIFO (named pipe), not a
// regular file" and the like, "larger than N bytes (M)", "was replaced while it was opened", or a
// failed read.
std::string ReadHostileFile(const std::filesystem::path& path, std::uintmax_t maxBytes,
                            const std::string& shown, const std::string& missingHint = "");

}  // namespace lexel::cases
