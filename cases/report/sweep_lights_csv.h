// lights.csv of `lexel sweep --out` (cases/README.md): one row per light, its kind, position or
// direction and counted pixels, then per method its misclassified pixels, h, e, time and storage
// factor, the phase means, the winning start and the virtual maps' pages — from one column table.
#pragma once

#include <string>

#include "lexel/cases/run/sweep.h"

namespace lexel::cases {

// The whole file, header line first; every line ends with '\n'.
std::string SweepLightsCsv(const SweepResult& result);

}  // namespace lexel::cases
