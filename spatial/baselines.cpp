// Normal, focused and plane-optimal baselines (Chong & Gortler report §3; see baselines.h for the
// papers). LiSPSM and PSM live in warping_baselines.cpp.
//
// Normal and focused share the optical axis p4 = (0, 0, 1) of the light frame (the axis from the
// light to the bounds centre) and differ only in the affine fit (report §2.3 step 4b-ii: the
// min-area rectangle about the projections on the plane p4·X = 1).
//
// Plane-optimal (Chong & Gortler, "A Lixel for Every Pixel", EGSR 2004): for the floor plane Π
// the light map restricted to Π must be an affine image A of the camera's screen map Q restricted
// to Π. With B (4×3) three homogeneous points spanning Π and L the homogeneous light, the 3×4
// rows (1, 2, 4) of P satisfy P·B = A·Q·B and P·L = 0 (report Fig. 1: P sends the light to
// infinity), so P = [A·Q·B, 0]·[B, L]⁻¹; its row 4 is (row 4 of Q·B, 0)·[B, L]⁻¹, independent of
// A, which is why only p4 is kept and the affine part refitted over the relevant points.
#include "lexel/spatial/baselines.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/baseline_support.h"

namespace lexel::spatial {

using namespace baseline_detail;

namespace {

void Note(BaselineDiagnostics* diagnostics, const std::string& why) {
    if (diagnostics == nullptr || why.empty()) return;
    if (!diagnostics->fallback.empty()) diagnostics->fallback += "; ";
    diagnostics->fallback += why;
}

// Fits p4's affine part to planePoints (already on the plane p4·X = 1); if the result misses a
// relevant point (which should only happen through rounding, or when the caller's relevant points
// stray outside the bounds), refits over planePoints ∪ the relevant points' projections and says
// so. Throws when a relevant point is behind p4 (callers choose p4 so that none is).
LightMatrix FitCovering(const glm::dvec3& p4, std::vector<glm::dvec2> planePoints,
                        const std::vector<glm::dvec3>& lsRelevant, Resolution map,
                        const char* method, BaselineDiagnostics* diagnostics) {
    if (!planePoints.empty()) {
        const auto m = FitMapToPlanePoints(p4, planePoints, map);
        if (m && CoversAll(*m, lsRelevant, map)) return *m;
        Note(diagnostics, std::string(method) + ": refitted over the relevant points too");
    }
    const std::optional<std::vector<glm::dvec2>> relevantPlane =
        ProjectToPlaneInFront(p4, lsRelevant);
    if (!relevantPlane)
        throw DomainError(Subject::kLight,
                          std::string(method) + ": a visible point is behind the light's plane");
    planePoints.insert(planePoints.end(), relevantPlane->begin(), relevantPlane->end());
    const auto m = FitMapToPlanePoints(p4, planePoints, map);
    if (!m || !CoversAll(*m, lsRelevant, map))
        throw DomainError(Subject::kLight,
                          std::string(method) + ": no rectangle covers the visible points");
    return *m;
}

}  // namespace

glm::dvec3 InitialLightAxis(const LightSpace& lightSpace, const Bounds& wsBounds,
                            std::span<const glm::dvec3> wsRelevant) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.wsBounds = wsBounds;
    context.wsRelevant = wsRelevant;
    CheckContext(context);
    return ChooseNormalAxis(context).p4;
}

LightMatrix NormalLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    const NormalAxis axis = ChooseNormalAxis(context);
    Note(diagnostics, axis.fallback);
    const LightSpace& ls = *context.lightSpace;
    std::vector<glm::dvec2> planePoints;
    if (axis.cornersInFront)
        for (const glm::dvec3& x : context.wsBounds.Corners())
            planePoints.push_back(ProjectToPlane(axis.p4, ls.ToLight(x)));
    return FitCovering(axis.p4, std::move(planePoints), ToLightAll(ls, context.wsRelevant),
                       context.map, "normal", diagnostics);
}

