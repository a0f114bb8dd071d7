#include "lexel/cases/plot/curve_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lexel/cases/plot/axes.h"
#include "lexel/flatland/scene.h"

namespace lexel::cases {

namespace {

using flatland::Vec2;
using plot::DecadeRange;
using plot::DrawAxesFrame;
using plot::DrawLegend;
using plot::DrawLogYTicks;
using plot::FormatTick;
using plot::GridLine;
using plot::NiceStep;
using plot::PxRect;
using plot::RenderPng;
using plot::Rgb;
using plot::SetColour;
using plot::SetFont;
using plot::ShowText;
using plot::TickMark;

// The x pixel of a value on the log axis [lo, hi] (decimal logs).
struct LogAxis {
    double lo = 0.0, hi = 1.0;
    double Px(const PxRect& plot, double x) const {
        return plot.x + (std::log10(x) - lo) / (hi - lo) * plot.width;
    }
};

void DrawXTicks(cairo_t* cr, const PxRect& plot, const LogAxis& axis,
                const std::vector<double>& xTicks) {
    if (!xTicks.empty()) {
        for (double x : xTicks) {
            GridLine(cr, axis.Px(plot, x), plot.y, axis.Px(plot, x), plot.Bottom());
            TickMark(cr, axis.Px(plot, x), plot.Bottom(), axis.Px(plot, x), plot.Bottom() + 6);
            ShowText(cr, axis.Px(plot, x), plot.Bottom() + 10, FormatTick(x), 0.5, 0);
        }
        return;
    }
    const int decadeLo = static_cast<int>(axis.lo), decadeHi = static_cast<int>(axis.hi);
    for (int d = decadeLo; d <= decadeHi; ++d) {
        const double x = std::pow(10.0, d);
        if (d > decadeLo && d < decadeHi)
            GridLine(cr, axis.Px(plot, x), plot.y, axis.Px(plot, x), plot.Bottom());
        TickMark(cr, axis.Px(plot, x), plot.Bottom(), axis.Px(plot, x), plot.Bottom() + 6);
        ShowText(cr, axis.Px(plot, x), plot.Bottom() + 10, FormatTick(x), 0.5, 0);
        if (d == decadeHi) break;
        for (int m = 2; m <= 9; ++m)
            TickMark(cr, axis.Px(plot, m * x), plot.Bottom(), axis.Px(plot, m * x),
                     plot.Bottom() + 3);
    }
}

void DrawGuide(cairo_t* cr, const PxRect& plot, double pxY, const std::string& label) {
    const double dashes[] = {6.0, 4.0};
    cairo_set_dash(cr, dashes, 2, 0);
    cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
    cairo_set_line_width(cr, 1.2);
    cairo_move_to(cr, plot.x, pxY);
    cairo_line_to(cr, plot.Right(), pxY);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    SetFont(cr, 13);
    ShowText(cr, plot.x + 8, pxY - 4, label, 0, 1);
}

// One curve as a polyline with dots, skipping points that cannot be drawn.
template <class PxX, class PxY>
void DrawCurve(cairo_t* cr, const PlotCurve& curve, Rgb colour, PxX pxX, PxY pxY) {
    SetColour(cr, colour);
    cairo_set_line_width(cr, 2);
    std::vector<Vec2> pxPoints;
    for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i)
        if (curve.x[i] > 0 && std::isfinite(curve.x[i]) && std::isfinite(curve.y[i]))
            pxPoints.emplace_back(pxX(curve.x[i]), pxY(curve.y[i]));
    for (std::size_t i = 0; i < pxPoints.size(); ++i) {
        if (i == 0)
            cairo_move_to(cr, pxPoints[i].x(), pxPoints[i].y());
        else
            cairo_line_to(cr, pxPoints[i].x(), pxPoints[i].y());
    }
    cairo_stroke(cr);
    for (const Vec2& px : pxPoints) {
        cairo_arc(cr, px.x(), px.y(), 3.5, 0, 2 * std::numbers::pi);
        cairo_fill(cr);
    }
}

// Linear x axis [lo, hi] with about 8 ticks at round values.
void DrawLinearXTicks(cairo_t* cr, const PxRect& plot, double lo, double hi) {
    const auto px = [&](double x) { return plot.x + (x - lo) / (hi - lo) * plot.width; };
    const double step = NiceStep((hi - lo) / 8);
    for (double x = std::ceil(lo / step - 1e-9) * step; x <= hi + 1e-9 * step; x += step) {
        const double value = std::abs(x) < 1e-9 * step ? 0.0 : x;
        if (px(x) > plot.x + 1 && px(x) < plot.Right() - 1)
            GridLine(cr, px(x), plot.y, px(x), plot.Bottom());
        TickMark(cr, px(x), plot.Bottom(), px(x), plot.Bottom() + 6);
        ShowText(cr, px(x), plot.Bottom() + 10, FormatTick(value), 0.5, 0);
    }
}

// Linear y axis [0, yHi] with about 6 ticks at round values.
template <class PxY>
void DrawLinearYTicks(cairo_t* cr, const PxRect& plot, double yHi, PxY pxY) {
    const double yStep = NiceStep(yHi / 6);
    for (double y = 0; y <= yHi + 1e-9; y += yStep) {
        if (y > 0) GridLine(cr, plot.x, pxY(y), plot.Right(), pxY(y));
        TickMark(cr, plot.x - 6, pxY(y), plot.x, pxY(y));
        ShowText(cr, plot.x - 10, pxY(y), FormatTick(y), 1, 0.5);
    }
}

// The figure's guide line and curves clipped to the plot, then its frame and legend;
// drawOne(curve, colour) draws one curve.
template <class PxY, class DrawOne>
void DrawCurvesInFrame(cairo_t* cr, const PxRect& plot, const CurvePlot& figure, PxY pxY,
                       DrawOne drawOne) {
    cairo_save(cr);
    cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
    cairo_clip(cr);
    if (figure.guideY) DrawGuide(cr, plot, pxY(*figure.guideY), figure.guideLabel);
    std::vector<std::string> labels;
    std::vector<Rgb> colours;
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (std::size_t c = 0; c < figure.curves.size(); ++c) {
        labels.push_back(figure.curves[c].label);
        colours.push_back(plot::PaletteColour(c));
        drawOne(figure.curves[c], colours.back());
    }
    cairo_restore(cr);
    DrawAxesFrame(cr, plot, figure.xLabel, figure.yLabel);
    DrawLegend(cr, plot, labels, colours, true);
}

// The same plot with a linear x or a log y axis (WriteCurvePlot's other cases).
// The range of the points a plot can draw (finite, positive on a log axis) and its guide; x is
// [0, 1] when the points span no x.
struct DataRange {
    double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
    double yMin = std::numeric_limits<double>::infinity(), yMax = -yMin;
};
DataRange DrawableRange(const CurvePlot& figure) {
    DataRange r;
    for (const PlotCurve& curve : figure.curves)
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i) {
            const double x = curve.x[i], y = curve.y[i];
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            if ((figure.logX && !(x > 0)) || (figure.logY && !(y > 0))) continue;
            r.xMin = std::min(r.xMin, x), r.xMax = std::max(r.xMax, x);
            r.yMin = std::min(r.yMin, y), r.yMax = std::max(r.yMax, y);
        }
    if (figure.guideY)
        r.yMin = std::min(r.yMin, *figure.guideY), r.yMax = std::max(r.yMax, *figure.guideY);
    if (!(r.xMax > r.xMin)) r.xMin = 0.0, r.xMax = 1.0;
    return r;
}

