// The memory a flatland run needs, from a scene's sizes alone, so that a loader can refuse a case
// before anything is allocated. Every term is an upper bound read off the data
// structures; memory.cpp has the sizeof arithmetic and tests/flatland/memory_test.cpp checks the
// bound against the allocator's count.
#pragma once

#include "lexel/flatland/scene.h"

namespace lexel::flatland {

// The sizes a run's memory depends on.
struct FlatlandSizes {
    double pixels = 0;          // camera pixels P (the full-resolution pass)
    double decisionPixels = 0;  // decision pixels D; equal to P when the case gives none
    double segments = 0;        // geometry segments S
    double wedges = 0;          // frusta.max W (the split's initial wedges)
    double budget = 0;          // frusta.budget B
};
FlatlandSizes SizesOf(const FlatScene& scene);

// Bytes a pass stores per pixel it is run at (FlatSample: 32; every pixel is reserved).
inline constexpr double kPassBytesPerPixel = 32;
// Bytes per pixel at the peak of a run whose decision pass is the full pass (P = D): the pass's
// 32 plus the largest working set, 32 (memory.cpp).
inline constexpr double kRunBytesPerPixel = 64;

// Upper bound, in bytes, of what RunFlatlandCase allocates for a scene with these sizes, running
// every method with its footprints not kept (as `lexel run` does). Without the process's own
// code and libraries, and without the case file's parsed JSON.
double FlatlandRunBytes(const FlatlandSizes& sizes);

}  // namespace lexel::flatland