LightMatrix FocusedLightMatrix(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    const NormalAxis axis = ChooseNormalAxis(context);
    const LightSpace& ls = *context.lightSpace;
    // The view frustum, cut to the part well in front of the light: a point light may sit inside
    // the frustum, and points near p4·X = 0 project to infinity. The cut plane p4·X = δ lies below
    // every bounds corner and relevant point (LightPlaneOffset), so nothing that matters is lost.
    ConvexPolyhedron frustum = FrustumPolyhedron(context.camera.FrustumCorners());
    frustum = ClipPolyhedron(frustum,
                             WorldPlaneOfLightPlane(ls, axis.p4, LightPlaneOffset(context, axis)));
    std::vector<glm::dvec2> frustumPlane;
    for (const glm::dvec3& x : frustum.Vertices()) {
        const glm::dvec3 X = ls.ToLight(x);
        if (InFront(axis.p4, X)) frustumPlane.push_back(ProjectToPlane(axis.p4, X));
    }
    const std::vector<glm::dvec2> frustumHull = ConvexHull(frustumPlane);

    std::vector<glm::dvec2> region;
    if (axis.cornersInFront) {
        std::vector<glm::dvec2> boundsPlane;
        for (const glm::dvec3& x : context.wsBounds.Corners())
            boundsPlane.push_back(ProjectToPlane(axis.p4, ls.ToLight(x)));
        const std::vector<glm::dvec2> boundsHull = ConvexHull(boundsPlane);
        region = IntersectConvexPolygons(frustumHull, boundsHull);
    } else {
        region = frustumHull;  // normal's extent is the relevant points themselves: see FitCovering
    }
    if (region.size() < 3) {
        // The view frustum misses the lit bounds (or collapses on the plane): nothing to focus on.
        Note(diagnostics, "focused: view frustum ∩ bounds is degenerate; using normal");
        return NormalLightMatrix(context, diagnostics);
    }
    Note(diagnostics, axis.fallback);
    return FitCovering(axis.p4, std::move(region), ToLightAll(ls, context.wsRelevant), context.map,
                       "focused", diagnostics);
}

std::optional<LightMatrix> PlaneOptimalProjectiveMatrix(const BaselineContext& context,
                                                        std::string* failure) {
    CheckContext(context);
    const auto fail = [&](const std::string& why) -> std::optional<LightMatrix> {
        if (failure) *failure = why;
        return std::nullopt;
    };
    if (!context.floorPlane) return fail("the scene has no floor plane");
    const glm::dvec4& floorPlane = *context.floorPlane;
    const glm::dvec3 n(floorPlane);
    const double nLen = glm::length(n);
    if (!(nLen > 0.0)) return fail("the floor plane normal is zero");
    const glm::dvec3 unitN = n / nLen;
    // The construction runs in the scene's unit frame x = c + R·x' (c, R: the bounds' centre and
    // radius), where the spanning points are one unit apart and the light O(1) or more away
    // whatever the scene's size and distance from the origin: [B, L] stays well conditioned and
    // the determinant test below is dimensionless.
    const glm::dvec3 wsSceneCenter = context.wsBounds.Center();
    const double radius = context.wsBounds.Radius() > 0.0 ? context.wsBounds.Radius() : 1.0;
    glm::dmat4 worldFromUnit(radius);
    worldFromUnit[3] = glm::dvec4(wsSceneCenter, 1.0);
    glm::dmat4 unitFromWorld(1.0 / radius);
    unitFromWorld[3] = glm::dvec4(-wsSceneCenter / radius, 1.0);
    // The floor n·x + d = 0 is n·x' + d' = 0 there; its point nearest the scene's centre:
    const double unitD = (glm::dot(unitN, wsSceneCenter) + floorPlane.w / nLen) / radius;
    const glm::dvec3 unitOnPlane = -unitD * unitN;
    glm::dvec3 t1, t2;
    PlaneBasis(unitN, &t1, &t2);
    const LightSpace& ls = *context.lightSpace;
    const glm::dvec4 light = ls.IsPoint()
                                 ? glm::dvec4((ls.light().position - wsSceneCenter) / radius, 1.0)
                                 : glm::dvec4(ls.light().direction, 0.0);
    glm::dmat4 basis;  // columns: B (three plane points), L, in the unit frame
    basis[0] = glm::dvec4(unitOnPlane, 1.0);
    basis[1] = glm::dvec4(unitOnPlane + t1, 1.0);
    basis[2] = glm::dvec4(unitOnPlane + t2, 1.0);
    basis[3] = light / glm::length(light);
    // Columns normalized, so |det| is a dimensionless measure of how far L is from Π: below 1e-12
    // the light lies on the floor plane and every floor point maps to one line of the map.
    glm::dmat4 unit = basis;
    for (int c = 0; c < 4; ++c) unit[c] /= glm::length(unit[c]);
    if (!(std::abs(glm::determinant(unit)) > 1e-12))
        return fail("the light lies on the floor plane");

    const glm::dmat4 screenFromUnit = context.camera.ScreenFromWorld(context.map) * worldFromUnit;
    const glm::dmat4 qb = screenFromUnit * basis;  // columns Q·B_k (and Q·L, dropped)
    glm::dmat4 target = qb;
    target[3] = glm::dvec4(0.0);  // P·L = 0
    const glm::dmat4 rows = target * glm::inverse(basis) * unitFromWorld;
    glm::dvec3 wsCenter = context.wsBounds.Center();
    if (!context.wsRelevant.empty()) {
        wsCenter = glm::dvec3(0.0);
        for (const glm::dvec3& x : context.wsRelevant) wsCenter += x;
        wsCenter /= static_cast<double>(context.wsRelevant.size());
    }
    return FromScreenRows(ls, rows, wsCenter, failure);
}

