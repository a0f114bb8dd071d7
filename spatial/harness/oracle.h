// `optimal-oracle`: the best single light matrix per light by the measured error —
// the limit of the single-matrix family, not a method a renderer can use (it scores candidates
// against the exact shadow rays).
//
// A derivative-free search (the measured count is piecewise constant in the matrix): every start
// (the single-map methods' own matrices, affine parts included) is scored as it is and with its
// affine part re-fitted to the visible points for its axis (RelevantHull::Fit, the optimizer's
// margin); from the best, a compass search on the optical axis p4 — rotations by ±step about two
// axes orthogonal to p4, each candidate's affine part re-fitted — moves to the best improving
// neighbour, halves the step when none improves, and stops below the final step or when the
// budget of scored candidates is spent.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/methods/method_info.h"
#include "lexel/spatial/optimizer.h"

namespace lexel::spatial {

// kOracleMethod (method_info.h; bound_methods.cpp registers it): the Evaluator computes it (it
// needs the truth), from the fair single-map methods' matrices (FairMethodNames) as starts, each
// candidate scored by its mean over K phases held out of the K the evaluation reports
// (HeldOutSubTexelPhases, sub_texel_phase.h), so that the reported bound is not the minimum of 64
// noisy means (the winner's curse).

struct OracleStart {
    std::string name;  // the method it came from
    LightMatrix matrix;
};

struct OracleOptions {
    int budget = 64;              // most candidates scored (starts included)
    double initialStepDeg = 4.0;  // the compass search's first rotation, degrees
    double finalStepDeg = 0.25;   // it stops once the step falls below this, degrees
    double margin = 0.02;         // the re-fit's margin (OptimizerOptions::margin)
};

struct OracleResult {
    LightMatrix matrix;
    double score = 0.0;  // its measured error (the scorer's)
    std::string start;   // the start the search began from ("<name>" or "<name>+fit")
    double startScore = 0.0;
    int scored = 0;  // candidates scored
};

// The search above over `starts` (at least one), re-fitting with `hull` at `map` texels; `score`
// is the measured error of a matrix (lower is better; +inf for one that cannot be used).
// std::invalid_argument without starts.
OracleResult SearchOracleMatrix(std::span<const OracleStart> starts, const RelevantHull& hull,
                                Resolution map,
                                const std::function<double(const LightMatrix&)>& score,
                                const OracleOptions& options = {});

}  // namespace lexel::spatial
