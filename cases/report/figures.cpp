#include "lexel/cases/report/figures.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <tuple>

#include "lexel/flatland/scene.h"
#include "lexel/solvers/geometry.h"

namespace lexel::cases {

namespace {

using flatland::Vec2;

struct Rgb {
    double r, g, b;
};

// Tableau-like colours, reordered so the first methods avoid the camera's blue and the light's
// yellow; twelve so that all eleven flatland methods get their own. Later ones reuse them.
constexpr std::array<Rgb, 12> kPalette = {{{0.84, 0.15, 0.16},
                                           {0.17, 0.63, 0.17},
                                           {0.58, 0.40, 0.74},
                                           {1.00, 0.50, 0.05},
                                           {0.09, 0.75, 0.81},
                                           {0.89, 0.47, 0.76},
                                           {0.55, 0.34, 0.29},
                                           {0.74, 0.74, 0.13},
                                           {0.12, 0.47, 0.71},
                                           {0.50, 0.50, 0.50},
                                           {0.00, 0.45, 0.45},
                                           {0.55, 0.00, 0.35}}};
constexpr Rgb kCameraColour{0.10, 0.30, 0.85};
constexpr Rgb kGeometryColour{0.25, 0.25, 0.25};

constexpr int kFanRays = 12;       // lexel rays per (unsplit) method
constexpr int kMaxFanMethods = 5;  // more fans than this turn the diagram into noise

Rgb MethodColour(std::size_t index) { return kPalette[index % kPalette.size()]; }

// amount < 0 darkens toward black, > 0 lightens toward white.
Rgb Shade(Rgb c, double amount) {
    const double target = amount < 0 ? 0.0 : 1.0, t = std::abs(amount);
    return {c.r + (target - c.r) * t, c.g + (target - c.g) * t, c.b + (target - c.b) * t};
}

void SetColour(cairo_t* cr, Rgb c, double alpha = 1.0) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

struct PxRect {
    double x, y, width, height;  // top-left corner, device pixels
    double Right() const { return x + width; }
    double Bottom() const { return y + height; }
};

// Text anchored at (pxX, pxY): alignX 0/0.5/1 puts the left/centre/right of the ink there,
// alignY 0/0.5/1 its top/middle/bottom.
void ShowText(cairo_t* cr, double pxX, double pxY, const std::string& text, double alignX,
              double alignY) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, pxX - alignX * extents.width - extents.x_bearing,
                  pxY - alignY * extents.height - extents.y_bearing);
    cairo_show_text(cr, text.c_str());
}

void SetFont(cairo_t* cr, double size, bool bold = false) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
}

std::string FormatTick(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

// 1, 2 or 5 times a power of ten, near `rough`.
double NiceStep(double rough) {
    if (!(rough > 0) || !std::isfinite(rough)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(rough)));
    const double m = rough / decade;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * decade;
}

// Whole decades [lo, hi] of log10 covering the positive finite values; nullopt if there are none.
std::optional<std::pair<int, int>> DecadeRange(double minValue, double maxValue) {
    if (!(minValue > 0) || !std::isfinite(maxValue) || maxValue < minValue) return std::nullopt;
    int lo = static_cast<int>(std::floor(std::log10(minValue) + 1e-9));
    int hi = static_cast<int>(std::ceil(std::log10(maxValue) - 1e-9));
    if (hi <= lo) hi = lo + 1;
    return std::make_pair(lo, hi);
}

// A legend box in the top-right corner of `plot`.
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

// Frame and axis labels around `plot`; ticks are drawn by the callers.
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

// Ticks are black, grid lines a grey light enough to stay behind the data.
void StrokeSegment(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1, double grey) {
    cairo_set_source_rgb(cr, grey, grey, grey);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, pxX0, pxY0);
    cairo_line_to(cr, pxX1, pxY1);
    cairo_stroke(cr);
}
void TickMark(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1) {
    StrokeSegment(cr, pxX0, pxY0, pxX1, pxY1, 0.0);
}
void GridLine(cairo_t* cr, double pxX0, double pxY0, double pxX1, double pxY1) {
    StrokeSegment(cr, pxX0, pxY0, pxX1, pxY1, 0.88);
}

// Log-scale y ticks at whole decades, light grid lines at each.
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

