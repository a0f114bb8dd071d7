// Line plots (Cairo, PNG): curves with dots over a log-scale (or linear) x axis and a linear (or
// log-scale) y axis, a legend and an optional dashed guide — the partitioned methods'
// misclassified pixels against k, and the thesis's Fig. 4.1 (the low-resolution decision: extra
// error against decision pixels).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lexel::cases {

struct PlotCurve {
    std::string label;
    std::vector<double> x, y;  // x > 0 on a log x axis, y > 0 on a log y axis
};
struct CurvePlot {
    std::string title, xLabel, yLabel;
    std::vector<PlotCurve> curves;
    std::vector<double> xTicks;    // ticks at these x (and the axis spans them); empty: decades
    std::optional<double> guideY;  // a dashed horizontal line at this y, labelled guideLabel
    std::string guideLabel;
    bool logX = true;   // false: linear x from the smallest to the largest x (xTicks ignored)
    bool logY = false;  // true: whole decades of y
};
// Throws std::runtime_error when the file cannot be written.
void WriteCurvePlot(const std::string& pngPath, const CurvePlot& plot);

struct LowresCurve {
    std::string label;                 // e.g. "L1 (average)"
    std::vector<double> pixels;        // decision pixels K (x, log scale)
    std::vector<double> extraPercent;  // additional error in percent (y)
};
// Thesis Fig. 4.1, with the thesis's 5% threshold as the guide when the curves reach it.
void WriteLowresPlot(const std::string& pngPath, const std::string& title,
                     const std::vector<LowresCurve>& curves);

}  // namespace lexel::cases
