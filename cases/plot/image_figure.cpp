#include "lexel/cases/plot/image_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "lexel/cases/plot/axes.h"

namespace lexel::cases {

namespace {

using plot::RenderPng;
using plot::SetFont;
using plot::ShowLine;
using plot::ShowText;
using plot::TextWidth;
using plot::TickMark;
using plot::WrapToWidth;

constexpr int kFigureMargin = 16;
constexpr int kFigureMinWidth = 720;
constexpr int kFigureTargetSide = 600;  // small pictures are scaled up toward this side
constexpr double kTitleSize = 17, kTextSize = 13;
constexpr double kLineGap = 5;             // between text lines
constexpr int kSwatch = 14, kKeyRow = 22;  // key swatches and rows
constexpr int kBarWidth = 320, kBarHeight = 14;

// Where everything of an image figure goes; computed once to size the PNG, again to draw it.
struct FigurePlan {
    ImageFigureLayout layout;
    std::vector<std::string> title, lines;  // wrapped
    double textTop = kFigureMargin;
    struct KeyItem {
        double x, y;
        const ImageKey* key;
    };
    std::vector<KeyItem> key;
    double barY = 0;  // top of the bar's label
};

std::string BarTick(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

// The bar's ticks: (fraction along the bar, label). Decades for a log bar (at most 11 labels),
// else five evenly spaced values.
std::vector<std::pair<double, std::string>> BarTicks(const ColourBar& bar) {
    std::vector<std::pair<double, std::string>> ticks;
    const double span = bar.hi > bar.lo ? bar.hi - bar.lo : 1.0;
    if (bar.log10) {
        const int lo = static_cast<int>(std::ceil(bar.lo - 1e-9));
        const int hi = static_cast<int>(std::floor(bar.hi + 1e-9));
        const int every = std::max(1, (hi - lo + 9) / 10);
        for (int d = lo; d <= hi; d += every)
            ticks.emplace_back((d - bar.lo) / span, BarTick(std::pow(10.0, d)));
        return ticks;
    }
    for (int k = 0; k <= 4; ++k)
        ticks.emplace_back(k / 4.0, BarTick(bar.lo + (bar.hi - bar.lo) * k / 4.0));
    return ticks;
}

FigurePlan PlanFigure(cairo_t* cr, const spatial::Image& image, const ImageFigure& figure) {
    FigurePlan plan;
    ImageFigureLayout& layout = plan.layout;
    const int longer = std::max(image.width, image.height);
    layout.scale = std::clamp(kFigureTargetSide / std::max(1, longer), 1, 8);
    const int pxImageWidth = image.width * layout.scale,
              pxImageHeight = image.height * layout.scale;
    layout.width = std::max(kFigureMinWidth, pxImageWidth + 2 * kFigureMargin);
    const double pxText = layout.width - 2.0 * kFigureMargin;
    SetFont(cr, kTitleSize, true);
    plan.title = WrapToWidth(cr, figure.title, pxText);
    SetFont(cr, kTextSize);
    for (const std::string& line : figure.lines)
        for (std::string& wrapped : WrapToWidth(cr, line, pxText))
            plan.lines.push_back(std::move(wrapped));
    double y = kFigureMargin + plan.title.size() * (kTitleSize + kLineGap) +
               plan.lines.size() * (kTextSize + kLineGap) + 6;
    layout.imageX = (layout.width - pxImageWidth) / 2;
    layout.imageY = static_cast<int>(std::ceil(y));
    y = layout.imageY + pxImageHeight + 12;
    // The key flows left to right, a new row when an entry would not fit.
    double x = kFigureMargin;
    for (const ImageKey& key : figure.key) {
        const double pxEntry = kSwatch + 6 + TextWidth(cr, key.label) + 20;
        if (x > kFigureMargin && x + pxEntry > layout.width - kFigureMargin) {
            x = kFigureMargin;
            y += kKeyRow;
        }
        plan.key.push_back({x, y, &key});
        x += pxEntry;
    }
    if (!figure.key.empty()) y += kKeyRow;
    plan.barY = y + 4;
    if (figure.bar) y = plan.barY + kTextSize + kLineGap + kBarHeight + 6 + kTextSize + 4;
    layout.height = static_cast<int>(std::ceil(y)) + kFigureMargin;
    return plan;
}

void DrawBar(cairo_t* cr, const ColourBar& bar, double pxX, double pxY) {
    SetFont(cr, kTextSize);
    cairo_set_source_rgb(cr, 0, 0, 0);
    ShowLine(cr, pxX, pxY, bar.label);
    const double pxBarY = pxY + kTextSize + kLineGap;
    if (bar.stops.size() >= 2) {
        cairo_pattern_t* ramp = cairo_pattern_create_linear(pxX, 0, pxX + kBarWidth, 0);
        for (std::size_t k = 0; k < bar.stops.size(); ++k)
            cairo_pattern_add_color_stop_rgb(ramp, static_cast<double>(k) / (bar.stops.size() - 1),
                                             bar.stops[k].r, bar.stops[k].g, bar.stops[k].b);
        cairo_rectangle(cr, pxX, pxBarY, kBarWidth, kBarHeight);
        cairo_set_source(cr, ramp);
        cairo_fill(cr);
        cairo_pattern_destroy(ramp);
    }
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, pxX - 0.5, pxBarY - 0.5, kBarWidth + 1, kBarHeight + 1);
    cairo_stroke(cr);
    for (const auto& [fraction, label] : BarTicks(bar)) {
        const double pxTick = pxX + fraction * kBarWidth;
        TickMark(cr, pxTick, pxBarY + kBarHeight, pxTick, pxBarY + kBarHeight + 4);
        ShowText(cr, pxTick, pxBarY + kBarHeight + 6, label, 0.5, 0);
    }
}

// The picture, scaled by whole pixels, written straight into the figure's RGB24 surface.
void PaintImage(cairo_t* cr, const spatial::Image& image, const ImageFigureLayout& layout) {
    cairo_surface_t* surface = cairo_get_target(cr);
    cairo_surface_flush(surface);
    unsigned char* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const auto byte = [](float v) {
        return static_cast<std::uint32_t>(std::lround(255.0f * std::clamp(v, 0.0f, 1.0f)));
    };
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int c = image.channels >= 3 ? 1 : 0;
            const std::uint32_t rgb = byte(image.at(x, y, 0)) << 16 | byte(image.at(x, y, c)) << 8 |
                                      byte(image.at(x, y, 2 * c));
            for (int dy = 0; dy < layout.scale; ++dy) {
                auto* row = reinterpret_cast<std::uint32_t*>(
                    data +
                    static_cast<std::size_t>(layout.imageY + y * layout.scale + dy) * stride);
                for (int dx = 0; dx < layout.scale; ++dx)
                    row[layout.imageX + x * layout.scale + dx] = rgb;
            }
        }
    cairo_surface_mark_dirty(surface);
}

}  // namespace