// Builds a surface, lets `draw` paint it, and writes it as PNG through a temporary file and a
// rename, so a reader never sees a half-written figure and a failed write leaves nothing behind.
template <typename Draw>
void RenderPng(const std::string& pngPath, int pxWidth, int pxHeight, Draw&& draw) {
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_RGB24, pxWidth, pxHeight), cairo_surface_destroy);
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> context(cairo_create(surface.get()),
                                                                     cairo_destroy);
    cairo_t* cr = context.get();
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_BEST);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    draw(cr);
    cairo_status_t status = cairo_status(cr);
    if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface.get());
    if (status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(pngPath + ": " + cairo_status_to_string(status));
    cairo_surface_flush(surface.get());
    const std::string partialPath = pngPath + ".partial.png";
    status = cairo_surface_write_to_png(surface.get(), partialPath.c_str());
    std::error_code ignored;
    if (status != CAIRO_STATUS_SUCCESS) {
        std::filesystem::remove(partialPath, ignored);
        throw std::runtime_error(pngPath + ": " + cairo_status_to_string(status));
    }
    std::error_code error;
    std::filesystem::rename(partialPath, pngPath, error);
    if (error) {
        std::filesystem::remove(partialPath, ignored);
        throw std::runtime_error(pngPath + ": " + error.message());
    }
}

// ----- the case diagram -------------------------------------------------------------------------

// World space to device pixels with equal aspect ratio and y up.
struct WorldView {
    Vec2 wsMin{0, 0}, wsMax{1, 1};  // the world rectangle the panel shows
    double scale = 1.0;             // pixels per world unit
    PxRect panel{0, 0, 1, 1};

    Vec2 ToPx(const Vec2& ws) const {
        return {panel.x + (ws.x() - wsMin.x()) * scale,
                panel.Bottom() - (ws.y() - wsMin.y()) * scale};
    }
    // Ray parameter at which origin + t·direction leaves the shown rectangle (origin inside).
    double ExitT(const Vec2& wsOrigin, const Vec2& wsDirection) const {
        double t = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 2; ++k) {
            if (wsDirection[k] > 0) t = std::min(t, (wsMax[k] - wsOrigin[k]) / wsDirection[k]);
            if (wsDirection[k] < 0) t = std::min(t, (wsMin[k] - wsOrigin[k]) / wsDirection[k]);
        }
        return std::isfinite(t) ? std::max(t, 0.0) : 0.0;
    }
};

WorldView FitView(const flatland::FlatScene& scene, const flatland::SamplingPass& pass,
                  const PxRect& panel) {
    Vec2 wsLo = scene.wsLight.cwiseMin(scene.camera.wsPosition);
    Vec2 wsHi = scene.wsLight.cwiseMax(scene.camera.wsPosition);
    for (const auto& s : pass.samples)
        wsLo = wsLo.cwiseMin(s.wsPoint), wsHi = wsHi.cwiseMax(s.wsPoint);
    // Geometry widens the box by at most half the extent of what the camera and the light see: a
    // long ground line would otherwise shrink the interesting part to a few pixels. The panel
    // clips what lies beyond.
    const double wsReach = 0.5 * std::max((wsHi - wsLo).maxCoeff(), 1e-6);
    const Vec2 wsCapLo = wsLo - Vec2(wsReach, wsReach), wsCapHi = wsHi + Vec2(wsReach, wsReach);
    for (const auto& polyline : scene.geometry)
        for (const Vec2& p : polyline) {
            const Vec2 wsP = p.cwiseMax(wsCapLo).cwiseMin(wsCapHi);
            wsLo = wsLo.cwiseMin(wsP), wsHi = wsHi.cwiseMax(wsP);
        }
    // A margin of 6% of the larger extent keeps the light disc and the camera inside the panel.
    const double wsMargin = 0.06 * std::max({wsHi.x() - wsLo.x(), wsHi.y() - wsLo.y(), 1e-6});
    wsLo -= Vec2(wsMargin, wsMargin);
    wsHi += Vec2(wsMargin, wsMargin);
    WorldView view;
    view.panel = panel;
    view.scale =
        std::min(panel.width / (wsHi.x() - wsLo.x()), panel.height / (wsHi.y() - wsLo.y()));
    // Centre the box in the panel; the shown rectangle is the whole panel in world units.
    const Vec2 wsCentre = 0.5 * (wsLo + wsHi);
    const Vec2 wsHalf(0.5 * panel.width / view.scale, 0.5 * panel.height / view.scale);
    view.wsMin = wsCentre - wsHalf;
    view.wsMax = wsCentre + wsHalf;
    return view;
}

