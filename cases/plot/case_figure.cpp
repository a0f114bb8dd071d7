#include "lexel/cases/plot/case_figure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "lexel/cases/plot/axes.h"
#include "lexel/flatland/scene.h"
#include "lexel/solvers/geometry.h"

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
using plot::Shade;
using plot::ShowText;
using plot::TickMark;

constexpr Rgb kCameraColour{0.10, 0.30, 0.85};
constexpr Rgb kGeometryColour{0.25, 0.25, 0.25};

constexpr int kFanRays = 12;       // lexel rays per (unsplit) method
constexpr int kMaxFanMethods = 5;  // more fans than this turn the diagram into noise

Rgb MethodColour(std::size_t index) { return plot::PaletteColour(index); }

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

// One method's lexel plane(s) and fan(s): its single frustum, or each frustum of its split in a
// shade of its colour with rays in proportion to its lexels (every Nth lexel across the split, so
// denser frusta get denser fans).
void DrawMethodPlanes(cairo_t* cr, const WorldView& view, const flatland::FlatScene& scene,
                      const flatland::SamplingPass& pass,
                      const std::vector<flatland::FlatSegment>& segments,
                      const flatland::MethodReport& method, std::size_t m) {
    const bool withFan = m < kMaxFanMethods;
    // Staggered distances keep planes of methods with similar axes apart.
    const double pxPlaneDistance = 45, pxPlaneStagger = 12;
    const double wsDistance = (pxPlaneDistance + pxPlaneStagger * m) / view.scale;
    if (method.frusta.empty()) {
        PlaneDrawing plane{method.wsAxis, 0, 0, kFanRays, MethodColour(m)};
        std::tie(plane.sLow, plane.sHigh) = FilmExtent(scene, pass, method.wsAxis);
        DrawPlaneAndFan(cr, view, scene, segments, plane, wsDistance, withFan);
        return;
    }
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
        PlaneDrawing plane{frustum.wsAxis, std::tan(flatland::WrapAngle(rayLow - frustum.wsAxis)),
                           std::tan(flatland::WrapAngle(rayHigh - frustum.wsAxis)), rays,
                           Shade(MethodColour(m), shade)};
        if (plane.sLow > plane.sHigh) std::swap(plane.sLow, plane.sHigh);
        DrawPlaneAndFan(cr, view, scene, segments, plane, wsDistance, withFan);
    }
}

// The geometry's polylines, then the visible points as faint dots (which part the camera sees).
void DrawGeometry(cairo_t* cr, const WorldView& view, const flatland::FlatScene& scene,
                  const flatland::SamplingPass& pass) {
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
    cairo_set_source_rgba(cr, 0, 0, 0, 0.35);
    for (const auto& sample : pass.samples) {
        const Vec2 px = view.ToPx(sample.wsPoint);
        cairo_arc(cr, px.x(), px.y(), 1.2, 0, 2 * std::numbers::pi);
        cairo_fill(cr);
    }
}

// The camera's frustum edges to the panel's border and a camera body behind the pinhole, its
// apex at the camera position where the edges start; sized in pixels so it reads the same at
// any world scale (y flips on screen).
void DrawCamera(cairo_t* cr, const WorldView& view, const flatland::FlatCamera& camera) {
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
    const Vec2 pxApex = view.ToPx(camera.wsPosition);
    const Vec2 pxForward(wsDirection.x(), -wsDirection.y()), pxSide(-pxForward.y(), pxForward.x());
    const Vec2 pxBaseA = pxApex - 18 * pxForward + 8 * pxSide;
    const Vec2 pxBaseB = pxApex - 18 * pxForward - 8 * pxSide;
    cairo_move_to(cr, pxApex.x(), pxApex.y());
    cairo_line_to(cr, pxBaseA.x(), pxBaseA.y());
    cairo_line_to(cr, pxBaseB.x(), pxBaseB.y());
    cairo_close_path(cr);
    cairo_fill(cr);
}

// The light: a yellow disc outlined in black.
void DrawLight(cairo_t* cr, const WorldView& view, const Vec2& wsLight) {
    const Vec2 pxLight = view.ToPx(wsLight);
    cairo_arc(cr, pxLight.x(), pxLight.y(), 8, 0, 2 * std::numbers::pi);
    cairo_set_source_rgb(cr, 1.0, 0.78, 0.1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);
}

// The case diagram in `panel`: the lexel fans first, so that the geometry, camera and light stay
// on top of them.
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
    for (std::size_t m = 0; m < report.methods.size(); ++m)
        DrawMethodPlanes(cr, view, scene, pass, segments, report.methods[m], m);
    DrawGeometry(cr, view, scene, pass);
    DrawCamera(cr, view, scene.camera);
    DrawLight(cr, view, scene.wsLight);
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

}  // namespace lexel::cases
