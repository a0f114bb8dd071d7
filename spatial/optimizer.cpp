#include "lexel/spatial/optimizer.h"

#include <ceres/ceres.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Core>
#include <chrono>
#include <cmath>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/min_area_parallelogram.h"
#include "lexel/spatial/energy_gradient.h"

namespace lexel::spatial {
namespace {

double MsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// Cross product and dot product for any scalar type.
template <typename T>
void Cross(const T* a, const T* b, T* out) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// The combinatorics of a minimum-area rectangle around projected hull vertices: the flush edge
// (a → b) and the vertices extreme along and across it. With the shear (FitOptions::shear) the
// parallelogram's: the shear k* = (u·(y_i - y_j)) / (v·(y_j - y_i)) from the adjacent hull
// vertices i, j that tie at it (shearI = -1: k* = 0), minU and maxU extreme in the sheared
// coordinate (u + k* v)·y, minV = a (the edge's line) and maxV the vertex farthest from it.
struct RectangleStructure {
    int a, b, minU, maxU, minV, maxV;
    bool swapAxes;  // the long side must go on the other map axis
    int shearI = -1, shearJ = -1;
};

// The minimum-area parallelogram's structure, from the solver itself
// (MinAreaParallelogramOfHull), so that ties and the choice of k* are the fit's exactly.
std::optional<RectangleStructure> FindShearedStructure(const std::vector<Eigen::Vector2d>& hull,
                                                       const std::vector<int>& index,
                                                       Resolution map) {
    ParallelogramStructure ps;
    const Parallelogram2 par = MinAreaParallelogramOfHull(hull, &ps);
    if (ps.edge < 0) return std::nullopt;
    const auto at = [&](int k) { return index[static_cast<std::size_t>(k) % index.size()]; };
    RectangleStructure s{at(ps.edge), at(ps.edge + 1), at(ps.minS), at(ps.maxS),
                         at(ps.edge), at(ps.top),      false};
    // As OrientLongSideAlong(Parallelogram2): side lengths, not extents.
    s.swapAxes = map.width >= map.height ? par.halfU < par.halfV : par.halfV < par.halfU;
    if (ps.shearEdge >= 0) s.shearI = at(ps.shearEdge), s.shearJ = at(ps.shearEdge + 1);
    return s;
}

// Brute-force rotating calipers over h vertices (h is small): the minimum-area rectangle's
// structure, ties to the first edge as in solvers/min_area_rectangle.
std::optional<RectangleStructure> FindStructure(const std::vector<glm::dvec2>& y, Resolution map,
                                                bool shear) {
    std::vector<Eigen::Vector2d> pts(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) pts[i] = {y[i].x, y[i].y};
    const std::vector<Eigen::Vector2d> hull = ConvexHull(pts);
    if (hull.size() < 3) return std::nullopt;
    std::vector<int> index(hull.size());
    for (std::size_t k = 0; k < hull.size(); ++k)
        for (std::size_t i = 0; i < pts.size(); ++i)
            if (pts[i] == hull[k]) {
                index[k] = static_cast<int>(i);
                break;
            }
    if (shear) return FindShearedStructure(hull, index, map);
    std::optional<RectangleStructure> best;
    double bestArea = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const int a = index[k], b = index[(k + 1) % hull.size()];
        const glm::dvec2 u = glm::normalize(y[b] - y[a]);
        const glm::dvec2 v(-u.y, u.x);
        RectangleStructure s{a, b, a, a, a, a, false};
        double lo[2] = {glm::dot(u, y[a]), glm::dot(v, y[a])}, hi[2] = {lo[0], lo[1]};
        for (int i : index) {
            const double pu = glm::dot(u, y[i]), pv = glm::dot(v, y[i]);
            if (pu < lo[0]) lo[0] = pu, s.minU = i;
            if (pu > hi[0]) hi[0] = pu, s.maxU = i;
            if (pv < lo[1]) lo[1] = pv, s.minV = i;
            if (pv > hi[1]) hi[1] = pv, s.maxV = i;
        }
        const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if (area < bestArea) {
            bestArea = area;
            s.swapAxes = (hi[0] - lo[0] >= hi[1] - lo[1]) != (map.width >= map.height);
            best = s;
        }
    }
    return best;
}

// h(fit(p4)) for the hull vertices and samples, differentiable in p4 through the fit for a fixed
// rectangle structure (FitMapToPlanePoints written for any scalar type).
struct RefinedEnergy {
    // scale multiplies h: 1 / h0 inside the refinement, as LBFGS's first line search tries a
    // unit step along −∇, a rotation of |∇| radians; h itself is in the thousands to millions,
    // and an unscaled first step leaves the valid cone and fails the line search.
    RefinedEnergy(std::span<const glm::dvec3> vertices, const LightSamples* samples, Resolution map,
                  const FitOptions& options, double scale = 1.0)
        : vertices(vertices),
          samples(samples),
          map(map),
          margin(options.margin),
          shear(options.shear),
          scale(scale) {}