// Where a ray from the light first meets the geometry, or where it leaves the view.
Vec2 TraceRay(const WorldView& view, const std::vector<flatland::FlatSegment>& segments,
              const Vec2& wsOrigin, const Vec2& wsDirection) {
    double tBest = view.ExitT(wsOrigin, wsDirection);
    for (const auto& segment : segments) {
        const Vec2 e = segment.b - segment.a;
        const double denominator = Cross(wsDirection, e);
        if (std::abs(denominator) < 1e-12) continue;
        const Vec2 offset = segment.a - wsOrigin;
        const double t = Cross(offset, e) / denominator;
        const double u = Cross(offset, wsDirection) / denominator;
        if (t > 1e-9 && u >= 0 && u <= 1) tBest = std::min(tBest, t);
    }
    return wsOrigin + tBest * wsDirection;
}

void StrokeWorldLine(cairo_t* cr, const WorldView& view, const Vec2& wsA, const Vec2& wsB) {
    const Vec2 pxA = view.ToPx(wsA), pxB = view.ToPx(wsB);
    cairo_move_to(cr, pxA.x(), pxA.y());
    cairo_line_to(cr, pxB.x(), pxB.y());
    cairo_stroke(cr);
}

// One lexel plane with its optical axis and, optionally, a fan of lexel rays. The film
// coordinate s of a ray is its offset along the plane per unit distance along the axis, so the
// ray direction is a + s·b and it crosses a plane at distance D at light + D·(a + s·b).
struct PlaneDrawing {
    double wsAxis = 0.0;
    double sLow = 0.0, sHigh = 0.0;  // film extent of the lexels
    int rays = kFanRays;
    Rgb colour{0, 0, 0};
};

void DrawPlaneAndFan(cairo_t* cr, const WorldView& view, const flatland::FlatScene& scene,
                     const std::vector<flatland::FlatSegment>& segments, const PlaneDrawing& plane,
                     double wsDistance, bool withFan) {
    const Vec2 a(std::cos(plane.wsAxis), std::sin(plane.wsAxis));
    const Vec2 b(-a.y(), a.x());
    const Vec2& wsLight = scene.wsLight;
    if (withFan) {
        SetColour(cr, plane.colour, 0.55);
        cairo_set_line_width(cr, 0.7);
        for (int k = 0; k < plane.rays; ++k) {
            const double s = plane.rays == 1
                                 ? 0.5 * (plane.sLow + plane.sHigh)
                                 : plane.sLow + (plane.sHigh - plane.sLow) * k / (plane.rays - 1);
            StrokeWorldLine(cr, view, wsLight, TraceRay(view, segments, wsLight, a + s * b));
        }
    }
    const Vec2 wsCentre = wsLight + wsDistance * a;
    cairo_set_line_width(cr, 0.8);
    SetColour(cr, plane.colour, 0.8);
    const double dashes[] = {3.0, 3.0};
    cairo_set_dash(cr, dashes, 2, 0);
    StrokeWorldLine(cr, view, wsLight, wsCentre);
    cairo_set_dash(cr, nullptr, 0, 0);
    // Short: it spans the lexels' film extent, but always shows a little plane around the axis and
    // stops at 45° either side so an oblique frustum's plane does not cross the whole diagram.
    const double sLo = std::clamp(std::min(plane.sLow, -0.3), -1.0, 0.0);
    const double sHi = std::clamp(std::max(plane.sHigh, 0.3), 0.0, 1.0);
    SetColour(cr, plane.colour);
    cairo_set_line_width(cr, 2.5);
    StrokeWorldLine(cr, view, wsCentre + wsDistance * sLo * b, wsCentre + wsDistance * sHi * b);
}

// Film extent of the visible points for a plane with optical axis wsAxis.
std::pair<double, double> FilmExtent(const flatland::FlatScene& scene,
                                     const flatland::SamplingPass& pass, double wsAxis) {
    const Vec2 a(std::cos(wsAxis), std::sin(wsAxis)), b(-a.y(), a.x());
    double sLow = std::numeric_limits<double>::infinity(), sHigh = -sLow;
    for (const auto& sample : pass.samples) {
        const Vec2 d = sample.wsPoint - scene.wsLight;
        if (d.dot(a) <= 0) continue;  // behind the plane: no lexel sees it
        const double s = d.dot(b) / d.dot(a);
        sLow = std::min(sLow, s), sHigh = std::max(sHigh, s);
    }
    if (sLow > sHigh) return {0.0, 0.0};
    return {sLow, sHigh};
}