namespace {

// "In front with margin" for the rotation fallback: p4·X > 1e-6 |X|, i.e. at least ~1e-6 rad
// above the plane p4·X = 0 (dimensionless), so the bisection's answer is not on a knife edge.
constexpr double kRotationMargin = 1e-6;

bool AllInFrontWithMargin(const glm::dvec3& p4, const std::vector<glm::dvec3>& lsPoints) {
    for (const glm::dvec3& X : lsPoints)
        if (!(glm::dot(p4, X) > kRotationMargin * glm::length(X))) return false;
    return true;
}

// The point at fraction t of the great-circle arc from unit a to unit b (a ≠ -b).
glm::dvec3 Slerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    if (angle < 1e-12) return b;  // same direction up to rounding
    const double s = std::sin(angle);
    return glm::normalize((std::sin((1.0 - t) * angle) * a + std::sin(t * angle) * b) / s);
}

}  // namespace

namespace {

// A plane-optimal candidate for axis p4: the refit over the relevant points, when it covers them
// all and keeps them a texel above the horizon.
std::optional<LightMatrix> PlaneOptimalCandidate(const glm::dvec3& p4,
                                                 const std::vector<glm::dvec3>& lsRelevant,
                                                 Resolution map) {
    const auto m = FitMapToPoints(p4, lsRelevant, map);
    if (!m || !CoversAll(*m, lsRelevant, map)) return std::nullopt;
    if (HorizonClearanceTexels(*m, lsRelevant, map) < kHorizonTexels) return std::nullopt;
    return m;
}

// The turn toward the focused axis (PlaneOptimalLightMatrix's header comment): t0 by bisection,
// then the admissible fraction of least h (the smallest without samples).
std::optional<LightMatrix> TurnTowardFocused(const BaselineContext& context, const glm::dvec3& p4,
                                             const glm::dvec3& focusedP4,
                                             const std::vector<glm::dvec3>& lsRelevant,
                                             double* fraction) {
    double lo = 0.0, hi = 1.0;  // 40 steps: the fraction to 1e-12
    for (int step = 0; step < 40; ++step) {
        const double mid = 0.5 * (lo + hi);
        (AllInFrontWithMargin(Slerp(p4, focusedP4, mid), lsRelevant) ? hi : lo) = mid;
    }
    std::optional<LightMatrix> best;
    double bestH = std::numeric_limits<double>::infinity();
    constexpr int kSteps = 16;
    for (int i = 0; i <= kSteps; ++i) {
        const double t = hi + (1.0 - hi) * i / kSteps;
        const auto m = PlaneOptimalCandidate(Slerp(p4, focusedP4, t), lsRelevant, context.map);
        if (!m) continue;
        const double h = context.samples ? Energy(*m, *context.samples) : 0.0;
        if (!best || h < bestH) {
            best = m;
            bestH = h;
            *fraction = t;
        }
        if (!context.samples) break;  // the smallest admissible fraction
    }
    return best;
}

}  // namespace

