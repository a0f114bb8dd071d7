#include "lexel/flatland/scene.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

std::vector<FlatSegment> Segments(const FlatScene& scene) {
    std::vector<FlatSegment> segments;
    for (std::size_t i = 0; i < scene.geometry.size(); ++i) {
        const auto& polyline = scene.geometry[i];
        for (std::size_t j = 0; j + 1 < polyline.size(); ++j)
            segments.push_back(
                {polyline[j], polyline[j + 1], static_cast<int>(i), static_cast<int>(j)});
    }
    return segments;
}

namespace {

// Distance from p to segment [a, b].
double DistanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double len2 = e.squaredNorm();
    const double s = len2 > 0 ? std::clamp((p - a).dot(e) / len2, 0.0, 1.0) : 0.0;
    return (a + s * e - p).norm();
}

// Even-odd point-in-polygon for a closed polyline (first point == last point).
bool InsideClosed(const Vec2& p, const std::vector<Vec2>& polyline) {
    bool inside = false;
    for (std::size_t j = 0; j + 1 < polyline.size(); ++j) {
        const Vec2& a = polyline[j];
        const Vec2& b = polyline[j + 1];
        if ((a.y() > p.y()) != (b.y() > p.y())) {
            const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
            if (x > p.x()) inside = !inside;
        }
    }
    return inside;
}

// |v| without overflow or underflow of the squares (a scene scaled by 1e-300 has a size).
double Length(const Vec2& v) { return std::hypot(v.x(), v.y()); }

double SceneScale(const FlatScene& scene) {
    double scale = Length(scene.camera.wsPosition - scene.wsLight);
    for (const auto& polyline : scene.geometry)
        for (const Vec2& p : polyline) scale = std::max(scale, Length(p - scene.camera.wsPosition));
    return scale;
}

std::string FormatCoordinate(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

// The first point with a coordinate beyond kMaxCoordinate (or not finite), as the error to throw.
std::optional<DomainError> FindCoordinateTooLarge(const FlatScene& scene) {
    const auto tooLarge = [](const Vec2& p) {
        return !(p.cwiseAbs().maxCoeff() <= kMaxCoordinate);
    };
    const auto reason = [](const Vec2& p) {
        return "coordinate too large: |x| = " + FormatCoordinate(p.cwiseAbs().maxCoeff()) +
               ", must be at most " + FormatCoordinate(kMaxCoordinate);
    };
    if (tooLarge(scene.camera.wsPosition))
        return DomainError(Subject::kCamera, reason(scene.camera.wsPosition));
    if (tooLarge(scene.wsLight)) return DomainError(Subject::kLight, reason(scene.wsLight));
    for (std::size_t i = 0; i < scene.geometry.size(); ++i)
        for (std::size_t j = 0; j < scene.geometry[i].size(); ++j)
            if (tooLarge(scene.geometry[i][j]))
                return DomainError(Subject::kGeometry, reason(scene.geometry[i][j]),
                                   {static_cast<int>(i), static_cast<int>(j)});
    return std::nullopt;
}

}  // namespace

std::optional<DomainError> FindSceneGeometryDefect(const FlatScene& scene) {
    // Bounded coordinates first: beyond them the squared lengths below overflow or underflow and
    // every segment would look zero-length.
    if (std::optional<DomainError> defect = FindCoordinateTooLarge(scene)) return defect;
    const double size = SceneScale(scene);
    if (!(size >= kMinSceneSize))
        return DomainError(Subject::kGeometry,
                           "the scene is too small: its size (the largest distance from the "
                           "camera to the light or a geometry point) is " +
                               FormatCoordinate(size) + ", must be at least " +
                               FormatCoordinate(kMinSceneSize));
    // Distances below 1e-12 of the scene's size are "on" a segment: at double precision such a
    // point cannot be told apart from one lying on it.
    const double onEps = 1e-12 * size;
    for (std::size_t i = 0; i < scene.geometry.size(); ++i) {
        const auto& polyline = scene.geometry[i];
        const int poly = static_cast<int>(i);
        for (std::size_t j = 0; j + 1 < polyline.size(); ++j) {
            const std::string seg =
                "segment " + std::to_string(j) + " of polyline " + std::to_string(i);
            const std::array<int, 2> at = {poly, static_cast<int>(j)};
            const double length = Length(polyline[j + 1] - polyline[j]);
            if (length <= onEps) {
                const std::string points =
                    "points " + std::to_string(j) + " and " + std::to_string(j + 1);
                return DomainError(Subject::kSegment,
                                   length == 0.0 ? "zero-length segment (" + points + " coincide)"
                                                 : "zero-length segment (" + points + " are " +
                                                       FormatCoordinate(length) +
                                                       " apart, within 1e-12 of the scene's size " +
                                                       FormatCoordinate(size) + ")",
                                   at);
            }
            if (DistanceToSegment(scene.wsLight, polyline[j], polyline[j + 1]) <= onEps)
                return DomainError(Subject::kLight, "the light lies on " + seg, at);
            if (DistanceToSegment(scene.camera.wsPosition, polyline[j], polyline[j + 1]) <= onEps)
                return DomainError(Subject::kCamera, "the camera lies on " + seg, at);
        }
        const bool closed =
            polyline.size() >= 4 && (polyline.front() - polyline.back()).norm() <= onEps;
        const std::string where = "the closed polyline " + std::to_string(i);
        if (closed && InsideClosed(scene.wsLight, polyline))
            return DomainError(Subject::kLight, "the light is inside " + where, {poly, -1});
        if (closed && InsideClosed(scene.camera.wsPosition, polyline))
            return DomainError(Subject::kCamera, "the camera is inside " + where, {poly, -1});
    }
    return std::nullopt;
}

void CheckSceneGeometry(const FlatScene& scene) {
    if (std::optional<DomainError> defect = FindSceneGeometryDefect(scene)) throw *defect;
}

double WrapAngle(double radians) {
    double a = std::remainder(radians, 2.0 * std::numbers::pi);  // [-π, π]
    if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
    return a;
}

double LexelPlaneDegFromAxis(double wsAxisAngle) {
    double deg = std::remainder(Degrees(wsAxisAngle), 180.0);  // [-90, 90]
    if (deg <= -90.0) deg += 180.0;
    return deg;
}

}  // namespace lexel::flatland
