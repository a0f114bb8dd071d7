#include "lexel/flatland/baselines.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

namespace {
// The optical axis is perpendicular to a film (lexel plane) direction v.
double AxisOfFilmDirection(const Vec2& v) {
    return std::atan2(v.y(), v.x()) + 0.5 * std::numbers::pi;
}
}  // namespace

BaselineAxis NormalAxis(const SamplingPass& pass) { return {pass.wsAxis0, {}}; }

BaselineAxis PlaneOptimalAxis(const FlatScene& scene, const Vec2& wsA, const Vec2& wsB) {
    const Vec2 c = scene.camera.wsPosition;
    const Vec2 viewPlane = Perp(scene.camera.wsDirection);
    const Vec2 e = wsB - wsA;
    const double denom = Cross(e, viewPlane);
    // Parallel within 1e-12 rad: q is at infinity along the segment.
    if (std::abs(denom) <= 1e-12 * e.norm())
        return {AxisOfFilmDirection(e), "segment parallel to the view plane"};
    // wsA + λ e = c + μ viewPlane.
    const double lambda = Cross(c - wsA, viewPlane) / denom;
    const Vec2 q = wsA + lambda * e;
    const Vec2 v = q - scene.wsLight;
    if (v.norm() <=
        1e-12 * e.norm())  // the light is q itself: any film through it; use the view plane
        return {AxisOfFilmDirection(viewPlane), "light at the segment's view-plane point"};
    return {AxisOfFilmDirection(v), {}};
}

BaselineAxis PlaneOptimalAxis(const FlatScene& scene) {
    return PlaneOptimalAxis(scene, scene.geometry.at(0).at(0), scene.geometry.at(0).at(1));
}

namespace {

enum class PsmFilm { kPole, kNearPlane };

BaselineAxis PsmAxisImpl(const FlatScene& scene, const SamplingPass& pass, PsmFilm film) {
    const FlatCamera& cam = scene.camera;
    const Vec2 d = cam.wsDirection, u = Perp(d);
    const double tanHalf = std::tan(Radians(0.5 * cam.fovDeg));
    double n = cam.near, f = cam.far;
    if (!(n > 0.0) || !std::isfinite(f)) {
        n = pass.depthNear, f = pass.depthFar;
        f = std::max(f, n * (1.0 + 1e-9));  // a single depth: keep the depth map invertible
    }
    // Camera projection to PPS (homogeneous): (x_c, y_c, 1) ↦ (y_c / tan(fov/2), A x_c − B, x_c),
    // A = (f+n)/(f−n), B = 2fn/(f−n): depth n ↦ −1 and f ↦ +1 after division by w = x_c.
    const double A = (f + n) / (f - n), B = 2.0 * f * n / (f - n);
    auto toPps = [&](const Vec2& ws, double& X, double& Z, double& w) {
        const Vec2 cs = ws - cam.wsPosition;
        const double xc = cs.dot(d), yc = cs.dot(u);
        X = yc / tanHalf, Z = A * xc - B, w = xc;
    };
    double lX, lZ, lw;
    toPps(scene.wsLight, lX, lZ, lw);
    // Direction in which the light's ray travels at each PPS point P: w_L P − (X_L, Z_L). For a
    // light in front of the camera (w_L > 0) this is P − L'; behind it (w_L < 0) the ray passes
    // through infinity and arrives from the far side, L' − P; on the view plane (w_L = 0) the
    // light is directional in PPS.
    // Nothing per sample is stored (flatland/memory.h): the PPS points are recomputed per loop.
    const auto ppsAt = [&](const FlatSample& s) {
        double X, Z, w;
        toPps(s.wsPoint, X, Z, w);
        return Vec2{X / w, Z / w};
    };
    double ref = 0.0, lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < pass.samples.size(); ++i) {
        const Vec2 dir = lw * ppsAt(pass.samples[i]) - Vec2{lX, lZ};
        const double angle = std::atan2(dir.y(), dir.x());
        if (i == 0) ref = angle;
        const double rayAngle = WrapAngle(angle - ref);
        lo = std::min(lo, rayAngle), hi = std::max(hi, rayAngle);
    }
    if (hi - lo >= std::numbers::pi)
        return {pass.wsAxis0, "PPS rays span 180 degrees or more; normal axis used"};
    const double axis = ref + 0.5 * (lo + hi);
    const Vec2 a{std::cos(axis), std::sin(axis)};
    const Vec2 cameraAxis = d;
    double c = INFINITY;
    if (film == PsmFilm::kNearPlane) {
        // Near plane as far forward as possible: through the first point the rays reach.
        for (const FlatSample& s : pass.samples) c = std::min(c, a.dot(ppsAt(s)));
    } else {
        // The pole: the PPS line through the light perpendicular to a. A light on the view plane
        // (w_L = 0, within 1e-12 of the scene's depth scale) has the line at infinity as its pole,
        // whose pre-image is the view plane: the film is parallel to it and the axis is d.
        if (std::abs(lw) <= 1e-12 * f) return {std::atan2(cameraAxis.y(), cameraAxis.x()), {}};
        c = a.dot(Vec2{lX / lw, lZ / lw});
    }
    // The PPS line a·(X, Z) = c pulled back to camera space: multiply
    // a_x y_c/tan(fov/2)/x_c + a_z (A − B/x_c) = c by x_c:
    //     (a_z A − c) x_c + (a_x / tan(fov/2)) y_c − a_z B = 0,
    // a world line whose normal (in the camera's (d, u) frame) is the lexel plane's axis.
    const double nx = a.y() * A - c, ny = a.x() / tanHalf;
    const Vec2 wsNormal = nx * d + ny * u;
    if (wsNormal.norm() == 0.0)
        return {pass.wsAxis0, "PSM near plane degenerate; normal axis used"};
    return {std::atan2(wsNormal.y(), wsNormal.x()), {}};
}

}  // namespace

BaselineAxis PsmAxis(const FlatScene& scene, const SamplingPass& pass) {
    return PsmAxisImpl(scene, pass, PsmFilm::kPole);
}

BaselineAxis PsmThesisAxis(const FlatScene& scene, const SamplingPass& pass) {
    return PsmAxisImpl(scene, pass, PsmFilm::kNearPlane);
}

}  // namespace lexel::flatland
