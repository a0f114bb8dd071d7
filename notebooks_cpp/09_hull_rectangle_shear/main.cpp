// 09 — The affine part of P: convex hull, minimum-area rectangle, and the exact shear.
//
// Given the optical axis p4, the other rows of P only place the map: project the visible points
// centrally onto the plane p4·X = 1, and map the smallest rectangle around them onto the shadow
// map (Chong & Gortler, Algorithm 1 step 4b-ii; Brabec et al. 2002). The rectangle encloses the
// points' convex hull (Andrew's monotone chain) and has a side flush with a hull edge (Freeman &
// Shapira 1975), so rotating calipers over the h hull edges find it. The report shears the
// rectangle heuristically to "better line up with the edge's endpoints" (§2.3, Fig. 3); optimized
// exactly, that is the minimum-area enclosing parallelogram (solvers/min_area_parallelogram.h).
// This program prints the areas and how much of each shape the visible points fill (initial →
// final), and h of eq. (6) for both fits. The checks, by brute force: the rectangle's area is the
// least bounding box over the hull-edge directions and over 3600 other directions; the
// parallelogram's is the least over all pairs of hull-edge directions (a side pair's width over
// |sin| is monotone between them); both enclose every point.
//
// Public API: lexel::solvers (ConvexHull, MinAreaRectangle, MinAreaParallelogram),
// lexel::spatial (ProjectToPlaneInFront, FitMapToPoints, Energy). Toy renderer and figure: the
// programs' own.
//
//   ./build/notebooks_cpp/notebook_09_hull_rectangle_shear [OUT_DIR]  (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/min_area_parallelogram.h"
#include "lexel/solvers/min_area_rectangle.h"
#include "lexel/spatial.h"
#include "notebook.h"
#include "plot.h"
#include "toy_renderer.h"

namespace {

using Eigen::Vector2d;

// max − min of n·p over the points: the width across direction n (unit).
double Width(const std::vector<Vector2d>& points, const Vector2d& n) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vector2d& p : points) lo = std::min(lo, n.dot(p)), hi = std::max(hi, n.dot(p));
    return hi - lo;
}