double HorizonClearanceTexels(const LightMatrix& m, std::span<const glm::dvec3> lsPoints,
                              Resolution map) {
    const glm::dvec2 center(0.5 * map.width, 0.5 * map.height);
    const glm::dvec3 x0 = glm::normalize(m.Unmap(center));
    const double texelAngle =
        std::min(std::acos(std::clamp(
                     glm::dot(x0, glm::normalize(m.Unmap(center + glm::dvec2(1, 0)))), -1.0, 1.0)),
                 std::acos(std::clamp(
                     glm::dot(x0, glm::normalize(m.Unmap(center + glm::dvec2(0, 1)))), -1.0, 1.0)));
    const double p4Length = glm::length(m.p4);
    double least = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& X : lsPoints)
        least = std::min(least, std::asin(std::clamp(
                                    glm::dot(m.p4, X) / (p4Length * glm::length(X)), -1.0, 1.0)));
    return least / texelAngle;
}

LightMatrix PlaneOptimalLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    if (!context.floorPlane)
        throw DomainError(Subject::kGeometry,
                          "plane-optimal needs a floor plane (a plane primitive or the "
                          "floor_objects generator)");
    auto fallBack = [&](const std::string& why) {
        Note(diagnostics, "plane-optimal: " + why + "; using focused");
        return FocusedLightMatrix(context, diagnostics);
    };
    std::string failure;  // the light on the floor plane (or rows not annihilating it)
    const std::optional<LightMatrix> projective = PlaneOptimalProjectiveMatrix(context, &failure);
    if (!projective) return fallBack(failure);
    // The hull vertices when known: their fit is every visible point's (optimizer.cpp).
    const std::vector<glm::dvec3> lsRelevant = RelevantLight(context);
    if (lsRelevant.empty()) return fallBack("no relevant points to fit");

    const glm::dvec3 p4 = projective->p4;
    if (AllInFrontWithMargin(p4, lsRelevant))
        if (const auto m = PlaneOptimalCandidate(p4, lsRelevant, context.map)) return *m;
    // The report's observation that one map cannot serve every configuration: a relevant point
    // off the plane whose shadow on the plane falls behind the camera is behind p4, or so near
    // its horizon that the map collapses. Turn p4 toward the focused axis, which sees them all.
    const glm::dvec3 focusedP4 = ChooseNormalAxis(context).p4;
    if (glm::dot(p4, focusedP4) < -1.0 + 1e-12 || !AllInFrontWithMargin(focusedP4, lsRelevant))
        return fallBack("no great-circle turn toward the focused axis sees every point");
    double fraction = 0.0;
    const auto m = TurnTowardFocused(context, p4, focusedP4, lsRelevant, &fraction);
    if (!m) return fallBack("no turn toward the focused axis keeps the points off the horizon");
    if (diagnostics) diagnostics->rotationFraction = fraction;
    Note(diagnostics, "plane-optimal: p4 turned toward focused by fraction " +
                          std::to_string(fraction) + " to see every relevant point");
    return *m;
}

LightMatrix FocusedTightLightMatrix(const BaselineContext& context,
                                    BaselineDiagnostics* diagnostics) {
    CheckContext(context);
    const NormalAxis axis = ChooseNormalAxis(context);
    Note(diagnostics, axis.fallback);
    const std::vector<glm::dvec3> lsRelevant = RelevantLight(context);
    FitOptions options;
    options.margin = context.margin;
    const auto m = FitMapToPoints(axis.p4, lsRelevant, context.map, options);
    if (!m)
        throw DomainError(Subject::kLight,
                          "focused-tight: a visible point is behind the light's plane");
    return *m;
}

}  // namespace lexel::spatial
