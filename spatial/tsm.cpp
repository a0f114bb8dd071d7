// Trapezoidal shadow maps (tsm.h).
#include "lexel/spatial/tsm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/geometry.h"
#include "lexel/spatial/baseline_support.h"

namespace lexel::spatial {

using namespace baseline_detail;

namespace {

// Below this length of the centre line, relative to the points' extent (dimensionless), the view
// axis is seen end on from the light: the trapezoid has no direction (§6 reverts to a box there).
constexpr double kMinCentreLine = 1e-3;
// Below this height or base width, relative to the points' extent, the trapezoid is flat.
constexpr double kMinExtent = 1e-9;

// A glm matrix from three rows (glm is column-major: m[c][r]).
glm::dmat3 FromRows3(const glm::dvec3& r0, const glm::dvec3& r1, const glm::dvec3& r2) {
    glm::dmat3 m;
    for (int c = 0; c < 3; ++c) {
        m[c][0] = r0[c];
        m[c][1] = r1[c];
        m[c][2] = r2[c];
    }
    return m;
}

std::optional<Trapezoid> Fail(std::string* failure, const std::string& why) {
    if (failure) *failure = why;
    return std::nullopt;
}

// The diagonal of the points' bounding box (their extent; > 0 unless all coincide).
double Extent(std::span<const glm::dvec2> points) {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec2& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return glm::length(hi - lo);
}

// N_T in closed form (tsm.h): rows acting on (y, 1).
glm::dmat3 SquareFromPlane(const Trapezoid& t, double sMin, double sMax) {
    const glm::dvec2 lp = Perp(t.l);
    const glm::dvec3 rowA(t.l.x, t.l.y, -glm::dot(t.l, t.q));  // a = l·(y − q)
    const glm::dvec3 rowB(lp.x, lp.y, -glm::dot(lp, t.q));     // b = l⊥·(y − q)
    const double sMid = 0.5 * (sMax + sMin), sHalf = 0.5 * (sMax - sMin);
    const double a = -1.0 - 2.0 * t.eta / t.lambda;
    const double b = 2.0 * t.eta * (t.eta + t.lambda) / t.lambda;
    return FromRows3((rowB - sMid * rowA) / sHalf, a * rowA + glm::dvec3(0.0, 0.0, b), rowA);
}

}  // namespace

glm::dvec2 Trapezoid::ToSquare(const glm::dvec2& y) const {
    const glm::dvec3 h = squareFromPlane * glm::dvec3(y, 1.0);
    return {h.x / h.z, h.y / h.z};
}

std::optional<Trapezoid> FitTrapezoid(std::span<const glm::dvec2> planePoints,
                                      const glm::dvec2& nearPoint, const glm::dvec2& farPoint,
                                      const glm::dvec2& focusPoint, double focusLine,
                                      std::string* failure) {
    if (planePoints.empty()) return Fail(failure, "no points");
    if (!(focusLine > -1.0 && focusLine < 1.0))
        return Fail(failure, "the focus line must lie in (-1, 1)");
    const std::vector<glm::dvec2> hull = ConvexHull(planePoints);
    const double extent = Extent(hull);
    Trapezoid t;
    const glm::dvec2 centreLine = farPoint - nearPoint;
    const double length = glm::length(centreLine);
    if (!(length > kMinCentreLine * extent))
        return Fail(failure, "the centre line is seen end on (view along the light)");
    t.l = centreLine / length;
    // 1. Top and base lines ⊥ l, as distances along l from nearPoint.
    double top = std::numeric_limits<double>::infinity(), base = -top;
    for (const glm::dvec2& p : hull) {
        top = std::min(top, glm::dot(p - nearPoint, t.l));
        base = std::max(base, glm::dot(p - nearPoint, t.l));
    }
    t.lambda = base - top;
    if (!(t.lambda > kMinExtent * extent)) return Fail(failure, "the points span no height");
    // 2. The 80% rule. Without a warp (η → ∞) the focus would sit (1 − ξ)/2 of the way down.
    t.deltaPrime = glm::dot(focusPoint - nearPoint, t.l) - top;
    const double unwarpedLine = 0.5 * (1.0 - focusLine) * t.lambda;
    if (!(t.deltaPrime > 0.0 && t.deltaPrime < unwarpedLine))
        return Fail(failure, "the focus point lies outside (0, " +
                                 std::to_string(0.5 * (1.0 - focusLine)) +
                                 ") of the way from the top line to the base");
    t.eta = t.lambda * t.deltaPrime * (1.0 + focusLine) /
            (t.lambda * (1.0 - focusLine) - 2.0 * t.deltaPrime);
    t.q = nearPoint + (top - t.eta) * t.l;
    // 3. The side lines: the extreme slopes s = b/a of the hull seen from q (a ≥ η > 0).
    const glm::dvec2 lp = Perp(t.l);
    double sMin = std::numeric_limits<double>::infinity(), sMax = -sMin;
    for (const glm::dvec2& p : hull) {
        const double s = glm::dot(p - t.q, lp) / glm::dot(p - t.q, t.l);
        sMin = std::min(sMin, s);
        sMax = std::max(sMax, s);
    }
    const double farDistance = t.eta + t.lambda;
    if (!((sMax - sMin) * farDistance > kMinExtent * extent))
        return Fail(failure, "the points span no width");
    const auto corner = [&](double a, double s) { return t.q + a * (t.l + s * lp); };
    t.t = {corner(farDistance, sMin), corner(farDistance, sMax), corner(t.eta, sMax),
           corner(t.eta, sMin)};
    t.squareFromPlane = SquareFromPlane(t, sMin, sMax);
    return t;
}

namespace {

struct CentreLine {
    glm::dvec3 wsNear, wsFar, wsFocus;
    double zNear = 0.0, zFar = 0.0, zFocus = 0.0;
};

// The view axis at the body's nearest and farthest planar eye depth, and the focus between them.
CentreLine CentreLineOf(const Camera& camera, std::span<const glm::dvec3> wsBody,
                        double focusDepth) {
    CentreLine c;
    c.zNear = std::numeric_limits<double>::infinity();
    c.zFar = -c.zNear;
    const glm::dvec3 view = glm::normalize(camera.target - camera.position);
    for (const glm::dvec3& x : wsBody) {
        const double z = glm::dot(x - camera.position, view);
        c.zNear = std::min(c.zNear, z);
        c.zFar = std::max(c.zFar, z);
    }
    c.zFocus = c.zNear + focusDepth * (c.zFar - c.zNear);
    c.wsNear = camera.position + c.zNear * view;
    c.wsFar = camera.position + c.zFar * view;
    c.wsFocus = camera.position + c.zFocus * view;
    return c;
}

// The trapezoid's map: N_T, the square's half sides grown by `margin`, onto [0, W] × [0, H] (the
// top edge at v = 0), composed with the central projection onto the plane p4·X = 1.
LightMatrix MatrixOf(const Trapezoid& t, const glm::dvec3& p4, Resolution map, double margin) {
    const double sx = 0.5 * map.width / (1.0 + margin), sy = 0.5 * map.height / (1.0 + margin);
    const glm::dmat3 texelFromSquare =
        FromRows3(glm::dvec3(sx, 0.0, 0.5 * map.width), glm::dvec3(0.0, -sy, 0.5 * map.height),
                  glm::dvec3(0.0, 0.0, 1.0));
    const glm::dmat3 r = texelFromSquare * t.squareFromPlane;
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    // Plane-homogeneous coordinates of X are (b1·X, b2·X, p4·X): row k of the light matrix is
    // Σ_j r_kj (b1, b2, p4)_j.
    const auto row = [&](int k) { return r[0][k] * b1 + r[1][k] * b2 + r[2][k] * p4; };
    const glm::dvec3 w = row(2);
    const double norm = glm::length(w);
    return {row(0) / norm, row(1) / norm, w / norm};
}

}  // namespace

TsmFit FitTsm(const BaselineContext& context, TsmBody body, const TsmOptions& options) {
    CheckContext(context);
    const LightSpace& ls = *context.lightSpace;
    TsmFit fit;
    std::vector<glm::dvec3> wsBody;
    double margin = 0.0;
    if (body == TsmBody::kVisible) {
        fit.planeAxis = InitialLightAxis(ls, context.wsBounds, context.wsRelevant);
        const auto hull =
            context.wsRelevantHull.empty() ? context.wsRelevant : context.wsRelevantHull;
        wsBody.assign(hull.begin(), hull.end());
        margin = context.margin;
    } else {
        const NormalAxis axis = ChooseNormalAxis(context);
        fit.planeAxis = axis.p4;
        wsBody = FocusBody(context, axis);
    }
    const char* method = body == TsmBody::kVisible ? "tsm" : "tsm-report";
    const auto fallBack = [&](const std::string& why) {
        fit.fallback = std::string(method) + ": " + why +
                       (body == TsmBody::kVisible ? "; using focused-tight" : "; using focused");
        fit.trapezoid.reset();
        fit.matrix = body == TsmBody::kVisible ? FocusedTightLightMatrix(context)
                                               : FocusedLightMatrix(context);
        return fit;
    };
    if (wsBody.empty()) return fallBack("empty body");
    const CentreLine line = CentreLineOf(context.camera, wsBody, options.focusDepth);
    fit.zNear = line.zNear, fit.zFar = line.zFar, fit.zFocus = line.zFocus;
    std::vector<glm::dvec2> planePoints;
    for (const glm::dvec3& x : wsBody) {
        const glm::dvec3 lsX = ls.ToLight(x);
        if (!InFront(fit.planeAxis, lsX)) return fallBack("a body point is behind the light");
        planePoints.push_back(ProjectToPlane(fit.planeAxis, lsX));
    }
    glm::dvec2 centre[3];
    const glm::dvec3* wsCentre[3] = {&line.wsNear, &line.wsFar, &line.wsFocus};
    for (int i = 0; i < 3; ++i) {
        const glm::dvec3 lsX = ls.ToLight(*wsCentre[i]);
        if (!InFront(fit.planeAxis, lsX))
            return fallBack("the view axis passes behind the light's plane");
        centre[i] = ProjectToPlane(fit.planeAxis, lsX);
    }
    std::string failure;
    fit.trapezoid =
        FitTrapezoid(planePoints, centre[0], centre[1], centre[2], kTsmFocusLine, &failure);
    if (!fit.trapezoid) return fallBack(failure);
    fit.matrix = MatrixOf(*fit.trapezoid, fit.planeAxis, context.map, margin);
    if (!CoversAll(fit.matrix, ToLightAll(ls, wsBody), context.map) ||
        !CoversAll(fit.matrix, RelevantLight(context), context.map))
        return fallBack("the trapezoid leaves a visible point outside the map");
    return fit;
}

LightMatrix TsmLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    TsmFit fit = FitTsm(context, TsmBody::kVisible);
    if (diagnostics && !fit.fallback.empty()) diagnostics->fallback = fit.fallback;
    return fit.matrix;
}

LightMatrix TsmReportLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    TsmFit fit = FitTsm(context, TsmBody::kFrustum);
    if (diagnostics && !fit.fallback.empty()) diagnostics->fallback = fit.fallback;
    return fit.matrix;
}

}  // namespace lexel::spatial