void WriteCurvePlotScaled(const std::string& pngPath, const CurvePlot& figure) {
    constexpr int kPxWidth = 900, kPxHeight = 600;
    const PxRect plot{95, 55, 775, 460};
    const DataRange range = DrawableRange(figure);
    const double xMin = range.xMin, xMax = range.xMax, yMin = range.yMin, yMax = range.yMax;
    LogAxis logX;
    if (figure.logX && !figure.xTicks.empty()) {
        const auto [lo, hi] = std::minmax_element(figure.xTicks.begin(), figure.xTicks.end());
        logX = {std::log10(*lo) - 0.05, std::log10(*hi) + 0.05};
    } else if (figure.logX) {
        const auto [lo, hi] = DecadeRange(xMin, xMax).value_or(std::make_pair(0, 1));
        logX = {static_cast<double>(lo), static_cast<double>(hi)};
    }
    const auto pxX = [&](double x) {
        return figure.logX ? logX.Px(plot, x) : plot.x + (x - xMin) / (xMax - xMin) * plot.width;
    };
    double yLo = 0.0, yHi = std::max(1.0, yMax * 1.1);
    if (figure.logY) {
        const auto [lo, hi] = DecadeRange(yMin, yMax).value_or(std::make_pair(0, 1));
        yLo = lo, yHi = hi;
    }
    const auto pxY = [&](double y) {
        const double v = figure.logY ? std::log10(y) : y;
        return plot.Bottom() - (v - yLo) / (yHi - yLo) * plot.height;
    };
    RenderPng(pngPath, kPxWidth, kPxHeight, [&](cairo_t* cr) {
        SetFont(cr, 18, true);
        cairo_set_source_rgb(cr, 0, 0, 0);
        ShowText(cr, kPxWidth / 2.0, 16, figure.title, 0.5, 0);
        SetFont(cr, 13);
        if (figure.logY) {
            DrawLogYTicks(cr, plot, static_cast<int>(yLo), static_cast<int>(yHi));
        } else {
            DrawLinearYTicks(cr, plot, yHi, pxY);
        }
        SetFont(cr, 13);
        if (figure.logX)
            DrawXTicks(cr, plot, logX, figure.xTicks);
        else
            DrawLinearXTicks(cr, plot, xMin, xMax);
        DrawCurvesInFrame(cr, plot, figure, pxY, [&](const PlotCurve& curve, Rgb colour) {
            PlotCurve drawable = curve;
            // DrawCurve skips x ≤ 0; on a linear x axis shift by the axis origin instead.
            if (!figure.logX)
                for (double& x : drawable.x) x = x - xMin + 1.0;
            const auto pxShifted = [&](double x) {
                return figure.logX ? pxX(x) : pxX(x - 1.0 + xMin);
            };
            if (figure.logY)
                for (double& y : drawable.y)
                    if (!(y > 0)) y = std::numeric_limits<double>::quiet_NaN();
            DrawCurve(cr, drawable, colour, pxShifted, pxY);
        });
    });
}

}  // namespace

