// Figures people would rather look at than read (Cairo, PNG):
//  - the case diagram: geometry, camera frustum, light, each method's lexel plane and a fan of
//    lexel rays (every Nth lexel) hitting the geometry; split methods draw each frustum in its
//    own colour;
//  - the footprint plot: f across the visible pixels for every method, log-scale y, labelled
//    axes and a legend;
//  - the low-resolution decision plot (thesis Fig. 4.1): extra error against decision pixels;
//  - any such curve plot (the partitioned methods' misclassified pixels against k).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lexel/flatland/methods.h"

namespace lexel::cases {

// Diagram (left) and footprint plot (right) of one case in one PNG. `report.fullPass` and each
// method's wsAxis/footprints/frusta must be filled (RunFlatlandCase with keepFootprints does;
// std::invalid_argument otherwise). Throws std::runtime_error when the file cannot be written.
void WriteCaseFigure(const std::string& pngPath, const flatland::FlatScene& scene,
                     const flatland::CaseReport& report);

// A line plot with a log-scale (or linear) x axis and a linear (or log-scale) y axis: curves with
// dots, a legend, an optional dashed guide.
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
void WriteLowresPlot(const std::string& pngPath, const std::string& title,
                     const std::vector<LowresCurve>& curves);

}  // namespace lexel::cases
