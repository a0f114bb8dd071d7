// `lexel lowres` (Chong 2003, §4.1.1, Fig. 4.1): the additional error at full resolution of the
// angle chosen from K decision pixels, relative to the full-resolution optimum.
#pragma once

#include <cmath>
#include <vector>

#include "lexel/flatland/scene.h"

namespace lexel::cases {

// Error is the thesis's: the average footprint for L1, mean + σ for L2, the worst for L∞.
struct LowresRow {
    int decisionPixels = 0;                    // K (the last row is the full resolution)
    double extraPercent[3] = {NAN, NAN, NAN};  // L1, L2, L∞; NaN when K pixels see nothing usable
};

std::vector<int> LowresResolutions(int fullPixels);  // 5, 10, 20, 50, 100, 200, full

// Throws DomainError (flatland/methods.h) when the full-resolution pass cannot be run.
std::vector<LowresRow> RunLowresStudy(const flatland::FlatScene& scene);

}  // namespace lexel::cases
