// A number in lexel's JSON outputs: JSON has no NaN or infinity, so an undefined or infinite value
// is `null` (cases/README.md: "No format ever prints nan"). The lossless sweep record
// (record/sweep_record_text.h) keeps them as strings instead.
#pragma once

#include <cmath>
#include <nlohmann/json.hpp>

namespace lexel::cases {

inline nlohmann::json FiniteOrNull(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace lexel::cases