    std::span<const glm::dvec3> vertices;
    const LightSamples* samples;
    Resolution map;
    double margin;
    bool shear = false;
    double scale = 1.0;

    template <typename T>
    bool operator()(const T* p4, T* energy) const {
        // The structure and the plane basis are chosen in double, locally constant in p4.
        const glm::dvec3 p4d(ceres::internal::AsScalar(p4[0]), ceres::internal::AsScalar(p4[1]),
                             ceres::internal::AsScalar(p4[2]));
        for (const glm::dvec3& v : vertices)
            if (!InFront(p4d, v)) return false;
        glm::dvec3 b1d, b2d;
        PlaneBasis(p4d, &b1d, &b2d);
        // b1 = normalize(helper × p4), b2 = p4 × b1, with the same helper axis as PlaneBasis.
        const glm::dvec3 helper = PlaneBasisHelper(p4d);
        const T h[3] = {T(helper.x), T(helper.y), T(helper.z)};
        T b1[3], b2[3];
        Cross(h, p4, b1);
        const T n1 = sqrt(b1[0] * b1[0] + b1[1] * b1[1] + b1[2] * b1[2]);
        for (T& c : b1) c /= n1;
        Cross(p4, b1, b2);

        std::vector<glm::dvec2> yd(vertices.size());
        for (std::size_t i = 0; i < yd.size(); ++i) {
            const glm::dvec3& v = vertices[i];
            const double w = glm::dot(p4d, v);
            yd[i] = {glm::dot(b1d, v) / w, glm::dot(b2d, v) / w};
        }
        const std::optional<RectangleStructure> s = FindStructure(yd, map, shear);
        if (!s) return false;
        const auto project = [&](int i, T* y) {
            const glm::dvec3& v = vertices[i];
            const T w = p4[0] * v.x + p4[1] * v.y + p4[2] * v.z;
            y[0] = (b1[0] * v.x + b1[1] * v.y + b1[2] * v.z) / w;
            y[1] = (b2[0] * v.x + b2[1] * v.y + b2[2] * v.z) / w;
        };
        T ya[2], yb[2], y[4][2];
        project(s->a, ya);
        project(s->b, yb);
        project(s->minU, y[0]);
        project(s->maxU, y[1]);
        project(s->minV, y[2]);
        project(s->maxV, y[3]);
        T u[2] = {yb[0] - ya[0], yb[1] - ya[1]};
        const T un = sqrt(u[0] * u[0] + u[1] * u[1]);
        u[0] /= un;
        u[1] /= un;
        T v[2] = {-u[1], u[0]};
        if (s->shearI >= 0) {
            // k* = u·(y_i - y_j) / v·(y_j - y_i): vertices i, j tie in (u + k v)·y. The map row
            // along the edge reads that sheared coordinate (FitMapToPlanePoints with shear).
            T yi[2], yj[2];
            project(s->shearI, yi);
            project(s->shearJ, yj);
            const T k = (u[0] * (yi[0] - yj[0]) + u[1] * (yi[1] - yj[1])) /
                        (v[0] * (yj[0] - yi[0]) + v[1] * (yj[1] - yi[1]));
            u[0] += k * v[0];
            u[1] += k * v[1];
        }
        T loU = u[0] * y[0][0] + u[1] * y[0][1], hiU = u[0] * y[1][0] + u[1] * y[1][1];
        T loV = v[0] * y[2][0] + v[1] * y[2][1], hiV = v[0] * y[3][0] + v[1] * y[3][1];
        if (s->swapAxes) {  // +90° turn of the frame, as OrientLongSideAlong
            const T newU[2] = {v[0], v[1]}, newV[2] = {-u[0], -u[1]};
            const T nLoU = loV, nHiU = hiV, nLoV = -hiU, nHiV = -loU;
            u[0] = newU[0], u[1] = newU[1], v[0] = newV[0], v[1] = newV[1];
            loU = nLoU, hiU = nHiU, loV = nLoV, hiV = nHiV;
        }
        const T halfU = T(0.5 * (1.0 + margin)) * (hiU - loU);
        const T halfV = T(0.5 * (1.0 + margin)) * (hiV - loV);
        const T kU = T(0.5 * map.width) / halfU, kV = T(0.5 * map.height) / halfV;
        const T cU = T(0.5) * (loU + hiU), cV = T(0.5) * (loV + hiV);
        // p1 = (W/2 - kU cU) p4 + kU (u.x b1 + u.y b2); p2 likewise (light_matrix.cpp).
        T p1[3], p2[3];
        for (int c = 0; c < 3; ++c) {
            p1[c] = (T(0.5 * map.width) - kU * cU) * p4[c] + kU * (u[0] * b1[c] + u[1] * b2[c]);
            p2[c] = (T(0.5 * map.height) - kV * cV) * p4[c] + kV * (v[0] * b1[c] + v[1] * b2[c]);
        }
        T total(0.0);
        for (std::size_t k = 0; k < samples->lsX.size(); ++k) {
            const glm::dvec3& X = samples->lsX[k];
            if (!(ceres::internal::AsScalar(p4[0] * X.x + p4[1] * X.y + p4[2] * X.z) > 0.0))
                return false;
            total += SampleEnergy(p1, p2, p4, X, samples->dXdx1[k], samples->dXdx2[k]);
        }
        *energy = total * T(scale);
        return ceres::internal::AsScalar(total) < std::numeric_limits<double>::infinity();
    }
};

}  // namespace

