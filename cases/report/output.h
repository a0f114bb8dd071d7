// Writing result files.
#pragma once

#include <string>

namespace lexel::cases {

// Writes `content` to `path` through a temporary file and a rename, so a failed run never leaves
// a partial file under the final name. Throws std::runtime_error on I/O failure.
void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace lexel::cases
