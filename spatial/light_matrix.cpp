#include "lexel/spatial/light_matrix.h"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

#include "lexel/solvers/min_area_parallelogram.h"
#include "lexel/solvers/min_area_rectangle.h"
#include "lexel/spatial/affine_fit.h"

namespace lexel::spatial {

glm::dmat3 LightMatrix::Rows() const {
    glm::dmat3 m;
    for (int c = 0; c < 3; ++c) {
        m[c][0] = p1[c];
        m[c][1] = p2[c];
        m[c][2] = p4[c];
    }
    return m;
}

glm::dvec3 LightMatrix::Unmap(glm::dvec2 u) const {
    return glm::inverse(Rows()) * glm::dvec3(u, 1.0);
}

void LightMatrix::MapJacobian(const glm::dvec3& lsX, glm::dvec3* du1dX, glm::dvec3* du2dX) const {
    const glm::dvec3 h = Homogeneous(lsX);
    *du1dX = (p1 - (h.x / h.z) * p4) / h.z;
    *du2dX = (p2 - (h.y / h.z) * p4) / h.z;
}

LightMatrix LightMatrix::ThenAffine(const glm::dmat3& a) const {
    // u'^r = Σ_c a_rc (u, 1)_c, so row r of P' is a_r0 p1 + a_r1 p2 + a_r2 p4 (a_rc = a[c][r]).
    LightMatrix out;
    out.p1 = a[0][0] * p1 + a[1][0] * p2 + a[2][0] * p4;
    out.p2 = a[0][1] * p1 + a[1][1] * p2 + a[2][1] * p4;
    out.p4 = p4;
    return out;
}

std::optional<LightMatrix> FromScreenRows(const LightSpace& lightSpace,
                                          const glm::dmat4& screenFromWorld,
                                          const glm::dvec3& wsCenter, std::string* failure) {
    const auto fail = [&](const std::string& why) -> std::optional<LightMatrix> {
        if (failure) *failure = why;
        return std::nullopt;
    };
    const glm::dmat3 linear = lightSpace.LsFromWsLinear();  // rows e1, e2, (e3 | 0)
    const glm::dvec3 lsCenter = lightSpace.ToLight(wsCenter);
    glm::dvec3 rows[3];
    const int rowIndex[3] = {0, 1, 3};
    for (int k = 0; k < 3; ++k) {
        const int r = rowIndex[k];
        const glm::dvec3 rXyz(screenFromWorld[0][r], screenFromWorld[1][r], screenFromWorld[2][r]);
        const double rW = screenFromWorld[3][r];
        // e_i · rXyz are the light-space components of the world covector (the frame is
        // orthonormal, so the covector transforms like a vector).
        glm::dvec3 p(glm::dot(glm::dvec3(linear[0][0], linear[1][0], linear[2][0]), rXyz),
                     glm::dot(glm::dvec3(linear[0][1], linear[1][1], linear[2][1]), rXyz), 0.0);
        if (lightSpace.IsPoint()) {
            const glm::dvec3 e3(linear[0][2], linear[1][2], linear[2][2]);
            p.z = glm::dot(e3, rXyz);
            // r·L + rW = 0 up to rounding: relative to the terms' magnitude |r||L| + |rW|, so the
            // test is the same at any scale and distance from the origin.
            const glm::dvec3& wsLight = lightSpace.light().position;
            const double atLight = glm::dot(rXyz, wsLight) + rW;
            const double terms = glm::length(rXyz) * glm::length(wsLight) + std::abs(rW);
            if (std::abs(atLight) > 1e-9 * terms)
                return fail("row " + std::to_string(r + 1) +
                            " does not send the point light to infinity");
        } else {
            const double alongLight = glm::dot(rXyz, lightSpace.light().direction);
            if (std::abs(alongLight) > 1e-9 * glm::length(rXyz))
                return fail("row " + std::to_string(r + 1) +
                            " does not send the directional light to infinity");
            // p·X(c) = r·[c; 1] at the centre fixes the third component.
            p.z =
                (glm::dot(rXyz, wsCenter) + rW - p.x * lsCenter.x - p.y * lsCenter.y) / lsCenter.z;
        }
        rows[k] = p;
    }
    double norm = glm::length(rows[2]);
    if (!(norm > 0.0)) return fail("the optical axis row is zero");
    if (glm::dot(rows[2], lsCenter) < 0.0) norm = -norm;
    return LightMatrix{rows[0] / norm, rows[1] / norm, rows[2] / norm};
}

bool InFront(const glm::dvec3& p4, const glm::dvec3& lsX) {
    return glm::dot(p4, lsX) > 1e-9 * glm::length(lsX);
}

// FitMapToPoints with options.shear: the rectangle becomes a parallelogram. The report (§2.3, Fig.
// 3) shears heuristically: for each hull edge's rectangle, "check to see if the minimum and maximum
// extents in the current edge direction can be shifted to better line up with the edge's
// endpoints"; in Fig. 3 the off-edge points all lie left of the edge's extents and are sheared
// right until the leftmost one lines up with the edge's left end. Exactly: for hull edge e with
// unit direction u and inward normal v, in the edge coordinates s = u·y, t = v·y - lo ≥ 0 (the edge
// on t = 0), the shear s' = s + k t keeps the edge and the height H fixed, and the extent E(k) of
// the hull in s' is convex and piecewise linear in k. Its minimum lies at a breakpoint where two
// adjacent hull vertices tie for the max or the min (a flat stretch of minimizers contains k = 0 or
// ends at such a breakpoint); it is found exactly (solvers/min_area_parallelogram.h, which also
// shows that the report's rule is the special case where lining up with the edge's endpoint is that
// breakpoint, and that |k*| ≤ 2 E(0) / H, finite because H > 0 for every edge of a hull of ≥ 3
// vertices). Of the minimizers the one closest to 0 is taken, so an edge that cannot gain keeps
// its rectangle. The edge with the least E(k*) H wins, which makes the result the minimum-area
// enclosing parallelogram. The shear enters the 2D affine map through the map row that reads
// along the edge: s' = (u + k v)·y, so that row (p1, or p2 after a long-side swap) gains a
// component along the v direction, while the other still reads v·y.
//   - Long side: the parallelogram's longer side (side lengths E and H √(1 + k²)) goes on the
//     map's longer dimension, as the rectangle's does. Of the two assignments this one has the
//     smaller ||M||_F, M the inverse linear part of the 2D map (columns: the side vectors over
//     the texel counts W, H_map on their map axes): E²/W² + H²(1 + k²)/H_map² against the swap.
//   - Margin: both half sides grow by the same fraction, i.e. the parallelogram is scaled about
//     its centre, exactly as the rectangle is.
//   - Degenerate hulls (1 or 2 distinct projected points, all collinear): the unsheared fit,
//     sliver included; the shear is never NaN or infinite.
// The sheared fit jumps with p4 more often than the rectangle fit does: near a minimum flush with
// hull edges on both side pairs, the two hull edges next to one of them give parallelograms of
// nearly equal area but different shear, and which one wins flips as p4 moves (an area tie is a
// jump for the rectangle too, but its candidates differ more). h differs between such twins by
// several percent: the area the shear minimizes is not the h it is meant to serve. The report finds
// the shear of "minimal benefit in practice"; method optimal-shear measures it here (`lexel sweep
// CASE --method optimal-report --method optimal-shear`).

namespace {

// The fitted frame in the plane (affine_fit.h). For the rectangle the rows are its orthonormal
// axes. For the parallelogram (options.shear) a point is y = c + a axisU + b axisV with
// a = dualU·(y - c), b = dualV·(y - c) (Parallelogram2::DualAxes), so the rows are the dual axes:
// the rectangle's formula, whose axes are self-dual.
detail::PlaneFrame<double> FitFrame(std::span<const Eigen::Vector2d> pts, Resolution map,
                                    bool shear) {
    const bool longSideOnU = map.width >= map.height;
    const Parallelogram2 fit =
        OrientLongSideAlong(shear ? MinAreaParallelogram(pts) : MinAreaRectangle(pts), longSideOnU);
    Eigen::Vector2d rowU = fit.axisU, rowV = fit.axisV;
    if (shear) {
        const auto dual = fit.DualAxes();
        rowU = dual[0];
        rowV = dual[1];
    }
    return {{rowU.x(), rowU.y()},
            {rowV.x(), rowV.y()},
            rowU.dot(fit.center),
            rowV.dot(fit.center),
            fit.halfU,
            fit.halfV};
}

}  // namespace

std::optional<LightMatrix> FitMapToPlanePoints(const glm::dvec3& p4,
                                               std::span<const glm::dvec2> planePoints,
                                               Resolution map, const FitOptions& options) {
    if (planePoints.empty()) return std::nullopt;
    std::vector<Eigen::Vector2d> pts(planePoints.size());
    for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = {planePoints[i].x, planePoints[i].y};
    const detail::PlaneFrame<double> frame = FitFrame(pts, map, options.shear);
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    LightMatrix m;
    m.p4 = p4;
    detail::AffineRowsFromFrame(&p4[0], &b1[0], &b2[0], frame, map, options.margin, &m.p1[0],
                                &m.p2[0]);
    // Rows that overflow (plane coordinates near the largest double) are no map.
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(m.p1[i]) || !std::isfinite(m.p2[i])) return std::nullopt;
    return m;
}

