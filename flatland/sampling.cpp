#include "lexel/flatland/sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

namespace {

// dα/dλ = (d_L × e) / |d_L|², d_L = X − L: the light angle's rate along the segment.
double LightAngleDerivative(const Vec2& wsLight, const Vec2& wsPoint, const Vec2& wsTangent) {
    const Vec2 toPoint = wsPoint - wsLight;
    return Cross(toPoint, wsTangent) / toPoint.squaredNorm();
}

}  // namespace

std::optional<RayHit> CastPixelRay(const FlatCamera& camera,
                                   const std::vector<FlatSegment>& segments, int pixels, double p) {
    const Vec2 d = camera.wsDirection;
    const Vec2 u = Perp(d);
    const double sigma = 2.0 * p / pixels - 1.0;
    const Vec2 ray = d + std::tan(Radians(0.5 * camera.fovDeg)) * sigma * u;  // ray·d == 1
    std::optional<RayHit> best;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const Vec2 a = segments[s].a;
        const Vec2 e = segments[s].b - a;
        // Solve C + depth·ray = A + λ e  ⇒  depth·ray − λ e = A − C.
        const double denom = Cross(ray, e);
        // A ray within 1e-14 (relative) of parallel to the segment only grazes it: no hit.
        if (std::abs(denom) <= 1e-14 * ray.norm() * e.norm()) continue;
        const Vec2 ac = a - camera.wsPosition;
        const double depth = Cross(ac, e) / denom;
        const double lambda = Cross(ac, ray) / denom;
        if (lambda < 0.0 || lambda > 1.0) continue;
        if (!(depth > 0.0) || depth < camera.near || depth > camera.far) continue;
        if (!best || depth < best->depth)
            best = RayHit{camera.wsPosition + depth * ray, depth, static_cast<int>(s), lambda};
    }
    return best;
}

double PixelDerivativeAlong(const FlatCamera& camera, int pixels, const Vec2& wsPoint,
                            const Vec2& wsTangent) {
    const Vec2 d = camera.wsDirection;
    const Vec2 u = Perp(d);
    const Vec2 cs = wsPoint - camera.wsPosition;
    const double xc = cs.dot(d), yc = cs.dot(u);
    const double scale = pixels / (2.0 * std::tan(Radians(0.5 * camera.fovDeg)));
    return scale * (wsTangent.dot(u) * xc - wsTangent.dot(d) * yc) / (xc * xc);
}

double PixelsPerLambda(const SamplingPass& pass, const FlatSample& s) {
    return PixelDerivativeAlong(pass.camera, pass.pixels, s.wsPoint, SegmentTangent(pass, s));
}

double PixelsPerRadian(const SamplingPass& pass, const FlatSample& s) {
    const Vec2 wsTangent = SegmentTangent(pass, s);
    const double dpdLambda = PixelDerivativeAlong(pass.camera, pass.pixels, s.wsPoint, wsTangent);
    return std::abs(dpdLambda / LightAngleDerivative(pass.wsLight, s.wsPoint, wsTangent));
}

std::optional<SamplingPass> TrySamplingPass(const FlatScene& scene, int pixels,
                                            std::optional<DomainError>* defect) {
    const auto fail = [&](DomainError error) -> std::optional<SamplingPass> {
        if (defect) defect->emplace(std::move(error));
        return std::nullopt;
    };
    SamplingPass pass;
    pass.pixels = pixels;
    pass.camera = scene.camera;
    pass.wsLight = scene.wsLight;
    pass.segments = Segments(scene);
    const std::vector<FlatSegment>& segments = pass.segments;
    // Every pixel may be visible: reserving them all keeps growth from doubling the peak.
    pass.samples.reserve(pixels);
    pass.depthNear = INFINITY;
    double wsRef = 0.0;  // world angle of the first visible point, to unwrap the others
    double lo = 0.0, hi = 0.0;
    for (int k = 0; k < pixels; ++k) {
        const auto hit = CastPixelRay(scene.camera, segments, pixels, k + 0.5);
        if (!hit) continue;
        const Vec2 wsTangent = segments[hit->segment].b - segments[hit->segment].a;
        const Vec2 toPoint = hit->wsPoint - scene.wsLight;
        const double dAlphadLambda = LightAngleDerivative(scene.wsLight, hit->wsPoint, wsTangent);
        // A light within 1e-12 rad per unit λ of the segment's line sees the segment edge-on: every
        // pixel on it maps to one lexel and its footprint is unbounded.
        if (std::abs(dAlphadLambda) * toPoint.norm() <= 1e-12 * wsTangent.norm()) {
            const auto& seg = segments[hit->segment];
            return fail(
                DomainError(Subject::kSegment,
                            "the light lies on this visible segment's line, so its footprint "
                            "dp/dl is unbounded",
                            {seg.polyline, seg.index}));
        }
        const double wsAngle = std::atan2(toPoint.y(), toPoint.x());
        if (pass.samples.empty()) wsRef = wsAngle;
        FlatSample s;
        s.wsPoint = hit->wsPoint;
        s.lsAngle = WrapAngle(wsAngle - wsRef);  // exact unwrapping while the sweep is < 180°
        s.pixel = k;
        s.segment = hit->segment;
        lo = std::min(lo, s.lsAngle), hi = std::max(hi, s.lsAngle);
        pass.depthNear = std::min(pass.depthNear, hit->depth);
        pass.depthFar = std::max(pass.depthFar, hit->depth);
        pass.samples.push_back(s);
    }
    if (pass.samples.empty())
        return fail(
            DomainError(Subject::kGeometry, "no camera pixel sees any geometry (Ω is empty)"));

    // The sweep: with all angles taken relative to one visible point, a set that fits in an open
    // half-plane has relative angles spanning less than π, and one that does not spans at least π.
    const double sweep = hi - lo;
    if (sweep >= std::numbers::pi * (1.0 - 1e-12))
        return fail(DomainError(
            Subject::kLight,
            "the visible points span " + std::to_string(Degrees(sweep)) +
                " degrees as seen from the light; no lexel plane has them all in front"));
    // Zero extent: all visible points on one ray from the light (1e-12 rad is the angular
    // resolution of double-precision atan2 at unit scale).
    if (sweep <= 1e-12)
        return fail(DomainError(Subject::kLight,
                                "all visible points lie on one ray from the light; the lexel plane "
                                "would have zero extent"));
    const double mid = 0.5 * (lo + hi);
    pass.wsAxis0 = WrapAngle(wsRef + mid);
    pass.halfSweep = 0.5 * sweep;
    for (auto& s : pass.samples) s.lsAngle -= mid;
    // Rounding is monotone, so the extremes of the shifted angles are the shifted extremes.
    pass.lsLow = lo - mid, pass.lsHigh = hi - mid;
    return pass;
}

SamplingPass RunSamplingPass(const FlatScene& scene, int pixels) {
    std::optional<DomainError> defect;
    std::optional<SamplingPass> pass = TrySamplingPass(scene, pixels, &defect);
    if (!pass) throw *defect;
    return std::move(*pass);
}

}  // namespace lexel::flatland
