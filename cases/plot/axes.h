// Axes of lexel's plots in device pixels: round tick steps, decades, tick marks and grid lines,
// the frame with its labels, a log-scale y axis and the legend box.
#pragma once

#include <cairo.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/plot/canvas.h"

namespace lexel::plot {

// A tick's label: printf's %g.
std::string FormatTick(double value);
// 1, 2 or 5 times a power of ten, nearest `rough` (1 when rough is not positive and finite).
double NiceStep(double rough);
// The least of 1, 2, 5 or 10 times a power of ten that is at least span / 5: about five steps.
double NiceStepAtLeast(double span);
// Whole decades [lo, hi] of log10 covering the positive finite values; nullopt if there are none.
std::optional<std::pair<int, int>> DecadeRange(double minValue, double maxValue);

// Ticks are black, grid lines a grey light enough to stay behind the data.
void TickMark(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1);
void GridLine(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1);

// Frame and axis labels around `plot`; ticks are drawn by the callers.
void DrawAxesFrame(cairo_t* cr, const PxRect& plot, const std::string& xLabel,
                   const std::string& yLabel);
// Log-scale y ticks at whole decades [decadeLo, decadeHi], light grid lines at each.
void DrawLogYTicks(cairo_t* cr, const PxRect& plot, int decadeLo, int decadeHi);
// A legend box in the top-right corner of `plot`: a line swatch per label (a dot on it when
// `markers`).
void DrawLegend(cairo_t* cr, const PxRect& plot, const std::vector<std::string>& labels,
                const std::vector<Rgb>& colours, bool markers);

}  // namespace lexel::plot
