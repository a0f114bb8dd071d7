// The 3D hull (convex_hull_3d.h).
//
// Before Qhull, Akl–Toussaint's pre-filter in 3D (S. G. Akl & G. T. Toussaint, "A fast convex
// hull algorithm", Information Processing Letters 7(5), 1978): the points extreme along the 13
// directions of a 3×3×3 stencil (axes, face and body diagonals) span a polytope E inside the
// hull, whose facets Qhull gives from those few points; a point whose computed signed distance to
// every facet plane of E is ≤ 0 is inside E (up to the rounding of those planes) and cannot be a
// vertex, so only the others go to the full Qhull run, which costs far more per point. Points on
// E's boundary go too, like the floor points on E's bottom face.
//
#include "lexel/solvers/convex_hull_3d.h"

#include <libqhull_r/libqhull_r.h>  // declares its functions extern "C"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"

namespace lexel {
namespace {

std::vector<std::size_t> Iota(std::size_t n) {
    std::vector<std::size_t> all(n);
    std::iota(all.begin(), all.end(), std::size_t{0});
    return all;
}

// Qhull's text sink: an in-memory stream (POSIX open_memstream) that is thrown away, so that
// precision warnings and error reports never reach stdout or stderr.
class DiscardedStream {
  public:
    DiscardedStream() : file_(open_memstream(&buffer_, &size_)) {}
    ~DiscardedStream() {
        if (file_) std::fclose(file_);
        std::free(buffer_);
    }
    DiscardedStream(const DiscardedStream&) = delete;
    DiscardedStream& operator=(const DiscardedStream&) = delete;
    FILE* get() const { return file_; }

  private:
    char* buffer_ = nullptr;
    std::size_t size_ = 0;
    FILE* file_;
};

// One Qhull run over points[subset[k]] (Qhull reads, and keeps pointers into, its own array of
// coordinates); its memory is released however the scope is left.
class QhullRun {
  public:
    QhullRun(std::span<const Eigen::Vector3d> points, std::span<const std::size_t> subset,
             FILE* messages)
        : coordinates_(3 * subset.size()) {
        for (std::size_t k = 0; k < subset.size(); ++k)
            for (int c = 0; c < 3; ++c) coordinates_[3 * k + c] = points[subset[k]][c];
        qh_zero(&qh_, messages);
        // The hull only, with Qhull's default merging of facets within roundoff ('C-0'); 'Q8'
        // skips the partitioning of interior points near a facet, which only matters for the
        // coplanar-point output, unused here. No output file.
        char command[] = "qhull Q8";
        exitCode_ = qh_new_qhull(&qh_, 3, static_cast<int>(subset.size()), coordinates_.data(),
                                 False, command, nullptr, messages);
    }
    ~QhullRun() {
        int curLong = 0, totLong = 0;
        qh_freeqhull(&qh_, !qh_ALL);
        qh_memfreeshort(&qh_, &curLong, &totLong);
    }
    QhullRun(const QhullRun&) = delete;
    QhullRun& operator=(const QhullRun&) = delete;

    int ExitCode() const { return exitCode_; }
    // Positions in `subset` of the hull's vertices, ascending.
    std::vector<std::size_t> Vertices() {
        qhT* qh = &qh_;  // the names FORALLvertices expects
        vertexT* vertex;
        std::vector<std::size_t> vertices;
        FORALLvertices {
            const int id = qh_pointid(qh, vertex->point);
            if (id >= 0 && static_cast<std::size_t>(id) < coordinates_.size() / 3)
                vertices.push_back(static_cast<std::size_t>(id));
        }
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        return vertices;
    }
    // Each facet's outward unit normal and offset: the signed distance of x is normal·x + offset.
    std::vector<std::array<double, 4>> Facets() {
        qhT* qh = &qh_;  // the names FORALLfacets expects
        facetT* facet;
        std::vector<std::array<double, 4>> facets;
        FORALLfacets {
            facets.push_back({facet->normal[0], facet->normal[1], facet->normal[2], facet->offset});
        }
        return facets;
    }