void WriteCurvePlot(const std::string& pngPath, const CurvePlot& figure) {
    if (!figure.logX || figure.logY) return WriteCurvePlotScaled(pngPath, figure);
    constexpr int kPxWidth = 900, kPxHeight = 600;
    const PxRect plot{95, 55, 775, 460};
    double xMin = std::numeric_limits<double>::infinity(), xMax = 0.0, yMax = 0.0;
    for (const PlotCurve& curve : figure.curves)
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i) {
            const double x = curve.x[i], y = curve.y[i];
            if (!(x > 0) || !std::isfinite(x) || !std::isfinite(y)) continue;
            xMin = std::min(xMin, x), xMax = std::max(xMax, x), yMax = std::max(yMax, y);
        }
    LogAxis axis;
    if (!figure.xTicks.empty()) {
        const auto [lo, hi] = std::minmax_element(figure.xTicks.begin(), figure.xTicks.end());
        axis = {std::log10(*lo) - 0.05, std::log10(*hi) + 0.05};
    } else {
        const auto [decadeLo, decadeHi] = DecadeRange(xMin, xMax).value_or(std::make_pair(1, 3));
        axis = {static_cast<double>(decadeLo), static_cast<double>(decadeHi)};
    }
    if (figure.guideY) yMax = std::max(yMax, *figure.guideY);
    yMax = std::max(1.0, yMax * 1.1);
    const auto pxX = [&](double x) { return axis.Px(plot, x); };
    const auto pxY = [&](double y) { return plot.Bottom() - y / yMax * plot.height; };

    RenderPng(pngPath, kPxWidth, kPxHeight, [&](cairo_t* cr) {
        SetFont(cr, 18, true);
        cairo_set_source_rgb(cr, 0, 0, 0);
        ShowText(cr, kPxWidth / 2.0, 16, figure.title, 0.5, 0);
        SetFont(cr, 13);
        DrawLinearYTicks(cr, plot, yMax, pxY);
        DrawXTicks(cr, plot, axis, figure.xTicks);
        DrawCurvesInFrame(cr, plot, figure, pxY, [&](const PlotCurve& curve, Rgb colour) {
            DrawCurve(cr, curve, colour, pxX, pxY);
        });
    });
}

void WriteLowresPlot(const std::string& pngPath, const std::string& title,
                     const std::vector<LowresCurve>& curves) {
    CurvePlot figure;
    figure.title = title;
    figure.xLabel = "decision pixels K";
    figure.yLabel = "additional error (%)";
    for (const LowresCurve& c : curves)
        figure.curves.push_back({c.label, c.pixels, c.extraPercent});
    // The thesis's threshold for "low resolution is good enough"; off-scale when every curve
    // stays well below it.
    double yMax = 0.0;
    for (const LowresCurve& c : curves)
        for (double y : c.extraPercent)
            if (std::isfinite(y)) yMax = std::max(yMax, y);
    if (std::max(1.0, yMax * 1.1) >= 5.0) {
        figure.guideY = 5.0;
        figure.guideLabel = "5%";
    }
    WriteCurvePlot(pngPath, figure);
}

}  // namespace lexel::cases
