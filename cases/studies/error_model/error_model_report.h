// The error-model study's outputs (cases/studies/error_model/error_model_study.h): per sample the
// predicted band and the measured phase-averaged misclassified pixels (CSV), the least-squares fit
// of measured on predicted with the correlation per method and pooled (JSON, text), and the scatter
// plot with its fit line (PNG, Cairo).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "lexel/cases/studies/error_model/error_model_study.h"

namespace lexel::cases {

// measured ≈ slope · predicted + intercept by ordinary least squares, and Pearson's r; NaN where
// fewer than 2 points or a variance is 0.
struct LineFit {
    double slope = 0.0, intercept = 0.0, r = 0.0;
    std::size_t points = 0;
};
LineFit FitLine(std::span<const double> x, std::span<const double> y);

// One method's (or, with method "all", every method's pooled) summary. The fit takes the samples
// with an edge normal that are in range (ErrorModelSample::inRange).
struct ErrorModelSummary {
    std::string method;
    LineFit fit, fitIsotropic;  // on ExpectedBandWidth, on ‖n̂ᵀJ⁻¹‖/4
    // Per light (and method): Σ measured over its fitted samples against Σ predicted, over the
    // lights with samples — the sample-to-sample split of a band among neighbours averaged out.
    LineFit fitPerLight;
    std::size_t samples = 0, withoutNormal = 0, outOfRange = 0;
    double measuredOutOfRange = 0.0;         // pixels assigned to out-of-range samples
    double predicted = 0.0, measured = 0.0;  // Σ over the fitted samples (frame pixels)
    ErrorModelTotals totals;                 // the method's (or every method's) summed
    double ExplainedShare() const;           // totals: explained / misclassified (NaN for 0)
    double UncoveredShare() const;           // totals: uncovered / misclassified (NaN for 0)
};
std::vector<ErrorModelSummary> SummarizeErrorModel(const ErrorModelStudy& study);

// The fitted samples of every method binned by prediction, one bin per octave [2^k, 2^(k+1))
// frame pixels (those below 2^-5 in the first): where the model holds on average, where the
// measured floor or the saturation takes over.
struct ErrorModelBin {
    double lo = 0.0, hi = 0.0;  // frame pixels
    std::size_t samples = 0;
    double predictedMean = 0.0, measuredMean = 0.0;
};
std::vector<ErrorModelBin> BinErrorModel(const ErrorModelStudy& study);

// light,method,sample,readback_x,readback_y,normal_x,normal_y,predicted,predicted_isotropic,
// measured,in_range — one row per sample and method (CsvNumber; predicted inf where J is singular).
std::string ErrorModelCsv(const ErrorModelStudy& study);
nlohmann::json ErrorModelJson(const ErrorModelStudy& study);
std::string ErrorModelText(const ErrorModelStudy& study);
// Measured against predicted, one colour per method, the pooled fit line, y = x dashed, and the
// fit's numbers in the legend. Throws std::runtime_error when the file cannot be written.
void WriteErrorModelPlot(const std::string& pngPath, const ErrorModelStudy& study);

}  // namespace lexel::cases
