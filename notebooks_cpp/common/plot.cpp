#include "plot.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "lexel/cases/plot/axes.h"
#include "lexel/cases/plot/canvas.h"

namespace lexel::notebooks {

namespace {

constexpr double kPanelWidth = 640, kPanelHeight = 470;  // pixels per plot panel
constexpr double kLeft = 84, kRight = 18, kTop = 38, kBottom = 58;

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

using plot::NiceStep;
using plot::SetColour;

// Text of `size` pixels, its ink centred vertically on y.
void Text(cairo_t* cr, double x, double y, const std::string& s, double alignX, double size) {
    plot::SetFont(cr, size);
    plot::ShowText(cr, x, y, s, alignX, 0.5);
}

std::string Format(double v) { return plot::FormatTick(std::abs(v) < 1e-12 ? 0.0 : v); }

// Data → pixels for one panel; y is log10(y) when the panel is log-scale.
struct Axes {
    double x0, x1, y0, y1;  // data range shown (y in log10 when logY)
    double px, py, pw, ph;  // plot rectangle, pixels
    bool logY;
    double Y(double y) const { return logY ? std::log10(y) : y; }
    double ToPxX(double x) const { return px + (x - x0) / (x1 - x0) * pw; }
    double ToPxY(double y) const { return py + ph - (Y(y) - y0) / (y1 - y0) * ph; }
    bool Usable(double x, double y) const {
        return std::isfinite(x) && std::isfinite(y) && (!logY || y > 0);
    }
};

Axes FitAxes(const Panel& panel, double px, double py) {
    Axes a{std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(),
           0,
           0,
           px + kLeft,
           py + kTop,
           kPanelWidth - kLeft - kRight,
           kPanelHeight - kTop - kBottom,
           panel.logY};
    a.y0 = a.x0, a.y1 = a.x1;
    for (const Series& s : panel.series)
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
            if (a.Usable(s.x[i], s.y[i])) {
                a.x0 = std::min(a.x0, s.x[i]), a.x1 = std::max(a.x1, s.x[i]);
                a.y0 = std::min(a.y0, a.Y(s.y[i])), a.y1 = std::max(a.y1, a.Y(s.y[i]));
            }
    if (!(a.x0 <= a.x1)) a.x0 = 0, a.x1 = 1, a.y0 = 0, a.y1 = 1;
    if (a.x1 - a.x0 < 1e-12) a.x0 -= 0.5, a.x1 += 0.5;
    if (a.y1 - a.y0 < 1e-12) a.y0 -= 0.5, a.y1 += 0.5;
    if (panel.equalAspect) {  // grow the shorter range so that both scales match
        const double scale = std::min(a.pw / (a.x1 - a.x0), a.ph / (a.y1 - a.y0));
        const double cx = 0.5 * (a.x0 + a.x1), cy = 0.5 * (a.y0 + a.y1);
        a.x0 = cx - 0.5 * a.pw / scale, a.x1 = cx + 0.5 * a.pw / scale;
        a.y0 = cy - 0.5 * a.ph / scale, a.y1 = cy + 0.5 * a.ph / scale;
    }
    const double padX = 0.04 * (a.x1 - a.x0), padY = 0.05 * (a.y1 - a.y0);
    a.x0 -= padX, a.x1 += padX, a.y0 -= padY, a.y1 += padY;
    return a;
}

void DrawTicks(cairo_t* cr, const Axes& a) {
    SetColour(cr, {0, 0, 0});
    cairo_set_line_width(cr, 1);
    const double stepX = NiceStep((a.x1 - a.x0) / 6);
    for (double x = std::ceil(a.x0 / stepX) * stepX; x <= a.x1; x += stepX) {
        cairo_move_to(cr, a.ToPxX(x), a.py + a.ph);
        cairo_rel_line_to(cr, 0, 5);
        Text(cr, a.ToPxX(x), a.py + a.ph + 15, Format(x), 0.5, 12);
    }
    std::vector<double> ticksY;  // linear: a nice step; log: 1, 2, 5 (or 1..9) per decade
    if (!a.logY) {
        const double stepY = NiceStep((a.y1 - a.y0) / 6);
        for (double y = std::ceil(a.y0 / stepY) * stepY; y <= a.y1; y += stepY) ticksY.push_back(y);
    }
    for (const std::vector<int>& mantissas :
         {std::vector<int>{1}, {1, 2, 5}, {1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
        if (!a.logY || ticksY.size() >= 3) break;
        ticksY.clear();
        for (double d = std::floor(a.y0); d <= a.y1; ++d)
            for (int m : mantissas)
                if (const double y = d + std::log10(m); y >= a.y0 && y <= a.y1) ticksY.push_back(y);
    }
    for (double y : ticksY) {
        const double pxY = a.py + a.ph - (y - a.y0) / (a.y1 - a.y0) * a.ph;
        cairo_move_to(cr, a.px, pxY);
        cairo_rel_line_to(cr, -5, 0);
        Text(cr, a.px - 8, pxY, Format(a.logY ? std::pow(10.0, y) : y), 1, 12);
    }
    cairo_stroke(cr);
}

void DrawSeries(cairo_t* cr, const Axes& a, const Series& s, Rgb colour) {
    SetColour(cr, colour);
    cairo_set_line_width(cr, s.width);
    const double dash[] = {7, 5};
    cairo_set_dash(cr, dash, s.style == Series::Style::kDashed ? 2 : 0, 0);
    bool pen = false;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
        if (!a.Usable(s.x[i], s.y[i])) {
            pen = false;
            continue;
        }
        const double x = a.ToPxX(s.x[i]), y = a.ToPxY(s.y[i]);
        if (s.style == Series::Style::kPoints) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, y, s.width, 0, 2 * std::numbers::pi);
            cairo_fill(cr);
        } else {
            pen ? cairo_line_to(cr, x, y) : cairo_move_to(cr, x, y);
            pen = true;
        }
    }
    if (s.style == Series::Style::kPolygon) cairo_close_path(cr);
    cairo_stroke(cr);
    cairo_set_dash(cr, dash, 0, 0);
}

void DrawLegend(cairo_t* cr, const Axes& a, const Panel& panel) {
    std::vector<std::size_t> entries;
    for (std::size_t i = 0; i < panel.series.size(); ++i)
        if (!panel.series[i].label.empty()) entries.push_back(i);
    if (entries.empty()) return;
    const double x = a.px + a.pw - 214, y = a.py + 8;
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_rectangle(cr, x, y, 206, 18 * entries.size() + 8);
    cairo_fill(cr);
    for (std::size_t row = 0; row < entries.size(); ++row) {
        const Series& s = panel.series[entries[row]];
        const double rowY = y + 13 + 18 * row;
        SetColour(cr, s.colour.value_or(PaletteColour(entries[row])));
        cairo_rectangle(cr, x + 6, rowY - 3, 22, 6);
        cairo_fill(cr);
        SetColour(cr, {0, 0, 0});
        Text(cr, x + 34, rowY, s.label, 0, 12);
    }
}

void DrawPanel(cairo_t* cr, const Panel& panel, double px) {
    const Axes a = FitAxes(panel, px, 0);
    cairo_save(cr);
    cairo_rectangle(cr, a.px, a.py, a.pw, a.ph);
    cairo_clip(cr);
    for (std::size_t i = 0; i < panel.series.size(); ++i)
        DrawSeries(cr, a, panel.series[i], panel.series[i].colour.value_or(PaletteColour(i)));
    cairo_restore(cr);
    SetColour(cr, {0, 0, 0});
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, a.px, a.py, a.pw, a.ph);
    cairo_stroke(cr);
    DrawTicks(cr, a);
    DrawLegend(cr, a, panel);
    Text(cr, a.px + a.pw / 2, 18, panel.title, 0.5, 15);
    Text(cr, a.px + a.pw / 2, a.py + a.ph + 40, panel.xLabel, 0.5, 14);
    cairo_save(cr);
    cairo_translate(cr, px + 18, a.py + a.ph / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    Text(cr, 0, 0, panel.yLabel, 0.5, 14);
    cairo_restore(cr);
}

}  // namespace