  private:
    std::vector<coordT> coordinates_;
    qhT qh_;
    int exitCode_ = qh_ERRnone;
};

// Akl–Toussaint's pre-filter (S. G. Akl & G. T. Toussaint, "A fast convex hull algorithm",
// Information Processing Letters 7(5), 1978) in 3D: the points extreme along the 13 directions
// of a 3×3×3 stencil (axes, face and body diagonals) span a polytope E inside the hull; a point
// inside E is not a vertex. E's facets come from Qhull; a point is dropped only when its
// computed signed distance to every facet plane is ≤ 0, so only points inside E up to the
// rounding of those planes (Qhull's own roundoff) go; those on E's boundary, like the floor
// points on E's bottom face, go too. Returns the positions in `subset` that remain (the
// extremes included), or all of them when E is flat (Qhull fails on it).
std::vector<std::size_t> OutsideExtremePolytope(std::span<const Eigen::Vector3d> points,
                                                std::span<const std::size_t> subset,
                                                FILE* messages) {
    constexpr int kDirections = 13;
    const auto along = [](const Eigen::Vector3d& p, double* v) {
        const double x = p.x(), y = p.y(), z = p.z();
        v[0] = x, v[1] = y, v[2] = z;
        v[3] = x + y, v[4] = x - y, v[5] = x + z, v[6] = x - z, v[7] = y + z, v[8] = y - z;
        v[9] = x + y + z, v[10] = x + y - z, v[11] = x - y + z, v[12] = x - y - z;
    };
    std::array<std::size_t, kDirections> lo{}, hi{};
    std::array<double, kDirections> loValue, hiValue;
    along(points[subset[0]], loValue.data());
    hiValue = loValue;
    for (std::size_t k = 1; k < subset.size(); ++k) {
        double v[kDirections];
        along(points[subset[k]], v);
        for (int d = 0; d < kDirections; ++d) {
            if (v[d] < loValue[d]) loValue[d] = v[d], lo[d] = k;
            if (v[d] > hiValue[d]) hiValue[d] = v[d], hi[d] = k;
        }
    }
    std::vector<std::size_t> extremes(lo.begin(), lo.end());
    extremes.insert(extremes.end(), hi.begin(), hi.end());
    std::sort(extremes.begin(), extremes.end());
    extremes.erase(std::unique(extremes.begin(), extremes.end()), extremes.end());
    if (extremes.size() < 4) return Iota(subset.size());

    std::vector<std::size_t> extremePoints(extremes.size());
    for (std::size_t j = 0; j < extremes.size(); ++j) extremePoints[j] = subset[extremes[j]];
    QhullRun run(points, extremePoints, messages);
    if (run.ExitCode() != qh_ERRnone) return Iota(subset.size());
    const std::vector<std::array<double, 4>> facets = run.Facets();

    std::vector<char> keep(subset.size(), 0);
    for (std::size_t k : extremes) keep[k] = 1;
    for (std::size_t k = 0; k < subset.size(); ++k) {
        const Eigen::Vector3d& p = points[subset[k]];
        double farthest = -std::numeric_limits<double>::infinity();
        for (const std::array<double, 4>& f : facets)
            farthest = std::max(farthest, f[0] * p.x() + f[1] * p.y() + f[2] * p.z() + f[3]);
        if (farthest > 0.0) keep[k] = 1;
    }
    std::vector<std::size_t> remaining;
    for (std::size_t k = 0; k < subset.size(); ++k)
        if (keep[k]) remaining.push_back(k);
    return remaining;
}

// The planar path (see the header): least-squares plane, exact planar hull of the projections.
// Returns positions in `subset`; all of them when the points are not within kFlatTolerance of
// the plane.
std::vector<std::size_t> PlanarHullVertices(std::span<const Eigen::Vector3d> points,
                                            std::span<const std::size_t> subset) {
    const std::size_t n = subset.size();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (std::size_t i : subset) centroid += points[i];
    centroid /= static_cast<double>(n);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    double radius = 0.0, maxAbs = 0.0;
    for (std::size_t i : subset) {
        const Eigen::Vector3d d = points[i] - centroid;
        covariance += d * d.transpose();
        radius = std::max(radius, d.norm());
        maxAbs = std::max(maxAbs, points[i].cwiseAbs().maxCoeff());
    }
    // Eigenvalues ascending: the first eigenvector is the plane's normal, the last two span it.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
    const Eigen::Vector3d normal = eigen.eigenvectors().col(0);
    const Eigen::Vector3d axisU = eigen.eigenvectors().col(2);
    const Eigen::Vector3d axisV = eigen.eigenvectors().col(1);

    const double tolerance = kFlatTolerance * (maxAbs + radius);
    std::vector<Eigen::Vector2d> planar(n);
    std::vector<std::pair<Eigen::Vector2d, std::size_t>> sorted(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Vector3d d = points[subset[k]] - centroid;
        if (std::abs(normal.dot(d)) > tolerance) return Iota(n);
        planar[k] = {axisU.dot(d), axisV.dot(d)};
        sorted[k] = {planar[k], k};
    }
    // ConvexHull returns its vertices bit for bit; find each one's (lowest) position by binary
    // search over the projections sorted lexicographically, then by position.
    const auto less = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    };
    std::sort(sorted.begin(), sorted.end(), [&](const auto& a, const auto& b) {
        return less(a.first, b.first) || (a.first == b.first && a.second < b.second);
    });
    std::vector<std::size_t> vertices;
    for (const Eigen::Vector2d& v : ConvexHull(planar)) {
        const auto it = std::lower_bound(
            sorted.begin(), sorted.end(), v,
            [&](const auto& entry, const Eigen::Vector2d& p) { return less(entry.first, p); });
        vertices.push_back(it->second);
    }
    std::sort(vertices.begin(), vertices.end());
    return vertices;
}

}  // namespace

std::vector<std::size_t> ConvexHullVertices3D(std::span<const Eigen::Vector3d> points) {
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw std::invalid_argument("convex hull 3d: point " + std::to_string(k) +
                                        " is not finite");
    const std::vector<std::size_t> all = Iota(points.size());
    if (points.size() < 4) return points.empty() ? all : PlanarHullVertices(points, all);

    DiscardedStream messages;
    if (!messages.get()) return all;  // nowhere to send Qhull's messages: keep every point
    const std::vector<std::size_t> candidates = OutsideExtremePolytope(points, all, messages.get());

    std::vector<std::size_t> positions;
    {
        QhullRun run(points, candidates, messages.get());
        // Qhull fails on flat, collinear or coincident input ("initial simplex is flat"); the
        // planar path checks the flatness itself and keeps every candidate when it fails too.
        positions =
            run.ExitCode() == qh_ERRnone ? run.Vertices() : PlanarHullVertices(points, candidates);
    }
    std::vector<std::size_t> vertices(positions.size());
    for (std::size_t j = 0; j < positions.size(); ++j) vertices[j] = candidates[positions[j]];
    return vertices;  // ascending: positions and candidates are
}

}  // namespace lexel
