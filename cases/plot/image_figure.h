// An image figure (Cairo, PNG): a picture (the 3D frame, an error map, a shadow map, a storage
// hemisphere) under its title and what it counts, with its colour key and, for a scale, a
// colour bar with values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lexel/spatial/harness/image_io.h"
#include "lexel/spatial/harness/images.h"

namespace lexel::cases {

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
