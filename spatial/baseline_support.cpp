// What the baselines share (baseline_support.h).
#include "lexel/spatial/baseline_support.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel::spatial::baseline_detail {

glm::dvec4 WorldPlaneOfLightPlane(const LightSpace& lightSpace, const glm::dvec3& p4,
                                  double delta) {
    // X(x) = L x + X(0) with L = LsFromWsLinear, so p4·X(x) = (Lᵀp4)·x + p4·X(0).
    const glm::dmat3 linear = lightSpace.LsFromWsLinear();
    const glm::dvec3 n = glm::transpose(linear) * p4;
    return {n, glm::dot(p4, lightSpace.ToLight(glm::dvec3(0.0))) - delta};
}

std::vector<glm::dvec3> ToLightAll(const LightSpace& lightSpace,
                                   std::span<const glm::dvec3> wsPoints) {
    std::vector<glm::dvec3> out;
    out.reserve(wsPoints.size());
    for (const glm::dvec3& x : wsPoints) out.push_back(lightSpace.ToLight(x));
    return out;
}

glm::dvec2 ProjectToPlane(const glm::dvec3& p4, const glm::dvec3& lsX) {
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    return ProjectToAxisPlane(p4, b1, b2, lsX);
}

bool CoversAll(const LightMatrix& m, std::span<const glm::dvec3> lsPoints, Resolution map) {
    for (const glm::dvec3& p : {m.p1, m.p2, m.p4})
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    const double tol = kMapToleranceTexels;
    for (const glm::dvec3& X : lsPoints) {
        if (!InFront(m.p4, X)) return false;
        const glm::dvec2 u = m.Map(X);
        if (!(u.x >= -tol && u.x <= map.width + tol && u.y >= -tol && u.y <= map.height + tol))
            return false;
    }
    return true;
}

glm::dmat4 FromRows(const glm::dvec4& r0, const glm::dvec4& r1, const glm::dvec4& r2,
                    const glm::dvec4& r3) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c) {
        m[c][0] = r0[c];
        m[c][1] = r1[c];
        m[c][2] = r2[c];
        m[c][3] = r3[c];
    }
    return m;
}

// The axis a of the narrowest cone around unit directions d_i: max over unit a of min_i a·d_i.
// By duality it is the minimum-norm point x of the convex hull of the d_i, normalized, with
// margin |x| (positive iff the directions fit in an open half-space). Gilbert's algorithm
// (E. G. Gilbert, "An iterative procedure for computing the minimum of a quadratic form on a
// convex set", SIAM J. Control 4(1), 1966): step toward the d_i least aligned with x, with exact
// line search. Stops when the duality gap |x|² - min_i x·d_i is below 1e-4 |x|² (the margin
// within 0.01% of optimal) or after 2000 steps; nullopt when the margin is not positive.
std::optional<glm::dvec3> NarrowestConeAxis(const std::vector<glm::dvec3>& directions) {
    if (directions.empty()) return std::nullopt;
    glm::dvec3 x(0.0);
    for (const glm::dvec3& d : directions) x += d;
    x /= static_cast<double>(directions.size());
    for (int step = 0; step < 2000; ++step) {
        std::size_t worst = 0;
        double worstDot = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < directions.size(); ++i) {
            const double dot = glm::dot(x, directions[i]);
            if (dot < worstDot) {
                worstDot = dot;
                worst = i;
            }
        }
        const double xx = glm::dot(x, x);
        if (xx - worstDot <= 1e-4 * xx) break;
        const glm::dvec3 toward = directions[worst] - x;
        const double t = std::clamp((xx - worstDot) / glm::dot(toward, toward), 0.0, 1.0);
        x += t * toward;
    }
    const double len = glm::length(x);
    if (!(len > 0.0)) return std::nullopt;
    const glm::dvec3 a = x / len;
    for (const glm::dvec3& d : directions)
        if (!(glm::dot(a, d) > 0.0)) return std::nullopt;
    return a;
}

namespace {

bool AllInFront(const glm::dvec3& p4, std::span<const glm::dvec3> lsPoints) {
    for (const glm::dvec3& X : lsPoints)
        if (!InFront(p4, X)) return false;
    return true;
}

// Normalized mean of the unit directions of the points (zero if they cancel out).
glm::dvec3 MeanDirection(std::span<const glm::dvec3> lsPoints) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& X : lsPoints) {
        const double len = glm::length(X);
        if (len > 0.0) sum += X / len;
    }
    const double len = glm::length(sum);
    return len > 0.0 ? sum / len : glm::dvec3(0.0);
}

std::vector<glm::dvec3> UnitDirections(std::span<const glm::dvec3> lsPoints) {
    std::vector<glm::dvec3> out;
    for (const glm::dvec3& X : lsPoints)
        if (glm::length(X) > 0.0) out.push_back(X / glm::length(X));
    return out;
}

}  // namespace