void WritePlot(const std::filesystem::path& png, const std::vector<Panel>& panels) {
    const int width = static_cast<int>(kPanelWidth * std::max<std::size_t>(panels.size(), 1));
    plot::RenderPng(png.string(), width, kPanelHeight, [&](cairo_t* cr) {
        for (std::size_t i = 0; i < panels.size(); ++i) DrawPanel(cr, panels[i], kPanelWidth * i);
    });
}

namespace {

// Picture k of the grid, scaled to fit its cell, its caption below.
void DrawPicture(cairo_t* cr, const Picture& p, int k, int columns, int cellSize,
                 int captionHeight) {
    const Surface image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, p.width, p.height),
                        cairo_surface_destroy);
    unsigned char* data = cairo_image_surface_get_data(image.get());
    const int stride = cairo_image_surface_get_stride(image.get());
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const float* v = &p.pixels[(static_cast<std::size_t>(y) * p.width + x) * p.channels];
            const auto byte = [](float c) {
                return static_cast<std::uint32_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255));
            };
            const std::uint32_t r = byte(v[0]), g = byte(v[p.channels >= 3 ? 1 : 0]),
                                b = byte(v[p.channels >= 3 ? 2 : 0]);
            reinterpret_cast<std::uint32_t*>(data + y * stride)[x] = (r << 16) | (g << 8) | b;
        }
    cairo_surface_mark_dirty(image.get());
    const double scale = std::min(double(cellSize - 8) / p.width, double(cellSize - 8) / p.height);
    const double x0 = (k % columns) * cellSize, y0 = (k / columns) * (cellSize + captionHeight);
    cairo_save(cr);
    cairo_translate(cr, x0 + 0.5 * (cellSize - scale * p.width),
                    y0 + 0.5 * (cellSize - scale * p.height));
    cairo_scale(cr, scale, scale);
    cairo_set_source_surface(cr, image.get(), 0, 0);
    cairo_pattern_set_filter(cairo_get_source(cr),
                             scale >= 1 ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
    cairo_paint(cr);
    cairo_restore(cr);
    SetColour(cr, {0, 0, 0});
    Text(cr, x0 + cellSize / 2.0, y0 + cellSize + captionHeight / 2.0 - 2, p.caption, 0.5, 14);
}

}  // namespace

void WritePictures(const std::filesystem::path& png, const std::vector<Picture>& pictures,
                   int columns, int cellSize) {
    const int count = static_cast<int>(pictures.size());
    columns = std::clamp(columns, 1, std::max(count, 1));
    const int rows = (count + columns - 1) / columns, captionHeight = 26;
    for (int k = 0; k < count; ++k) {
        const Picture& p = pictures[k];
        if (p.width <= 0 || p.height <= 0 ||
            p.pixels.size() != static_cast<std::size_t>(p.width) * p.height * p.channels)
            throw std::runtime_error(png.string() + ": picture " + std::to_string(k) +
                                     " has the wrong number of pixels");
    }
    plot::RenderPng(png.string(), columns * cellSize,
                    std::max(rows, 1) * (cellSize + captionHeight), [&](cairo_t* cr) {
                        for (int k = 0; k < count; ++k)
                            DrawPicture(cr, pictures[k], k, columns, cellSize, captionHeight);
                    });
}

}  // namespace lexel::notebooks
