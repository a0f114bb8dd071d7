// The memory budget of one lexel run: a case whose sizes would need more than this is refused
// before anything is allocated, with the estimate in the one-line error.
#pragma once

#include <cstddef>
#include <string>

namespace lexel::cases {

// 8 GiB: what a case may ask for. The CI and development machines have 24 GiB; the thesis and
// report cases need well under 1 GiB.
inline constexpr double kMemoryBudgetBytes = 8.0 * 1024 * 1024 * 1024;

// "needs about 9.3 GiB (what), above lexel's memory budget of 8 GiB" when `bytes` exceeds the
// budget, else empty. `what` says what the estimate counts, e.g. "camera 16384x16384".
std::string MemoryBudgetExcess(double bytes, const std::string& what);

// "9.3 GiB", "512 MiB", "12 KiB": a byte count for messages.
std::string FormatBytes(double bytes);

}  // namespace lexel::cases