NormalAxis ChooseNormalAxis(const BaselineContext& context) {
    const LightSpace& ls = *context.lightSpace;
    const auto wsCorners = context.wsBounds.Corners();
    const std::vector<glm::dvec3> lsCorners = ToLightAll(ls, wsCorners);
    NormalAxis axis;
    if (AllInFront(axis.p4, lsCorners)) return axis;
    axis.p4 = MeanDirection(lsCorners);
    axis.fallback = "normal: a bounds corner is behind p4 = (0, 0, 1); p4 = mean corner direction";
    if (glm::length(axis.p4) > 0.0 && AllInFront(axis.p4, lsCorners)) return axis;
    // The mean is pulled toward clusters of corners; the narrowest cone's axis sees them all
    // whenever any axis does (the light outside the box but near the plane of a face).
    if (const auto cone = NarrowestConeAxis(UnitDirections(lsCorners));
        cone && AllInFront(*cone, lsCorners)) {
        axis.p4 = *cone;
        axis.fallback =
            "normal: p4 = (0, 0, 1) and the mean corner direction miss a bounds "
            "corner; p4 = axis of the narrowest cone around the corners";
        return axis;
    }
    // Last resort (a light in the plane of a box face): only the relevant points must be seen.
    const std::vector<glm::dvec3> lsRelevant = ToLightAll(ls, context.wsRelevant);
    axis.cornersInFront = false;
    axis.fallback =
        "normal: no axis sees every bounds corner; p4 = axis of the narrowest cone "
        "around the relevant points, fitted over them only";
    if (const auto cone = NarrowestConeAxis(UnitDirections(lsRelevant));
        cone && AllInFront(*cone, lsRelevant)) {
        axis.p4 = *cone;
        return axis;
    }
    throw DomainError(Subject::kLight,
                      "no optical axis sees every visible point from this light (they surround "
                      "it)");
}

double LightPlaneOffset(const BaselineContext& context, const NormalAxis& axis) {
    const LightSpace& ls = *context.lightSpace;
    double smallest = std::numeric_limits<double>::infinity();
    auto consider = [&](const glm::dvec3& wsPoint) {
        const glm::dvec3 X = ls.ToLight(wsPoint);
        if (InFront(axis.p4, X)) smallest = std::min(smallest, glm::dot(axis.p4, X));
    };
    for (const glm::dvec3& x : context.wsBounds.Corners()) consider(x);
    for (const glm::dvec3& x : context.wsRelevant) consider(x);
    // Half the nearest depth: strictly positive, and below every point the map must see. When
    // no point is in front, any positive offset will do; 1e-9 scene radii keeps it scale-free.
    if (std::isfinite(smallest)) return 0.5 * smallest;
    const double radius = context.wsBounds.Radius();
    return radius > 0.0 && std::isfinite(radius) ? 1e-9 * radius : 1e-9;
}

std::vector<glm::dvec3> FocusBody(const BaselineContext& context, const NormalAxis& axis) {
    const Camera& camera = context.camera;
    ConvexPolyhedron body = FrustumPolyhedron(camera.FrustumCorners());
    body = ClipPolyhedron(body, WorldPlaneOfLightPlane(*context.lightSpace, axis.p4,
                                                       LightPlaneOffset(context, axis)));
    if (!body.faces.empty()) body = ClipToBox(body, context.wsBounds.lo, context.wsBounds.hi);
    std::vector<glm::dvec3> out = body.Vertices();
    out.insert(out.end(), context.wsRelevant.begin(), context.wsRelevant.end());
    return out;
}

namespace {

// The parameter t ≥ 0 where the ray x + t·d leaves the box [lo, hi] that contains x (slab test).
double ExitDistance(const glm::dvec3& x, const glm::dvec3& d, const Bounds& box) {
    double exit = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (d[k] > 0.0) exit = std::min(exit, (box.hi[k] - x[k]) / d[k]);
        if (d[k] < 0.0) exit = std::min(exit, (box.lo[k] - x[k]) / d[k]);
    }
    return std::max(exit, 0.0);
}

std::span<const glm::dvec3> RelevantWorld(const BaselineContext& context) {
    return context.wsRelevantHull.empty() ? context.wsRelevant : context.wsRelevantHull;
}

}  // namespace

std::vector<glm::dvec3> TightBody(const BaselineContext& context) {
    const LightSpace& ls = *context.lightSpace;
    std::vector<glm::dvec3> body;
    for (const glm::dvec3& x : RelevantWorld(context)) {
        body.push_back(x);
        const glm::dvec3 toLight = ls.DirectionToLight(x);
        // A point light inside the swept range stops the sweep at the light itself.
        const double reach =
            std::min(ExitDistance(x, toLight, context.wsBounds), ls.DistanceToLight(x));
        if (reach > 0.0 && std::isfinite(reach)) body.push_back(x + reach * toLight);
    }
    return body;
}

std::vector<glm::dvec3> RelevantLight(const BaselineContext& context) {
    return ToLightAll(*context.lightSpace, RelevantWorld(context));
}

void CheckContext(const BaselineContext& context) {
    if (context.lightSpace == nullptr)
        throw std::invalid_argument("baselines: the context needs a light space");
    if (context.wsBounds.Empty())
        throw DomainError(Subject::kGeometry, "the scene bounds are empty");
}

}  // namespace lexel::spatial::baseline_detail