void DrawDiagram(cairo_t* cr, const PxRect& panel, const flatland::FlatScene& scene,
                 const flatland::CaseReport& report) {
    const flatland::SamplingPass& pass = *report.fullPass;
    const WorldView view = FitView(scene, pass, panel);
    const auto segments = flatland::Segments(scene);
    cairo_save(cr);
    cairo_rectangle(cr, panel.x, panel.y, panel.width, panel.height);
    cairo_clip(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);

    // Lexel fans first so the geometry, camera and light stay on top of them.
    const double pxPlaneDistance = 45, pxPlaneStagger = 12;
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
        const auto& method = report.methods[m];
        const bool withFan = m < kMaxFanMethods;
        // Staggered distances keep planes of methods with similar axes apart.
        const double wsDistance = (pxPlaneDistance + pxPlaneStagger * m) / view.scale;
        if (method.frusta.empty()) {
            PlaneDrawing plane{method.wsAxis, 0, 0, kFanRays, MethodColour(m)};
            std::tie(plane.sLow, plane.sHigh) = FilmExtent(scene, pass, method.wsAxis);
            DrawPlaneAndFan(cr, view, scene, segments, plane, wsDistance, withFan);
            continue;
        }
        // Every Nth lexel across the whole split, so denser frusta get denser fans.
        int totalLexels = 0;
        for (const auto& frustum : method.frusta) totalLexels += frustum.lexels;
        const std::size_t count = method.frusta.size();
        for (std::size_t j = 0; j < count; ++j) {
            const auto& frustum = method.frusta[j];
            const double shade = count == 1 ? 0.0 : -0.35 + 0.7 * j / (count - 1.0);
            const int rays =
                totalLexels > 0
                    ? std::max(3, static_cast<int>(std::lround(static_cast<double>(kFanRays) *
                                                               frustum.lexels / totalLexels)))
                    : kFanRays;
            const double rayLow = Radians(frustum.wsRayLowDeg);
            const double rayHigh = Radians(frustum.wsRayHighDeg);
            PlaneDrawing plane{frustum.wsAxis,
                               std::tan(flatland::WrapAngle(rayLow - frustum.wsAxis)),
                               std::tan(flatland::WrapAngle(rayHigh - frustum.wsAxis)), rays,
                               Shade(MethodColour(m), shade)};
            if (plane.sLow > plane.sHigh) std::swap(plane.sLow, plane.sHigh);
            DrawPlaneAndFan(cr, view, scene, segments, plane, wsDistance, withFan);
        }
    }

    SetColour(cr, kGeometryColour);
    cairo_set_line_width(cr, 2);
    for (const auto& polyline : scene.geometry) {
        for (std::size_t i = 0; i < polyline.size(); ++i) {
            const Vec2 px = view.ToPx(polyline[i]);
            if (i == 0)
                cairo_move_to(cr, px.x(), px.y());
            else
                cairo_line_to(cr, px.x(), px.y());
        }
        cairo_stroke(cr);
    }

    // Visible points: faint dots show which part of the geometry the camera sees.
    cairo_set_source_rgba(cr, 0, 0, 0, 0.35);
    for (const auto& sample : pass.samples) {
        const Vec2 px = view.ToPx(sample.wsPoint);
        cairo_arc(cr, px.x(), px.y(), 1.2, 0, 2 * std::numbers::pi);
        cairo_fill(cr);
    }

    const flatland::FlatCamera& camera = scene.camera;
    const Vec2 wsDirection = camera.wsDirection.normalized();
    const double halfFov = Radians(0.5 * camera.fovDeg);
    SetColour(cr, kCameraColour);
    cairo_set_line_width(cr, 1.5);
    for (const double side : {-1.0, 1.0}) {
        const double angle = std::atan2(wsDirection.y(), wsDirection.x()) + side * halfFov;
        const Vec2 wsEdge(std::cos(angle), std::sin(angle));
        StrokeWorldLine(cr, view, camera.wsPosition,
                        camera.wsPosition + view.ExitT(camera.wsPosition, wsEdge) * wsEdge);
    }
    // A camera body behind the pinhole, its apex at the camera position where the frustum edges
    // start; sized in pixels so it reads the same at any world scale. y flips on screen.
    const Vec2 pxApex = view.ToPx(camera.wsPosition);
    const Vec2 pxForward(wsDirection.x(), -wsDirection.y()), pxSide(-pxForward.y(), pxForward.x());
    const Vec2 pxBaseA = pxApex - 18 * pxForward + 8 * pxSide;
    const Vec2 pxBaseB = pxApex - 18 * pxForward - 8 * pxSide;
    cairo_move_to(cr, pxApex.x(), pxApex.y());
    cairo_line_to(cr, pxBaseA.x(), pxBaseA.y());
    cairo_line_to(cr, pxBaseB.x(), pxBaseB.y());
    cairo_close_path(cr);
    cairo_fill(cr);

    const Vec2 pxLight = view.ToPx(scene.wsLight);
    cairo_arc(cr, pxLight.x(), pxLight.y(), 8, 0, 2 * std::numbers::pi);
    cairo_set_source_rgb(cr, 1.0, 0.78, 0.1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
    cairo_restore(cr);
}