std::optional<double> RefinedObjective(std::span<const glm::dvec3> vertices,
                                       const LightSamples& samples, const glm::dvec3& p4,
                                       Resolution map, const FitOptions& options,
                                       glm::dvec3* gradient) {
    const RefinedEnergy energy(vertices, &samples, map, options);
    if (!gradient) {
        double h = 0.0;
        const double x[3] = {p4.x, p4.y, p4.z};
        if (!energy(x, &h)) return std::nullopt;
        return h;
    }
    using Jet = ceres::Jet<double, 3>;
    const Jet x[3] = {Jet(p4.x, 0), Jet(p4.y, 1), Jet(p4.z, 2)};
    Jet h;
    if (!energy(x, &h)) return std::nullopt;
    *gradient = {h.v[0], h.v[1], h.v[2]};
    return h.a;
}

RelevantHull::RelevantHull(std::span<const glm::dvec3> lsRelevant, const glm::dvec3& p4Reference) {
    if (lsRelevant.empty()) throw InputError("optimizer: no relevant points");
    glm::dvec3 b1, b2;
    PlaneBasis(p4Reference, &b1, &b2);
    std::vector<Eigen::Vector2d> y;
    y.reserve(lsRelevant.size());
    for (const glm::dvec3& X : lsRelevant) {
        if (!InFront(p4Reference, X))
            throw InputError("optimizer: a relevant point is behind the initial axis's plane");
        const double w = glm::dot(p4Reference, X);
        y.emplace_back(glm::dot(b1, X) / w, glm::dot(b2, X) / w);
    }
    // Akl–Toussaint pre-filter (S. G. Akl & G. T. Toussaint, "A fast convex hull algorithm",
    // Information Processing Letters 7(5), 1978): a point strictly inside the quadrilateral of the
    // four axis extremes cannot be a hull vertex. One O(N) pass leaves only a thin boundary layer
    // for the O(N log N) sort of the monotone chain. A point is dropped only when the rounded
    // cross product clears its error bound (1e-14 of the operands' magnitude, far above the few
    // ulps of rounding), so only points certainly inside go; borderline ones stay for the exact
    // hull.
    std::size_t extreme[4] = {0, 0, 0, 0};  // min x, min y, max x, max y
    for (std::size_t i = 1; i < y.size(); ++i) {
        if (y[i].x() < y[extreme[0]].x()) extreme[0] = i;
        if (y[i].y() < y[extreme[1]].y()) extreme[1] = i;
        if (y[i].x() > y[extreme[2]].x()) extreme[2] = i;
        if (y[i].y() > y[extreme[3]].y()) extreme[3] = i;
    }
    std::vector<Eigen::Vector2d> candidates;
    candidates.reserve(y.size() / 4 + 4);
    for (std::size_t i = 0; i < y.size(); ++i) {
        bool inside = true;  // strictly left of every counter-clockwise quadrilateral edge
        for (int e = 0; e < 4 && inside; ++e) {
            const Eigen::Vector2d& a = y[extreme[e]];
            const Eigen::Vector2d ab = y[extreme[(e + 1) % 4]] - a, ap = y[i] - a;
            const double cross = ab.x() * ap.y() - ab.y() * ap.x();
            const double bound = 1e-14 * (std::abs(ab.x()) + std::abs(ab.y())) *
                                 (std::abs(ap.x()) + std::abs(ap.y()));
            inside = cross > bound;
        }
        if (!inside) candidates.push_back(y[i]);
    }
    for (const Eigen::Vector2d& v : ConvexHull(candidates))
        vertices_.push_back(v.x() * b1 + v.y() * b2 + p4Reference);
}

