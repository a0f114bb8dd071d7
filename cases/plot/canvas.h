// Drawing on a Cairo canvas in device pixels: colours, fonts, text placed by its ink or its
// baseline, and a PNG written whole or not at all. The primitives of every lexel figure
// (curve_plot.h, image_figure.h, case_figure.h, the error model's scatter) and of the teaching
// programs' plots.
#pragma once

#include <cairo.h>

#include <functional>
#include <string>
#include <vector>

#include "lexel/cases/plot/palette.h"

namespace lexel::plot {

struct PxRect {
    double x, y, width, height;  // top-left corner, device pixels
    double Right() const { return x + width; }
    double Bottom() const { return y + height; }
};

void SetColour(cairo_t* cr, Rgb c, double alpha = 1.0);
// The sans-serif face at `size` pixels.
void SetFont(cairo_t* cr, double size, bool bold = false);

// Text anchored at (pxX, pxY): alignX 0/0.5/1 puts the left/centre/right of the ink there,
// alignY 0/0.5/1 its top/middle/bottom.
void ShowText(cairo_t* cr, double pxX, double pxY, const std::string& text, double alignX,
              double alignY);
// Text on the baseline pxY, alignX as ShowText's.
void ShowBaselineText(cairo_t* cr, double pxX, double pxY, const std::string& text,
                      double alignX = 0.0);
// Text with its origin at pxX and the font's ascent below pxY, so lines align by their
// baselines whatever their ink; centred on pxY when `centreY`.
void ShowLine(cairo_t* cr, double pxX, double pxY, const std::string& text, bool centreY = false);
// The advance width of `text` in the current font.
double TextWidth(cairo_t* cr, const std::string& text);
// `text` cut at spaces into lines no wider than `pxWidth` in the context's current font.
std::vector<std::string> WrapToWidth(cairo_t* cr, const std::string& text, double pxWidth);

// Builds a white pxWidth × pxHeight RGB surface, lets `draw` paint it, and writes it as PNG
// through a temporary file and a rename, so a reader never sees a half-written figure and a
// failed write leaves nothing behind. Throws std::runtime_error naming the path.
void RenderPng(const std::string& pngPath, int pxWidth, int pxHeight,
               const std::function<void(cairo_t*)>& draw);
// A 1×1 scratch canvas for measuring text before a figure's size is known.
void WithMeasuringCanvas(const std::function<void(cairo_t*)>& measure);

}  // namespace lexel::plot
