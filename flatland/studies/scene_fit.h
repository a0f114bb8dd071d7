// Fitting a scene family's parameters to a published table (Chong 2003, ch. 4.1.3): the inverse
// problem "which scene prints these numbers?".
//
// Each published number is compared with lexel's value on the scene, measured exactly as
// `lexel tables` measures it (RunFlatlandCase: decisions on the case's decision pass, every
// number at full resolution):
//   angle      lexel plane angle, degrees counterclockwise from vertical, compared mod 180°
//              (the thesis prints 91° for our −89°); error = ours − published, degrees;
//   footprints worst (L∞), average (L1/|Ω|), mean + σ (population σ) of f = |dp/dl| in pixels per
//              lexel over the visible full-resolution pixels, and the mean of the two-frustum
//              split; error = ours / published − 1.
// The least-squares residual of a number is its error over its acceptance tolerance times 0.1:
// an angle error of 2° weighs as much as a footprint 10% off.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lexel/flatland/scene.h"
#include "lexel/flatland/studies/scene_family.h"
#include "lexel/solvers/errors.h"

namespace lexel::flatland {

// One printed row: the method that measures it and its numbers (NaN where not printed).
struct PublishedRow {
    std::string label;      // as printed, e.g. "Our Method (L1)"
    std::string method;     // lexel's method for the row (optimal-l1, psm-thesis, normal, ...)
    double angleDeg = NAN;  // lexel plane angle, degrees
    double worst = NAN, average = NAN, meanPlusSigma = NAN;  // pixels per lexel
    double twoFrustaMean = NAN;  // mean footprint of the two-frustum split, pixels per lexel
};

struct PublishedTable {
    std::string title;  // the thesis's heading
    std::vector<PublishedRow> rows;
    std::string splitMethod = "split-dp";  // measures twoFrustaMean
};

enum class Quantity { kAngle, kWorst, kAverage, kMeanPlusSigma, kTwoFrustaMean };
const char* QuantityName(
    Quantity quantity);  // "angle", "worst", "average", "mean+σ", "mean (2 frusta)"

struct ComparedNumber {
    int row = 0;  // index into PublishedTable::rows
    Quantity quantity = Quantity::kAngle;
    double published = NAN, value = NAN;
    double error = NAN;  // degrees (angle) or relative (footprints), signed
};

struct Tolerances {
    double angleDeg = 2.0;   // acceptance: every angle within this many degrees
    double footprint = 0.1;  // acceptance: every footprint within this relative error
};

// Normalized error of a number: |error| / its tolerance (≤ 1 is accepted).
double NormalizedError(const ComparedNumber& number, const Tolerances& tolerances);
// Least-squares residual: 0.1 × signed error / tolerance.
double FitResidual(const ComparedNumber& number, const Tolerances& tolerances);

// The published numbers of `table` beside lexel's on `scene`, footprints multiplied by
// `footprintScale` (SceneFamily::FootprintScale; 1 for a case file), in row order and within a
// row angle, worst, average, mean + σ, two-frusta mean (those published). Throws DomainError as
// RunFlatlandCase does when lexel refuses the scene; std::invalid_argument for an unknown method.
std::vector<ComparedNumber> CompareWithTable(const FlatScene& scene, const PublishedTable& table,
                                             double footprintScale = 1.0);
// The same without throwing, for scenes a search proposes: nullopt when the scene's geometry is
// refused (CheckSceneGeometry), a sampling pass refuses it (TrySamplingPass), or the table needs
// a split and the scene has fewer lexels than its frustum budget (where SplitLightFrustum could
// refuse it); the reason in *defect when given.
std::optional<std::vector<ComparedNumber>> TryCompareWithTable(
    const FlatScene& scene, const PublishedTable& table, double footprintScale = 1.0,
    std::optional<DomainError>* defect = nullptr);

struct TableAgreement {
    double worstAngleDeg = 0.0;    // max |angle error|
    double worstFootprint = 0.0;   // max |relative footprint error|
    double worstNormalized = 0.0;  // max NormalizedError
    double rms = 0.0;              // RMS of FitResidual
    bool accepted = false;         // worstNormalized ≤ 1
};
TableAgreement Agreement(const std::vector<ComparedNumber>& numbers, const Tolerances& tolerances);

struct FitOptions {
    std::uint64_t seed = 1;
    int screenSamples = 400;  // random parameter vectors drawn from the family's ranges
    int starts = 4;           // Levenberg–Marquardt runs from the best screened ones
    int maxIterations = 200;  // per run
    // Rounds of Lawson's reweighting after the least-squares run: each multiplies a number's
    // weight by its |residual|, which drives the fit toward the minimax (smallest worst error),
    // the acceptance criterion. The best iterate by worst normalized error is kept.
    int minimaxRounds = 0;
    // Then a compass search on the acceptance criterion itself, the worst normalized error of the
    // scene as written (integer lexel count), which is piecewise constant where pixels change
    // what they see: at most this many scenes measured (0: none), steps from patternStep of each
    // range down to 1e-6.
    int patternEvaluations = 0;
    double patternStep = 0.02;
    std::vector<double> weights;  // per published number (CompareWithTable order); empty: all 1
    Tolerances tolerances;
};

struct FitResult {
    std::vector<double> parameters;       // the family's parameters at the optimum
    FlatScene scene;                      // built from them (lexel count rounded)
    std::vector<ComparedNumber> numbers;  // measured on `scene` as built (integer lexels)
    TableAgreement agreement;
    double cost = 0.0;    // ½ Σ residual² at the real-valued optimum
    int evaluations = 0;  // scenes measured
    int validStarts = 0;  // screened samples whose scene lexel accepted (FitFamily)
};

// The residual vector of a parameter vector (size: published numbers), each multiplied by
// weights[i] when weights are given; empty when the scene is refused or a residual is not finite.
std::vector<double> FamilyResiduals(const SceneFamily& family, const PublishedTable& table,
                                    std::span<const double> parameters,
                                    const Tolerances& tolerances = {},
                                    std::span<const double> weights = {});

// Multi-start fit: screens options.screenSamples seeded random vectors (uniform in each range, in
// log for logScale parameters), then runs bounded Levenberg–Marquardt (Ceres, central numeric
// differences, in coordinates normalized to the ranges) from the best options.starts of them,
// and returns the best; nullopt when no screened sample gives a scene lexel accepts (or
// options.starts is 0).
std::optional<FitResult> FitFamily(const SceneFamily& family, const PublishedTable& table,
                                   const FitOptions& options);
// One Levenberg–Marquardt run from `start` (inside the ranges), then options.minimaxRounds and
// the pattern search; never returns a worse scene than the start. Throws DomainError (the
// reason TryCompareWithTable gives) when the start's scene is refused.
FitResult RefineFamily(const SceneFamily& family, const PublishedTable& table,
                       std::span<const double> start, const FitOptions& options);
// Which published numbers cannot be met together: for each number k, refits from `start` with k
// left out (weight 0, then options.minimaxRounds) and reports the worst normalized error of the
// other numbers. A number whose removal lets the rest be met (≤ 1) is in conflict with them.
// Throws DomainError, like RefineFamily, when the start's scene is refused.
struct DroppedNumber {
    int number = 0;                  // index in CompareWithTable order
    double restWorstNormalized = 0;  // over the other numbers, at the refit
    double droppedNormalized = 0;    // the left-out number's own error at the refit
};
std::vector<DroppedNumber> DropOneAnalysis(const SceneFamily& family, const PublishedTable& table,
                                           std::span<const double> start,
                                           const FitOptions& options);

// The result of `parameters` without optimizing (evaluations = 1); throws DomainError when their
// scene is refused.
FitResult EvaluateFamily(const SceneFamily& family, const PublishedTable& table,
                         std::span<const double> parameters, const Tolerances& tolerances = {});

}  // namespace lexel::flatland
