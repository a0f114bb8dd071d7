#include "lexel/spatial/logpsm.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lexel/spatial/baseline_support.h"
#include "lexel/spatial/cascades.h"

namespace lexel::spatial {

using namespace baseline_detail;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // no pole
// Below this |X∞| (light-space units of a unit axis) the warp's p4 is the normal axis: no
// perspective warp, nothing to take the logarithm of.
constexpr double kNoWarp = 1e-9;
// The largest map side (OpenGL's common GL_MAX_TEXTURE_SIZE; the CPU has no limit but memory).
constexpr int kMaxSide = 16384;

// b∞: the second map coordinate of the points at ζ = ∞ (the header comment); NaN where the warp
// has none.
double PoleOf(const LightMatrix& warp, const glm::dvec3& normalAxis) {
    glm::dvec3 atInfinity = warp.p4 - glm::dot(warp.p4, normalAxis) * normalAxis;
    if (!(glm::length(atInfinity) > kNoWarp)) return kNaN;
    if (glm::dot(warp.p4, atInfinity) < 0.0) atInfinity = -atInfinity;
    const glm::dvec3 h = warp.Homogeneous(atInfinity);
    if (!(h.z > 0.0)) return kNaN;
    const double pole = h.y / h.z;
    return std::isfinite(pole) ? pole : kNaN;
}

struct Extent {
    double lo = kInf, hi = -kInf;
    void Add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
    // Centre and half extent grown by `margin` (a 1e-12 sliver for a zero extent).
    double Centre() const { return 0.5 * (lo + hi); }
    double Half(double margin) const { return std::max(0.5 * (hi - lo) * (1.0 + margin), 1e-12); }
};

// The axis warp mapping values v (b_x, or ℓ through `log`) with centre c and half extent h onto
// [0, side]; `log` (pole, sign) or null for an affine axis.
AxisWarp FitAxis(double centre, double half, int side, const std::pair<double, double>* log) {
    const double scale = side / (2.0 * half), offset = 0.5 * side - scale * centre;
    if (!log) return AxisWarp::Affine(scale, offset);
    return AxisWarp::Logarithmic(log->first, log->second, scale, offset);
}

// The largest beam width per map axis over the pixel width, at one texel per axis, over the
// visible points: (A_x, A_z) of the header comment.
glm::dvec2 AxisAliasing(const BaselineContext& context, const MapWarp& unit) {
    const LightSpace& ls = *context.lightSpace;
    const glm::dmat3 lsFromWs = ls.LsFromWsLinear();
    const double pixel = 2.0 * std::tan(glm::radians(context.camera.fovYDeg) / 2.0) /
                         context.camera.resolution.height;
    glm::dvec2 worst(0.0);
    for (const glm::dvec3& x : context.wsRelevant) {
        glm::dvec3 du1, du2;
        if (!unit.Jacobian(ls.ToLight(x), &du1, &du2)) continue;
        // J_l on a unit basis (e1, e2) of the plane ⊥ the light ray; its inverse's columns are
        // the beam's steps along the map's two axes.
        const glm::dvec3 ray = -ls.DirectionToLight(x);
        glm::dvec3 e1, e2;
        PlaneBasis(ray, &e1, &e2);
        const glm::dvec3 l1 = lsFromWs * e1, l2 = lsFromWs * e2;
        const double a = glm::dot(du1, l1), b = glm::dot(du1, l2);
        const double c = glm::dot(du2, l1), d = glm::dot(du2, l2);
        const double det = a * d - b * c;
        if (!(std::abs(det) > 0.0)) continue;
        // J_l⁻¹ = [d −b; −c a] / det: column 1 (d, −c)/det, column 2 (−b, a)/det.
        const double wi = pixel * PlanarEyeDepth(context.camera, x);
        if (!(wi > 0.0)) continue;
        worst.x = std::max(worst.x, std::hypot(d, c) / std::abs(det) / wi);
        worst.y = std::max(worst.y, std::hypot(b, a) / std::abs(det) / wi);
    }
    return worst;
}

// M_x × M_z with M_x / M_z = ratio and M_x M_z ≤ the map's texels.
Resolution SplitTexels(Resolution map, double ratio) {
    const double texels = static_cast<double>(map.width) * map.height;
    if (!(ratio > 0.0) || !std::isfinite(ratio)) return map;
    const double limit = std::min<double>(kMaxSide, std::floor(texels / kLogPsmMinSide));
    if (limit < kLogPsmMinSide) return map;  // too few texels for two sides of kLogPsmMinSide
    const int mx = static_cast<int>(
        std::clamp(std::round(std::sqrt(texels * ratio)), double(kLogPsmMinSide), limit));
    const int mz = static_cast<int>(std::min<double>(kMaxSide, std::floor(texels / mx)));
    return {mx, mz};
}

}  // namespace

LogPsmMap LogPsmLightMap(const BaselineContext& context, BaselineDiagnostics* diagnostics) {
    BaselineDiagnostics local;
    BaselineDiagnostics* diag = diagnostics ? diagnostics : &local;
    const LightMatrix warp =
        LispsmRuleLightMatrix(context, {LispsmNearRule::Kind::kNearDepth}, diag);
    const std::vector<glm::dvec3> lsVisible = RelevantLight(context);
    // A plain double and flag rather than std::optional: GCC 12 reports the optional's payload as
    // maybe uninitialized here (-Wmaybe-uninitialized, a false positive under -O3).
    const double pole = diag->fallback.empty() ? PoleOf(warp, ChooseNormalAxis(context).p4) : kNaN;
    bool hasPole = std::isfinite(pole);
    // Every visible point on one side of the pole (they are at finite ζ > 0; rounding aside).
    Extent bx, by;
    double side = 0.0;
    for (const glm::dvec3& X : lsVisible) {
        const glm::dvec2 b = warp.Map(X);
        bx.Add(b.x);
        if (hasPole) side += b.y - pole;
    }
    const double sign = side >= 0.0 ? 1.0 : -1.0;
    if (hasPole)
        for (const glm::dvec3& X : lsVisible)
            if (!(sign * (warp.Map(X).y - pole) > 0.0)) hasPole = false;
    for (const glm::dvec3& X : lsVisible) {
        const double b = warp.Map(X).y;
        by.Add(hasPole ? sign * std::log(sign * (b - pole)) : b);
    }
    if (!hasPole && diag->fallback.empty()) diag->fallback = "logpsm: no warp to take the log of";
    const std::pair<double, double> poleAndSign(pole, sign);
    const std::pair<double, double>* log = hasPole ? &poleAndSign : nullptr;

    // The aspect from the warp at one texel per axis, then the map.
    const double margin = context.margin;
    MapWarp unit = MapWarp::Linear(warp);
    unit.x = FitAxis(bx.Centre(), bx.Half(margin), 1, nullptr);
    unit.y = FitAxis(by.Centre(), by.Half(margin), 1, log);
    const glm::dvec2 aliasing = AxisAliasing(context, unit);
    LogPsmMap out;
    out.logarithmic = hasPole;
    out.aliasingRatio = aliasing.y > 0.0 ? aliasing.x / aliasing.y : 1.0;
    out.resolution = SplitTexels(context.map, out.aliasingRatio);
    out.warp = MapWarp::Linear(warp);
    out.warp.x = FitAxis(bx.Centre(), bx.Half(margin), out.resolution.width, nullptr);
    out.warp.y = FitAxis(by.Centre(), by.Half(margin), out.resolution.height, log);
    return out;
}

}  // namespace lexel::spatial
