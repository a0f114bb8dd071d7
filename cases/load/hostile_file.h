// Reading a file that lexel did not just write (a shard's record or image beside another run's
// --out), as hostile: never through a symbolic link, only a regular file (a FIFO or a device is
// refused without blocking on it or acting on it), and never more than a stated number of bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace lexel::cases {

// All bytes of `path`, a regular file (not a link to one) of at most maxBytes. Throws InputError
// "<shown>: <reason>": "not found" (with `missingHint` appended when given), "is a symbolic link
// (...)", "is a FIFO (named pipe), not a regular file" and the like, "larger than N bytes", or a
// failed read.
std::string ReadHostileFile(const std::filesystem::path& path, std::uintmax_t maxBytes,
                            const std::string& shown, const std::string& missingHint = "");

}  // namespace lexel::cases