ImageFigureLayout LayOutImageFigure(const spatial::Image& image, const ImageFigure& figure) {
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> scratch(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(scratch.get()),
                                                                cairo_destroy);
    return PlanFigure(cr.get(), image, figure).layout;
}

void WriteImageFigure(const std::string& pngPath, const spatial::Image& image,
                      const ImageFigure& figure) {
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0)
        throw std::invalid_argument(pngPath + ": an empty image");
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> scratch(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1), cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> measure(cairo_create(scratch.get()),
                                                                     cairo_destroy);
    const FigurePlan plan = PlanFigure(measure.get(), image, figure);
    const ImageFigureLayout& layout = plan.layout;
    RenderPng(pngPath, layout.width, layout.height, [&](cairo_t* cr) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        double y = kFigureMargin;
        SetFont(cr, kTitleSize, true);
        for (const std::string& line : plan.title) {
            ShowLine(cr, kFigureMargin, y, line);
            y += kTitleSize + kLineGap;
        }
        SetFont(cr, kTextSize);
        for (const std::string& line : plan.lines) {
            ShowLine(cr, kFigureMargin, y, line);
            y += kTextSize + kLineGap;
        }
        PaintImage(cr, image, layout);
        cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
        cairo_set_line_width(cr, 1);
        cairo_rectangle(cr, layout.imageX - 0.5, layout.imageY - 0.5,
                        image.width * layout.scale + 1.0, image.height * layout.scale + 1.0);
        cairo_stroke(cr);
        SetFont(cr, kTextSize);
        for (const FigurePlan::KeyItem& item : plan.key) {
            const spatial::ImageColour c = item.key->colour;
            cairo_rectangle(cr, item.x, item.y, kSwatch, kSwatch);
            cairo_set_source_rgb(cr, c.r, c.g, c.b);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
            cairo_stroke(cr);
            cairo_set_source_rgb(cr, 0, 0, 0);
            ShowLine(cr, item.x + kSwatch + 6, item.y + kSwatch / 2.0, item.key->label, true);
        }
        if (figure.bar) DrawBar(cr, *figure.bar, kFigureMargin + 28, plan.barY);
    });
}

}  // namespace lexel::cases
