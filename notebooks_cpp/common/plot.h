// The one figure each teaching program writes: line and point plots side by side, or captioned
// pictures in a grid, as a PNG, drawn with lexel's plotting module (cases/plot: its palette,
// canvas and PNG writing). Not part of lexel's API: the programs' own panels.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/plot/palette.h"

namespace lexel::notebooks {

using plot::HeatColour;     // t in [0, 1]: dark purple → teal → yellow (clamped)
using plot::PaletteColour;  // lexel's palette: the reports' colours, repeating after twelve
using plot::Rgb;

struct Series {
    enum class Style { kLine, kDashed, kPoints, kPolygon };  // kPolygon: closed outline
    explicit Series(std::string label = "", Style style = Style::kLine,
                    std::optional<Rgb> colour = std::nullopt, double width = 2.0)
        : label(std::move(label)), style(style), colour(colour), width(width) {}
    void Add(double xValue, double yValue) { x.push_back(xValue), y.push_back(yValue); }

    std::string label;         // legend entry; empty: not in the legend
    std::vector<double> x, y;  // data coordinates; a non-finite point breaks a line
    Style style = Style::kLine;
    std::optional<Rgb> colour;  // default: PaletteColour(series index)
    double width = 2.0;         // line width, or marker radius for kPoints (pixels)
};

struct Panel {
    Panel(std::string title, std::string xLabel, std::string yLabel, bool logY = false,
          bool equalAspect = false, std::vector<Series> series = {})
        : title(std::move(title)),
          xLabel(std::move(xLabel)),
          yLabel(std::move(yLabel)),
          logY(logY),
          equalAspect(equalAspect),
          series(std::move(series)) {}

    std::string title, xLabel, yLabel;
    bool logY = false;         // log-scale y (non-positive values are left out)
    bool equalAspect = false;  // one data unit is as long on x as on y (geometry)
    std::vector<Series> series;
};

// The panels side by side in one PNG. Throws std::runtime_error when it cannot be written.
void WritePlot(const std::filesystem::path& png, const std::vector<Panel>& panels);

// An image with a caption: interleaved floats in [0, 1], row-major from the top row, 1 (grey),
// 3 (RGB) or 4 (RGBA, alpha ignored) channels.
struct Picture {
    std::string caption;
    int width = 0, height = 0, channels = 3;
    std::span<const float> pixels;
};

// The pictures in a grid of `columns`, each scaled to fit a cell of cellSize pixels, captions
// below. Throws std::runtime_error when it cannot be written.
void WritePictures(const std::filesystem::path& png, const std::vector<Picture>& pictures,
                   int columns, int cellSize = 360);

}  // namespace lexel::notebooks
