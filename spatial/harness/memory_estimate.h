// How much memory the 3D experiment (evaluation.h) needs for a scene's sizes, before it
// allocates: the loader refuses a case over lexel's memory budget and the sweep runs only as many
// lights at once as the budget holds.
#pragma once

#include <cstddef>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// Bytes, split into what one Evaluator holds for the whole run and what each light in flight adds.
struct EvaluationMemory {
    double shared = 0;    // frame and readback buffers, the geometry and its ray-tracing BVH
    double perLight = 0;  // truth, shades and maps of one light's methods, its samples
    double Total(int lightsInFlight) const { return shared + perLight * lightsInFlight; }
};

struct EvaluationSizes {
    Resolution frame, readback, shadowMap;
    std::size_t triangles = 0;
    int methods = 1;          // methods evaluated per light
    bool keepBuffers = true;  // every method's shades and maps kept (run --out's images)
    int truthMapSize = 0;     // the focused truth map's side (EvaluationOptions::mapTruth), or 0
};

// An upper bound of the heap the evaluation uses (measured against it in memory_estimate_test);
// the per-element byte counts and their sources are in memory_estimate.cpp.
EvaluationMemory EstimateEvaluationMemory(const EvaluationSizes& sizes);

}  // namespace lexel::spatial
