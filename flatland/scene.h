// The flatland world of Chong 2003: a pinhole camera with a 1D film, a point light, and polyline
// geometry. All positions are world space (ws); angles in degrees where a case file gives them.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/footprint_metrics.h"

namespace lexel::flatland {

using Vec2 = Eigen::Vector2d;

struct FlatCamera {
    Vec2 wsPosition{0, 0};
    Vec2 wsDirection{1, 0};  // unit; normalized by the loader
    double fovDeg = 60.0;    // full field of view
    int pixels = 1000;
    // Hits with depth (distance along wsDirection) outside [near, far] are clipped.
    double near = 0.0;
    double far = std::numeric_limits<double>::infinity();
};

// Thesis §3.2 partitioning options (the "frusta" object of a case file).
struct FrustaOptions {
    int max = 16;    // initial even split of the light's angular range
    int budget = 2;  // frusta that remain
    Metric metric = Metric::kL1;
};

struct FlatScene {
    std::string name;
    FlatCamera camera;
    Vec2 wsLight{0, 10};
    int lexels = 1000;
    std::vector<std::vector<Vec2>> geometry;  // polylines, each ≥ 2 points
    int decisionPixels = 0;                   // 0 = same as camera.pixels
    std::optional<FrustaOptions> frusta;

    int DecisionPixels() const { return decisionPixels > 0 ? decisionPixels : camera.pixels; }
};

struct FlatSegment {
    Vec2 a, b;
    int polyline = 0;  // index into FlatScene::geometry
    int index = 0;     // segment index within the polyline (points index, index+1)
};

std::vector<FlatSegment> Segments(const FlatScene& scene);

// The range of scene sizes lexel accepts (world units). Every coordinate of the camera, the light
// and the geometry is at most kMaxCoordinate in magnitude, and the scene's size (the largest
// distance from the camera to the light or to a geometry point) is at least kMinSceneSize. Inside
// these bounds squared lengths and the solvers' products of up to four lengths stay normal
// doubles (1e±60 ≪ 1e±308), so "zero-length" and "on a segment" mean what they say.
inline constexpr double kMaxCoordinate = 1e15;
inline constexpr double kMinSceneSize = 1e-15;

// Geometric sanity of a scene: coordinates beyond kMaxCoordinate, a scene smaller than
// kMinSceneSize, zero-length segments, the light or the camera on a segment or inside a closed
// polyline. "Zero" and "on" are relative: within 1e-12 of the scene's size. Throws DomainError:
// kCamera / kLight (index {-1, -1}) or kGeometry (index {polyline, point}) for a coordinate too
// large; kGeometry (whole) for a scene too small; Subject::kSegment (index {polyline, segment})
// for a zero-length segment; kLight or kCamera, with the segment's or polyline's index, for the
// rest.
void CheckSceneGeometry(const FlatScene& scene);
// The same without throwing: the error CheckSceneGeometry would throw, or nullopt.
std::optional<DomainError> FindSceneGeometryDefect(const FlatScene& scene);

// Angle helpers. World angles are radians counterclockwise from +x.
double WrapAngle(double radians);  // to (-π, π]
// The lexel plane angle of the thesis tables: counterclockwise from vertical (+y), in (-90, 90].
// The plane is perpendicular to the optical axis, so it equals the axis's world angle mod 180°.
double LexelPlaneDegFromAxis(double wsAxisAngle);

}  // namespace lexel::flatland
