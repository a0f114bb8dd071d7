#include "lexel/cases/plot/axes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace lexel::plot {

std::string FormatTick(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

double NiceStep(double rough) {
    if (!(rough > 0) || !std::isfinite(rough)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(rough)));
    const double m = rough / decade;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * decade;
}

double NiceStepAtLeast(double span) {
    const double rough = span / 5.0;
    const double p = std::pow(10.0, std::floor(std::log10(rough)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= rough) return m * p;
    return 10.0 * p;
}

std::optional<std::pair<int, int>> DecadeRange(double minValue, double maxValue) {
    if (!(minValue > 0) || !std::isfinite(maxValue) || maxValue < minValue) return std::nullopt;
    int lo = static_cast<int>(std::floor(std::log10(minValue) + 1e-9));
    int hi = static_cast<int>(std::ceil(std::log10(maxValue) - 1e-9));
    if (hi <= lo) hi = lo + 1;
    return std::make_pair(lo, hi);
}

namespace {

void StrokeSegment(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1, double grey) {
    cairo_set_source_rgb(cr, grey, grey, grey);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, pxX0, pxY0);
    cairo_line_to(cr, pxX1, pxY1);
    cairo_stroke(cr);
}

}  // namespace

void TickMark(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1) {
    StrokeSegment(cr, pxX0, pxY0, pxX1, pxY1, 0.0);
}
void GridLine(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1) {
    StrokeSegment(cr, pxX0, pxY0, pxX1, pxY1, 0.88);
}

void DrawAxesFrame(cairo_t* cr, const PxRect& plot, const std::string& xLabel,
                   const std::string& yLabel) {
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
    cairo_stroke(cr);
    SetFont(cr, 15);
    ShowText(cr, plot.x + plot.width / 2, plot.Bottom() + 42, xLabel, 0.5, 0);
    cairo_save(cr);
    cairo_translate(cr, plot.x - 62, plot.y + plot.height / 2);
    cairo_rotate(cr, -std::numbers::pi / 2);
    ShowText(cr, 0, 0, yLabel, 0.5, 0.5);
    cairo_restore(cr);
}

void DrawLogYTicks(cairo_t* cr, const PxRect& plot, int decadeLo, int decadeHi) {
    const auto pxY = [&](double log10Value) {
        return plot.Bottom() - (log10Value - decadeLo) / (decadeHi - decadeLo) * plot.height;
    };
    // Label every decade unless there are too many to read.
    const int labelEvery = (decadeHi - decadeLo) > 10 ? 2 : 1;
    SetFont(cr, 13);
    for (int d = decadeLo; d <= decadeHi; ++d) {
        if (d > decadeLo && d < decadeHi) GridLine(cr, plot.x, pxY(d), plot.Right(), pxY(d));
        TickMark(cr, plot.x - 6, pxY(d), plot.x, pxY(d));
        if ((d - decadeLo) % labelEvery == 0)
            ShowText(cr, plot.x - 10, pxY(d), FormatTick(std::pow(10.0, d)), 1, 0.5);
        if (d == decadeHi) break;
        for (int m = 2; m <= 9; ++m) {
            const double y = pxY(d + std::log10(m));
            TickMark(cr, plot.x - 3, y, plot.x, y);
        }
    }
}

void DrawLegend(cairo_t* cr, const PxRect& plot, const std::vector<std::string>& labels,
                const std::vector<Rgb>& colours, bool markers) {
    if (labels.empty()) return;
    SetFont(cr, 13);
    double pxTextWidth = 0;
    for (const auto& label : labels) {
        cairo_text_extents_t extents;
        cairo_text_extents(cr, label.c_str(), &extents);
        pxTextWidth = std::max(pxTextWidth, extents.x_advance);
    }
    const double pxRow = 19, pxSwatch = 26;
    const double pxWidth = pxTextWidth + pxSwatch + 26, pxHeight = pxRow * labels.size() + 10;
    const double pxX = plot.Right() - pxWidth - 10, pxY = plot.y + 10;
    cairo_rectangle(cr, pxX, pxY, pxWidth, pxHeight);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const double pxRowY = pxY + 5 + pxRow * (i + 0.5);
        SetColour(cr, colours[i]);
        cairo_set_line_width(cr, 2.5);
        cairo_move_to(cr, pxX + 8, pxRowY);
        cairo_line_to(cr, pxX + 8 + pxSwatch, pxRowY);
        cairo_stroke(cr);
        if (markers) {
            cairo_arc(cr, pxX + 8 + pxSwatch / 2, pxRowY, 3.5, 0, 2 * std::numbers::pi);
            cairo_fill(cr);
        }
        cairo_set_source_rgb(cr, 0, 0, 0);
        ShowText(cr, pxX + pxSwatch + 16, pxRowY, labels[i], 0, 0.5);
    }
}

}  // namespace lexel::plot