// ----- the footprint plot -----------------------------------------------------------------------

void DrawFootprints(cairo_t* cr, const PxRect& plot, const flatland::CaseReport& report) {
    const auto& samples = report.fullPass->samples;
    double fMin = std::numeric_limits<double>::infinity(), fMax = 0.0;
    for (const auto& method : report.methods)
        for (double f : method.footprints)
            if (f > 0 && std::isfinite(f)) fMin = std::min(fMin, f), fMax = std::max(fMax, f);
    // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
    const std::pair<int, int> decades = DecadeRange(fMin, fMax).value_or(std::make_pair(-1, 1));
    const int decadeLo = decades.first, decadeHi = decades.second;
    const double pixels = std::max(report.pixels, 1);
    const auto pxX = [&](double p) { return plot.x + p / pixels * plot.width; };
    const auto pxY = [&](double f) {
        return plot.Bottom() - (std::log10(f) - decadeLo) / (decadeHi - decadeLo) * plot.height;
    };

    DrawLogYTicks(cr, plot, decadeLo, decadeHi);
    const double xStep = NiceStep(pixels / 5);
    SetFont(cr, 13);
    for (double p = 0; p <= pixels + 1e-9; p += xStep) {
        if (p > 0 && p < pixels) GridLine(cr, pxX(p), plot.y, pxX(p), plot.Bottom());
        TickMark(cr, pxX(p), plot.Bottom(), pxX(p), plot.Bottom() + 6);
        ShowText(cr, pxX(p), plot.Bottom() + 10, FormatTick(p), 0.5, 0);
    }

    cairo_save(cr);
    cairo_rectangle(cr, plot.x, plot.y, plot.width, plot.height);
    cairo_clip(cr);
    cairo_set_line_width(cr, 1.6);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    std::vector<std::string> labels;
    std::vector<Rgb> colours;
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
        const auto& method = report.methods[m];
        labels.push_back(method.method);
        colours.push_back(MethodColour(m));
        SetColour(cr, colours.back());
        const std::size_t count = std::min(method.footprints.size(), samples.size());
        bool drawing = false;
        for (std::size_t i = 0; i < count; ++i) {
            const double f = method.footprints[i];
            if (!(f > 0) || !std::isfinite(f)) {
                drawing = false;
                continue;
            }
            // A gap in pixel index means the geometry was not seen there: break the line.
            const bool adjacent = i > 0 && samples[i].pixel == samples[i - 1].pixel + 1;
            if (drawing && adjacent)
                cairo_line_to(cr, pxX(flatland::PixelCenter(samples[i])), pxY(f));
            else
                cairo_move_to(cr, pxX(flatland::PixelCenter(samples[i])), pxY(f));
            drawing = true;
        }
        cairo_stroke(cr);
    }
    cairo_restore(cr);
    DrawAxesFrame(cr, plot, "pixel", "footprint dp/dl (pixels per lexel)");
    DrawLegend(cr, plot, labels, colours, false);
}

}  // namespace

