// Figures people would rather look at than read (Cairo, PNG):
//  - the case diagram: geometry, camera frustum, light, each method's lexel plane and a fan of
//    lexel rays (every Nth lexel) hitting the geometry; split methods draw each frustum in its
//    own colour;
//  - the footprint plot: f across the visible pixels for every method, log-scale y, labelled
//    axes and a legend;
//  - the low-resolution decision plot (thesis Fig. 4.1): extra error against decision pixels;
//  - any such curve plot (the partitioned methods' misclassified pixels against k);
//  - an image figure: a picture (the 3D frame, error map, shadow map, a storage hemisphere) under
//    its title and what it counts, with its colour key and, for a scale, a colour bar with values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lexel/flatland/methods.h"
#include "lexel/spatial/harness/image_io.h"
#include "lexel/spatial/harness/images.h"

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

// An image figure's key entry: a swatch of the colour painted and what it means.
struct ImageKey {
    std::string label;
    spatial::ImageColour colour;
};
// A colour scale: `stops` evenly spaced from `lo` to `hi`, ticks with values under it.
struct ColourBar {
    std::string label;  // what the colours measure, with units
    std::vector<spatial::ImageColour> stops;
    double lo = 0.0, hi = 1.0;
    bool log10 = false;  // lo and hi are decades (whole numbers): ticks at 10^k
};
struct ImageFigure {
    std::string title;               // bold, first
    std::vector<std::string> lines;  // under the title: what it shows and its counts
    std::vector<ImageKey> key;       // under the picture
    std::optional<ColourBar> bar;    // under the key
};
// Layout of an image figure, in device pixels: the picture is `image` scaled by a whole factor
// (nearest neighbour, so texels stay square) to about 600 pixels on its longer side when it is
// smaller, never down.
struct ImageFigureLayout {
    int width = 0, height = 0;  // the PNG
    int scale = 1;
    int imageX = 0, imageY = 0;  // top-left of the picture
};
ImageFigureLayout LayOutImageFigure(const spatial::Image& image, const ImageFigure& figure);
// Writes the figure as PNG (8-bit RGB, a picture of 1 or 3 channels in [0, 1]). Throws
// std::runtime_error when the file cannot be written, std::invalid_argument for an empty image.
void WriteImageFigure(const std::string& pngPath, const spatial::Image& image,
                      const ImageFigure& figure);

}  // namespace lexel::cases