lexel::notebooks::Series Outline(const char* label, const std::vector<Vector2d>& corners) {
    lexel::notebooks::Series s(label, lexel::notebooks::Series::Style::kPolygon);
    for (const Vector2d& c : corners) s.Add(c.x(), c.y());
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace lexel;
    using namespace lexel::spatial;
    const auto outDir = notebooks::OutputDirectory(argc, argv);
    const notebooks::ToyRenderer renderer({160, 120});
    const glm::dmat4 screenFromWorld = renderer.ScreenFromWorld();
    const Readback readback = MakeReadback(
        CameraBufferFromDepth(renderer.resolution(), renderer.DepthBuffer(), screenFromWorld),
        screenFromWorld);
    const LightSpace lightSpace(Light{Light::Type::kPoint, renderer.wsLight(), {}},
                                renderer.SceneBounds());
    const LightSamples samples =
        MakeLightSamples(readback, lightSpace, renderer.ShadowMask(readback));
    const glm::dvec3 p4 = InitialLightAxis(lightSpace, renderer.SceneBounds(), readback.wsRelevant);

    std::vector<Vector2d> points;
    const std::vector<glm::dvec2> planePoints = *ProjectToPlaneInFront(p4, samples.lsRelevant);
    for (const glm::dvec2& y : planePoints) points.emplace_back(y.x, y.y);
    const std::vector<Vector2d> hull = ConvexHull(points);
    const Parallelogram2 rectangle = MinAreaRectangle(points);
    const Parallelogram2 parallelogram = MinAreaParallelogram(points);
    double hullArea = 0;
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const Vector2d &a = hull[k], &b = hull[(k + 1) % hull.size()];
        hullArea += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    std::printf(
        "%zu visible points on the plane p4·X = 1; their hull has %zu vertices, area %.6g\n",
        points.size(), hull.size(), hullArea);
    std::printf(
        "rectangle area %.6g, parallelogram area %.6g (shear angle %.2f°)\n", rectangle.Area(),
        parallelogram.Area(),
        90 - std::acos(parallelogram.axisU.dot(parallelogram.axisV)) * 180 / std::numbers::pi);
    std::printf("map used by the visible points, rectangle → parallelogram: %.2f%% → %.2f%%\n",
                100 * hullArea / rectangle.Area(), 100 * hullArea / parallelogram.Area());
    const Resolution map{1024, 1024};
    const double hRectangle =
        Energy(*FitMapToPoints(p4, samples.lsRelevant, map, {0.02, false}), samples);
    const double hShear =
        Energy(*FitMapToPoints(p4, samples.lsRelevant, map, {0.02, true}), samples);
    std::printf("h (eq. 6) over %zu boundary samples, rectangle → parallelogram: %.6g → %.6g\n",
                samples.lsX.size(), hRectangle, hShear);

    // Brute force: bounding boxes along every hull edge and 3600 more directions; parallelograms
    // with side pairs along every two hull edges (area = width_i · width_j / |sin|).
    std::vector<Vector2d> normals;
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const Vector2d e = (hull[(k + 1) % hull.size()] - hull[k]).normalized();
        normals.emplace_back(-e.y(), e.x());
    }
    double boxEdges = INFINITY, boxOthers = INFINITY, pairs = INFINITY;
    for (const Vector2d& n : normals)
        boxEdges = std::min(boxEdges, Width(points, n) * Width(points, {-n.y(), n.x()}));
    for (int k = 0; k < 3600; ++k) {
        const double a = (k + 0.5) * std::numbers::pi / 7200;  // 0 to 90°: a box repeats after that
        boxOthers = std::min(boxOthers, Width(points, {std::cos(a), std::sin(a)}) *
                                            Width(points, {-std::sin(a), std::cos(a)}));
    }
    for (const Vector2d& ni : normals)
        for (const Vector2d& nj : normals)
            if (const double sine = std::abs(ni.x() * nj.y() - ni.y() * nj.x()); sine > 1e-12)
                pairs = std::min(pairs, Width(points, ni) * Width(points, nj) / sine);
    const double tolerance = 1e-12 * std::sqrt(rectangle.Area());
    const bool inside = std::all_of(points.begin(), points.end(), [&](const Vector2d& p) {
        return rectangle.Contains(p, tolerance) && parallelogram.Contains(p, tolerance);
    });

    notebooks::Claims claims;
    claims.Check(std::abs(rectangle.Area() / boxEdges - 1) < 1e-12 && rectangle.Area() <= boxOthers,
                 "rectangle %.9g = least box over hull edges %.9g <= over 3600 directions %.9g",
                 rectangle.Area(), boxEdges, boxOthers);
    claims.Check(std::abs(parallelogram.Area() / pairs - 1) < 1e-9,
                 "parallelogram %.9g = least over pairs of hull edges %.9g", parallelogram.Area(),
                 pairs);
    claims.Check(inside, "every visible point lies in both (tolerance %.1e)", tolerance);

    notebooks::Series cloud("visible points", notebooks::Series::Style::kPoints,
                            notebooks::Rgb{0.6, 0.6, 0.6}, 1.2);
    for (std::size_t k = 0; k < points.size(); k += 7) cloud.Add(points[k].x(), points[k].y());
    const auto corners = [](const Parallelogram2& p) {
        const auto c = p.Corners();
        return std::vector<Vector2d>(c.begin(), c.end());
    };
    const auto figure = outDir / "09_hull_rectangle_shear.png";
    notebooks::Panel plot("visible points on the plane p4·X = 1", "y1", "y2", false, true);
    plot.series = {cloud, Outline("min-area rectangle", corners(rectangle)),
                   Outline("min-area parallelogram", corners(parallelogram)),
                   Outline("convex hull", hull)};
    notebooks::WritePlot(figure, {plot});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