std::optional<LightMatrix> ScaleMapToCover(const LightMatrix& matrix,
                                           std::span<const glm::dvec3> lsPoints, Resolution map,
                                           double margin) {
    if (lsPoints.empty()) return std::nullopt;
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec3& X : lsPoints) {
        if (!InFront(matrix.p4, X)) return std::nullopt;
        const glm::dvec2 u = matrix.Map(X);
        lo = glm::min(lo, u);
        hi = glm::max(hi, u);
    }
    const glm::dvec2 center = 0.5 * (lo + hi);
    const glm::dvec2 half = glm::max(0.5 * (hi - lo) * (1.0 + margin), glm::dvec2(1e-12));
    // u' = W/2 + (u - c) · W/(2 half): a scale and a shift per axis.
    const glm::dvec2 scale(0.5 * map.width / half.x, 0.5 * map.height / half.y);
    glm::dmat3 a(0.0);
    a[0][0] = scale.x;
    a[1][1] = scale.y;
    a[2][0] = 0.5 * map.width - scale.x * center.x;
    a[2][1] = 0.5 * map.height - scale.y * center.y;
    a[2][2] = 1.0;
    return matrix.ThenAffine(a);
}

std::optional<std::vector<glm::dvec2>> ProjectToPlaneInFront(const glm::dvec3& p4,
                                                             std::span<const glm::dvec3> lsPoints) {
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    std::vector<glm::dvec2> planePoints;
    planePoints.reserve(lsPoints.size());
    for (const glm::dvec3& X : lsPoints) {
        if (!InFront(p4, X)) return std::nullopt;
        planePoints.push_back(ProjectToAxisPlane(p4, b1, b2, X));
    }
    return planePoints;
}