void WriteCaseFigure(const std::string& pngPath, const flatland::FlatScene& scene,
                     const flatland::CaseReport& report) {
    if (!report.fullPass)
        throw std::invalid_argument(pngPath + ": the case report has no full-resolution pass");
    for (const auto& method : report.methods)
        if (method.footprints.size() != report.fullPass->samples.size())
            throw std::invalid_argument(pngPath + ": method " + method.method +
                                        " kept no footprints (RunFlatlandCase keepFootprints)");
    constexpr int kPxWidth = 1600, kPxHeight = 700;
    RenderPng(pngPath, kPxWidth, kPxHeight, [&](cairo_t* cr) {
        SetFont(cr, 20, true);
        cairo_set_source_rgb(cr, 0, 0, 0);
        ShowText(cr, 400, 16, scene.name, 0.5, 0);
        SetFont(cr, 16);
        ShowText(cr, 1210, 18,
                 "footprints at full resolution (" + std::to_string(report.pixelsVisible) + " of " +
                     std::to_string(report.pixels) + " pixels visible, " +
                     std::to_string(report.lexels) + " lexels)",
                 0.5, 0);
        const PxRect diagram{20, 50, 760, 630};
        cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
        cairo_set_line_width(cr, 1);
        cairo_rectangle(cr, diagram.x - 0.5, diagram.y - 0.5, diagram.width + 1,
                        diagram.height + 1);
        cairo_stroke(cr);
        DrawDiagram(cr, diagram, scene, report);
        DrawFootprints(cr, PxRect{895, 50, 680, 580}, report);
    });
}

namespace {

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

}  // namespace

namespace {

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
        colours.push_back(MethodColour(c));
        drawOne(figure.curves[c], colours.back());
    }
    cairo_restore(cr);
    DrawAxesFrame(cr, plot, figure.xLabel, figure.yLabel);
    DrawLegend(cr, plot, labels, colours, true);
}

// The same plot with a linear x or a log y axis (WriteCurvePlot's other cases).
void WriteCurvePlotScaled(const std::string& pngPath, const CurvePlot& figure) {
    constexpr int kPxWidth = 900, kPxHeight = 600;
    const PxRect plot{95, 55, 775, 460};
    double xMin = std::numeric_limits<double>::infinity(), xMax = -xMin;
    double yMin = std::numeric_limits<double>::infinity(), yMax = -yMin;
    for (const PlotCurve& curve : figure.curves)
        for (std::size_t i = 0; i < std::min(curve.x.size(), curve.y.size()); ++i) {
            const double x = curve.x[i], y = curve.y[i];
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            if ((figure.logX && !(x > 0)) || (figure.logY && !(y > 0))) continue;
            xMin = std::min(xMin, x), xMax = std::max(xMax, x);
            yMin = std::min(yMin, y), yMax = std::max(yMax, y);
        }
    if (figure.guideY) yMin = std::min(yMin, *figure.guideY), yMax = std::max(yMax, *figure.guideY);
    if (!(xMax > xMin)) xMin = 0.0, xMax = 1.0;
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

// ----- image figures ----------------------------------------------------------------------------

namespace {

constexpr int kFigureMargin = 16;
constexpr int kFigureMinWidth = 720;
constexpr int kFigureTargetSide = 600;  // small pictures are scaled up toward this side
constexpr double kTitleSize = 17, kTextSize = 13;
constexpr double kLineGap = 5;             // between text lines
constexpr int kSwatch = 14, kKeyRow = 22;  // key swatches and rows
constexpr int kBarWidth = 320, kBarHeight = 14;

// `text` cut at spaces into lines no wider than `pxWidth` in the context's current font.
std::vector<std::string> WrapToWidth(cairo_t* cr, const std::string& text, double pxWidth) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        start = end + 1;
        const std::string candidate = line.empty() ? word : line + " " + word;
        cairo_text_extents_t extents;
        cairo_text_extents(cr, candidate.c_str(), &extents);
        if (!line.empty() && extents.x_advance > pxWidth) {
            lines.push_back(line);
            line = word;
        } else {
            line = candidate;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

// Text with its origin at pxX and the font's ascent below pxTop, so lines align by their
// baselines whatever their ink; centred on pxY when `centreY`.
void ShowLine(cairo_t* cr, double pxX, double pxY, const std::string& text, bool centreY = false) {
    cairo_font_extents_t font;
    cairo_font_extents(cr, &font);
    cairo_move_to(cr, pxX, centreY ? pxY + (font.ascent - font.descent) / 2 : pxY + font.ascent);
    cairo_show_text(cr, text.c_str());
}

double TextWidth(cairo_t* cr, const std::string& text) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    return extents.x_advance;
}

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
