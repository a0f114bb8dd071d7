// The text of a progress line (lexel's bar on a terminal, cases/app/progress.h): how far a long
// command is, how long it has run, and how long it will still take at its pace so far.
#pragma once

#include <cstddef>
#include <string>

namespace lexel::cases {

// "12 s", "4 min 05 s", "3 h 07 min", "2 d 05 h": a duration in seconds (rounded down, ≥ 0) in
// the two largest units it needs.
std::string DurationText(double seconds);

// "<label> [####......] <done>/<total> <what>, <elapsed> elapsed, about <remaining> left", the
// remaining time extrapolated from the mean time per unit done so far ("estimating" before the
// first unit; nothing once all are done). The bar is 30 characters.
std::string ProgressText(const std::string& label, std::size_t done, std::size_t total,
                         const std::string& what, double elapsedSeconds);

}  // namespace lexel::cases