std::optional<LightMatrix> FitMapBoxToPoints(const glm::dvec3& p4, const glm::dvec2& axisU,
                                             std::span<const glm::dvec3> lsPoints, Resolution map,
                                             const FitOptions& options) {
    const std::optional<std::vector<glm::dvec2>> planePoints = ProjectToPlaneInFront(p4, lsPoints);
    if (!planePoints || planePoints->empty()) return std::nullopt;
    const glm::dvec2 axisV = Perp(axisU);
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec2& y : *planePoints) {
        const glm::dvec2 st(glm::dot(axisU, y), glm::dot(axisV, y));
        lo = glm::min(lo, st);
        hi = glm::max(hi, st);
    }
    glm::dvec2 center = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double margin = options.margin;
    if (options.snapUnit > 0.0) {
        const double unit = options.snapUnit;
        const int size[2] = {map.width, map.height};
        for (int a = 0; a < 2; ++a) {
            const double tight = half[a], grown = std::max(tight * (1.0 + margin), 1e-9 * unit);
            double snapped = unit * std::exp2(std::ceil(std::log2(grown / unit)));
            double snappedCenter = center[a];
            // The centre moves by up to half a texel: grow until the points still fit.
            for (int doubling = 0; doubling < 64; ++doubling, snapped *= 2.0) {
                const double texel = 2.0 * snapped / size[a];
                snappedCenter = texel * std::round(center[a] / texel);
                if (std::abs(snappedCenter - center[a]) + tight <= snapped) break;
            }
            half[a] = snapped;
            center[a] = snappedCenter;
        }
        margin = 0.0;
    }
    const detail::PlaneFrame<double> frame{
        {axisU.x, axisU.y}, {axisV.x, axisV.y}, center.x, center.y, half.x, half.y};
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    LightMatrix m;
    m.p4 = p4;
    detail::AffineRowsFromFrame(&p4[0], &b1[0], &b2[0], frame, map, margin, &m.p1[0], &m.p2[0]);
    return m;
}

std::optional<LightMatrix> FitMapToPoints(const glm::dvec3& p4,
                                          std::span<const glm::dvec3> lsPoints, Resolution map,
                                          const FitOptions& options) {
    const std::optional<std::vector<glm::dvec2>> planePoints = ProjectToPlaneInFront(p4, lsPoints);
    if (!planePoints) return std::nullopt;
    return FitMapToPlanePoints(p4, *planePoints, map, options);
}

}  // namespace lexel::spatial