std::optional<LightMatrix> RelevantHull::Fit(const glm::dvec3& p4, Resolution map,
                                             const FitOptions& options) const {
    return FitMapToPoints(p4, vertices_, map, options);
}

glm::dvec3 RotateAxis(const glm::dvec3& p4, const glm::dvec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return glm::normalize(p4 * c + glm::cross(k, p4) * s + k * glm::dot(k, p4) * (1.0 - c));
}

OptimizerResult OptimizeLightMatrix(const LightSamples& samples, const glm::dvec3& initialP4,
                                    Resolution map, const OptimizerOptions& options) {
    if (samples.lsRelevant.empty()) throw InputError("optimizer: no relevant points");
    OptimizerResult r;
    const FitOptions fitOptions{options.margin, options.shear};

    // The generators of the cone of relevant rays: the light-space images of the readback's 3D
    // hull vertices when the readback has them (see the header comment), else every point.
    const std::span<const glm::dvec3> lsCone =
        (options.hullOnce && !samples.lsRelevantHull.empty())
            ? std::span<const glm::dvec3>(samples.lsRelevantHull)
            : std::span<const glm::dvec3>(samples.lsRelevant);
    r.coneGenerators = lsCone.size();

    auto start = std::chrono::steady_clock::now();
    std::optional<RelevantHull> hull;
    if (options.hullOnce) {
        try {
            hull.emplace(lsCone, glm::normalize(initialP4));
            r.hullVertices = hull->Vertices().size();
        } catch (const InputError&) {
            hull.reset();  // the initial axis does not see every point: fit from every generator
        }
    }
    r.hullMs = MsSince(start);
    const auto fit = [&](const glm::dvec3& p4) {
        return hull ? hull->Fit(p4, map, fitOptions) : FitMapToPoints(p4, lsCone, map, fitOptions);
    };

    start = std::chrono::steady_clock::now();
    const BoundedEnergy energy(samples);  // Energy, stopping once h reaches the bound
    glm::dvec3 p4 = glm::normalize(initialP4);
    std::optional<LightMatrix> best = fit(p4);
    double bestH = best ? energy(*best) : std::numeric_limits<double>::infinity();
    r.hAfterIteration.push_back(bestH);
    for (int it = 0; it < options.iterations && best; ++it) {
        const glm::dvec3 g = EnergyGradientAnalytic(*best, samples);
        const glm::dvec3 axis = glm::cross(p4, -g);
        const double axisLength = glm::length(axis);
        if (!(axisLength > 0.0) || !std::isfinite(axisLength)) break;
        const glm::dvec3 unitAxis = axis / axisLength;
        glm::dvec3 nextP4 = p4;
        for (double deg : options.anglesDeg) {
            ++r.candidatesTried;
            const glm::dvec3 candidate = RotateAxis(p4, unitAxis, glm::radians(deg));
            const std::optional<LightMatrix> m = fit(candidate);
            if (!m) {
                ++r.candidatesRejected;
                continue;
            }
            const double h = energy(*m, bestH);
            if (h < bestH) {
                bestH = h;
                best = m;
                nextP4 = candidate;
            }
        }
        p4 = nextP4;
        r.hAfterIteration.push_back(bestH);
    }
    r.searchMs = MsSince(start);
    if (!best) {
        // Not even the initial axis sees every relevant point; nothing to optimize.
        r.usedFallback = true;
        best = FitMapToPoints(glm::normalize(initialP4), lsCone, map, fitOptions);
        if (!best) throw InputError("optimizer: no light matrix sees every relevant point");
        bestH = Energy(*best, samples);
    }
    r.hBeforeRefine = bestH;

    if (options.refine && hull && hull->Vertices().size() >= 3 && !samples.lsX.empty()) {
        start = std::chrono::steady_clock::now();
        double x[3] = {p4.x, p4.y, p4.z};
        ceres::GradientProblem problem(
            new ceres::AutoDiffFirstOrderFunction<RefinedEnergy, 3>(
                new RefinedEnergy(hull->Vertices(), &samples, map, fitOptions, 1.0 / bestH)),
            new ceres::SphereManifold<3>());
        ceres::GradientProblemSolver::Options solverOptions;
        solverOptions.max_num_iterations = options.refineIterations;
        solverOptions.logging_type = ceres::SILENT;
        // Run to the iteration limit or a stationary point: h/h0 changes of 1e-12 still move p4
        // by ~1e-6 rad near a flat minimum (the default 1e-6 stops ~1e-3 rad short).
        solverOptions.function_tolerance = 1e-12;
        // The Wolfe line search grows a decreasing step by this factor (default 10): on the
        // sphere a step of a few radians wraps around and lands outside the valid cone, which the
        // zoom phase cannot recover from. Tripling keeps the bracket within a fraction of a turn.
        solverOptions.max_line_search_step_expansion = 3.0;
        ceres::GradientProblemSolver::Summary summary;
        ceres::Solve(solverOptions, problem, x, &summary);
        const glm::dvec3 refined = glm::normalize(glm::dvec3(x[0], x[1], x[2]));
        if (const std::optional<LightMatrix> m = fit(refined)) {
            const double h = Energy(*m, samples);
            if (h < bestH) {
                bestH = h;
                best = m;
            }
        }
        r.refineMs = MsSince(start);
    }
    r.matrix = *best;
    r.h = bestH;
    return r;
}

}  // namespace lexel::spatial
