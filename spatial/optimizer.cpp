// Algorithm 1 (optimizer.h): why one hull per frame and one per light suffice, and how the
// refinement differentiates the fit.
//
// One 3D hull per frame, one 2D hull per light. Let C be the cone of light rays through the
// relevant points X_i. A linear functional positive on generators of C is positive on their
// conic combinations, so p4·X > 0 holds for all points iff it holds for the generators; and
// projecting centrally onto the plane p4·X = 1 sends C to the convex set conv(projected
// generators) whenever every generator is in front (the central projection between two planes is
// a homography, which maps a segment to a segment when no point of it crosses the horizon, so
// convex combinations go to convex combinations and extreme points to extreme points). The
// extreme rays of C are exactly the vertices of the convex hull of the points projected onto any
// one valid plane — here the initial axis's (RelevantHull). So that 2D hull is computed once per
// light, and every candidate transforms only its h vertices: a rectangle around the hull of the
// projected vertices is the rectangle around all projected points.
//
// The generators need not be all N relevant points: the vertices v_j of the 3D convex hull of
// their world points x_i (Readback::wsRelevantHull, computed once per frame) generate C for every
// light. Light space is an affine image of world space that keeps the homogeneous part: X = R(x -
// L) for a point light, X = (e1·(x - o), e2·(x - o), s) for a directional one (light_space.h).
// Writing x_i = Σ_j λ_j v_j with λ_j ≥ 0, Σ_j λ_j = 1, an affine map gives X_i = Σ_j λ_j X(v_j):
// every relevant X is a convex, hence conic, combination of the vertices' X, so C is the cone of
// the vertices (which are relevant points themselves). The in-front test with its margin
// (InFront: p4·X > ε|X|, ε = 1e-9) also carries over: if every vertex passes, then
// p4·X_i = Σ_j λ_j p4·X(v_j) > ε Σ_j λ_j |X(v_j)| ≥ ε |Σ_j λ_j X(v_j)| = ε |X_i| (triangle
// inequality), and conversely the vertices are among the points. So fitting and rejecting from
// the vertices (LightSamples::lsRelevantHull, a few dozen) gives the decisions and matrices of
// all N points, up to the rounding of the hull (Qhull's roundoff; solvers/convex_hull_3d.h). The
// cost is one O(N log N) 3D hull per frame (most points never reach Qhull: samples.h) and
// O(h log h) per light and candidate, instead of O(k·|θ|·N log N) per light.
//
// `optimal-refined`: after the search, Ceres' line-search solver (LBFGS) minimizes h over p4 on
// the unit sphere (ceres::SphereManifold<3>) with the affine part re-fitted inside the objective.
// The minimum-area rectangle is piecewise smooth in p4 (its combinatorics — the flush hull edge
// and the four extreme vertices — are locally constant), so the objective re-derives that
// structure in double at each evaluation and differentiates the fit through it with Jets.
#include "lexel/spatial/optimizer.h"

#include <ceres/ceres.h>
#include <ceres/sphere_manifold.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"
#include "lexel/solvers/min_area_parallelogram.h"
#include "lexel/solvers/min_area_rectangle.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/affine_fit.h"
#include "lexel/spatial/energy_gradient.h"

namespace lexel::spatial {
namespace {

// The combinatorics of the fit at p4 (minimum-area rectangle, or parallelogram with the shear)
// around the projected vertices y, in vertex indices, from the solvers themselves, so that ties
// and the choice of k* are the fit's exactly; and whether the long side goes on the other axis.
struct FitStructure {
    int a, b;        // the flush edge a → b
    int minU, maxU;  // extreme in the (sheared) edge coordinate
    int top;         // farthest from the edge's line (the edge itself is the other side)
    int shearI = -1, shearJ = -1;  // the adjacent vertices tying at k* (-1: k* = 0)
    bool swapAxes = false;
};

std::optional<FitStructure> FindStructure(const std::vector<glm::dvec2>& y, Resolution map,
                                          bool shear) {
    std::vector<Eigen::Vector2d> pts(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) pts[i] = {y[i].x, y[i].y};
    const std::vector<Eigen::Vector2d> hull = ConvexHull(pts);
    if (hull.size() < 3) return std::nullopt;
    std::vector<int> index(hull.size());
    for (std::size_t k = 0; k < hull.size(); ++k)
        index[k] = static_cast<int>(std::find(pts.begin(), pts.end(), hull[k]) - pts.begin());
    ParallelogramStructure ps;
    const Parallelogram2 fit =
        shear ? MinAreaParallelogramOfHull(hull, &ps) : MinAreaRectangleOfHull(hull, &ps);
    const auto at = [&](int k) { return index[static_cast<std::size_t>(k) % index.size()]; };
    FitStructure s{at(ps.edge), at(ps.edge + 1), at(ps.minS), at(ps.maxS), at(ps.top)};
    if (ps.shearEdge >= 0) s.shearI = at(ps.shearEdge), s.shearJ = at(ps.shearEdge + 1);
    // Whether OrientLongSideAlong turns the frame (it swaps unequal half sides only).
    s.swapAxes = OrientLongSideAlong(fit, map.width >= map.height).halfU != fit.halfU;
    return s;
}

// h(fit(p4)) for the hull vertices and samples, differentiable in p4 through the fit for a fixed
// rectangle structure (FitMapToPlanePoints written for any scalar type).
struct RefinedEnergy {
    // scale multiplies h: 1 / h0 inside the refinement, as LBFGS's first line search tries a
    // unit step along −∇, a rotation of |∇| radians; h itself is in the thousands to millions,
    // and an unscaled first step leaves the valid cone and fails the line search.
    RefinedEnergy(std::span<const glm::dvec3> vertices, const LightSamples* samples, Resolution map,
                  const FitOptions& options, double scale = 1.0, const EnergyOptions& energy = {})
        : vertices(vertices),
          samples(samples),
          map(map),
          margin(options.margin),
          shear(options.shear),
          scale(scale),
          energy(energy) {}

    std::span<const glm::dvec3> vertices;
    const LightSamples* samples;
    Resolution map;
    double margin;
    bool shear = false;
    double scale = 1.0;
    EnergyOptions energy;

    // The chosen energy of the rows p1, p2 and axis p4 over the samples and the prior (energy.h).
    template <typename T>
    T Total(const T* p1, const T* p2, const T* p4, bool* inFront) const {
        const LightSamples& s = *samples;
        const bool edge = energy.kind == EnergyKind::kEdge;
        const bool normals = s.edgeNormal.size() == s.lsX.size();
        T total(0.0);
        for (std::size_t k = 0; k < s.lsX.size(); ++k) {
            const glm::dvec3& X = s.lsX[k];
            if (!(ceres::internal::AsScalar(p4[0] * X.x + p4[1] * X.y + p4[2] * X.z) > 0.0)) {
                *inFront = false;
                return total;
            }
            if (!edge)
                total += SampleEnergy(p1, p2, p4, X, s.dXdx1[k], s.dXdx2[k]);
            else
                total +=
                    SampleEdgeEnergy(p1, p2, p4, X, s.dXdx1[k], s.dXdx2[k],
                                     normals ? s.edgeNormal[k] : glm::dvec2(0.0), energy.exponent);
        }
        *inFront = true;
        if (energy.priorWeight == 0.0 || s.lsPrior.empty()) return total;
        T prior(0.0);
        for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
            const glm::dvec3& X = s.lsPrior[k];
            if (!(ceres::internal::AsScalar(p4[0] * X.x + p4[1] * X.y + p4[2] * X.z) > 0.0))
                continue;
            const T f = edge ? SampleEdgeEnergy(p1, p2, p4, X, s.priorDXdx1[k], s.priorDXdx2[k],
                                                glm::dvec2(0.0), energy.exponent)
                             : SampleEnergy(p1, p2, p4, X, s.priorDXdx1[k], s.priorDXdx2[k]);
            if (std::isfinite(ceres::internal::AsScalar(f))) prior += f;
        }
        return total + prior * T(energy.priorWeight / static_cast<double>(s.lsPrior.size()));
    }

    template <typename T>
    bool operator()(const T* p4, T* energy) const {
        // The structure and the plane basis are chosen in double, locally constant in p4.
        const glm::dvec3 p4d(ceres::internal::AsScalar(p4[0]), ceres::internal::AsScalar(p4[1]),
                             ceres::internal::AsScalar(p4[2]));
        for (const glm::dvec3& v : vertices)
            if (!InFront(p4d, v)) return false;
        glm::dvec3 b1d, b2d;
        PlaneBasis(p4d, &b1d, &b2d);
        T b1[3], b2[3];
        PlaneBasis(p4, PlaneBasisHelper(p4d), b1, b2);  // the same basis, differentiable

        std::vector<glm::dvec2> yd(vertices.size());
        for (std::size_t i = 0; i < yd.size(); ++i)
            yd[i] = ProjectToAxisPlane(p4d, b1d, b2d, vertices[i]);
        const std::optional<FitStructure> s = FindStructure(yd, map, shear);
        if (!s) return false;
        const auto project = [&](int i, T* y) { ProjectToAxisPlane(p4, b1, b2, vertices[i], y); };
        T ya[2], yb[2], y[3][2];
        project(s->a, ya);
        project(s->b, yb);
        project(s->minU, y[0]);
        project(s->maxU, y[1]);
        project(s->top, y[2]);
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
        T loV = v[0] * ya[0] + v[1] * ya[1], hiV = v[0] * y[2][0] + v[1] * y[2][1];
        if (s->swapAxes) {  // +90° turn of the frame, as OrientLongSideAlong
            const T newU[2] = {v[0], v[1]}, newV[2] = {-u[0], -u[1]};
            const T nLoU = loV, nHiU = hiV, nLoV = -hiU, nHiV = -loU;
            u[0] = newU[0], u[1] = newU[1], v[0] = newV[0], v[1] = newV[1];
            loU = nLoU, hiU = nHiU, loV = nLoV, hiV = nHiV;
        }
        const detail::PlaneFrame<T> frame{{u[0], u[1]},         {v[0], v[1]},
                                          T(0.5) * (loU + hiU), T(0.5) * (loV + hiV),
                                          T(0.5) * (hiU - loU), T(0.5) * (hiV - loV)};
        T p1[3], p2[3];
        detail::AffineRowsFromFrame(p4, b1, b2, frame, map, margin, p1, p2);
        bool inFront = true;
        const T total = Total(p1, p2, p4, &inFront);
        if (!inFront) return false;
        *energy = total * T(scale);
        return ceres::internal::AsScalar(total) < std::numeric_limits<double>::infinity();
    }
};

}  // namespace

std::optional<double> RefinedObjective(std::span<const glm::dvec3> vertices,
                                       const LightSamples& samples, const glm::dvec3& p4,
                                       Resolution map, const FitOptions& options,
                                       glm::dvec3* gradient, const EnergyOptions& energyOptions) {
    const RefinedEnergy energy(vertices, &samples, map, options, 1.0, energyOptions);
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

std::optional<RelevantHull> RelevantHull::Of(std::span<const glm::dvec3> lsRelevant,
                                             const glm::dvec3& p4Reference) {
    if (lsRelevant.empty()) return std::nullopt;
    const std::optional<std::vector<glm::dvec2>> planePoints =
        ProjectToPlaneInFront(p4Reference, lsRelevant);
    if (!planePoints) return std::nullopt;
    RelevantHull hull;
    glm::dvec3 b1, b2;
    PlaneBasis(p4Reference, &b1, &b2);
    std::vector<Eigen::Vector2d> y;
    y.reserve(planePoints->size());
    for (const glm::dvec2& yX : *planePoints) y.emplace_back(yX.x, yX.y);
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
        hull.vertices_.push_back(v.x() * b1 + v.y() * b2 + p4Reference);
    return hull;
}

std::optional<LightMatrix> RelevantHull::Fit(const glm::dvec3& p4, Resolution map,
                                             const FitOptions& options) const {
    return FitMapToPoints(p4, vertices_, map, options);
}

glm::dvec3 RotateAxis(const glm::dvec3& p4, const glm::dvec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return glm::normalize(p4 * c + glm::cross(k, p4) * s + k * glm::dot(k, p4) * (1.0 - c));
}

LightSamples SamplesWithinBudget(const LightSamples& samples, const OptimizerOptions& options) {
    return options.hullOnce ? ThinSamplesForSearch(samples, options.maxSamples)
                            : ThinSamples(samples, options.maxSamples);
}

namespace {

// Step 4b-ii for an axis: the map fitted around the cone of relevant rays, from the readback's
// hull when there is one (RelevantHull::Fit), else from every generator (FitMapToPoints).
struct AxisFit {
    const RelevantHull* hull;  // null: fit from every generator
    std::span<const glm::dvec3> lsCone;
    Resolution map;
    FitOptions options;
    std::optional<LightMatrix> operator()(const glm::dvec3& p4) const {
        return hull ? hull->Fit(p4, map, options) : FitMapToPoints(p4, lsCone, map, options);
    }
};

// Where the search stands: the axis it is at, and the best map and energy so far.
struct AxisSearch {
    glm::dvec3 p4;
    std::optional<LightMatrix> best;
    double bestH = std::numeric_limits<double>::infinity();
};

// Algorithm 1's search (report §2.3): from `initialP4`, `options.iterations` times, rotate the
// axis by each of options.anglesDeg about p4 × (−∇) and keep the candidate of least energy.
// Counts candidates and the energy after each iteration into `r`.
AxisSearch SearchAxis(const AxisFit& fit, const SearchEnergy& energy, const glm::dvec3& initialP4,
                      const OptimizerOptions& options, OptimizerResult& r) {
    AxisSearch s{glm::normalize(initialP4), std::nullopt};
    s.best = fit(s.p4);
    s.bestH = s.best ? energy(*s.best) : std::numeric_limits<double>::infinity();
    r.hAfterIteration.push_back(s.bestH);
    for (int it = 0; it < options.iterations && s.best; ++it) {
        const glm::dvec3 g = energy.Gradient(*s.best);
        const glm::dvec3 axis = glm::cross(s.p4, -g);
        const double axisLength = glm::length(axis);
        if (!(axisLength > 0.0) || !std::isfinite(axisLength)) break;
        const glm::dvec3 unitAxis = axis / axisLength;
        glm::dvec3 nextP4 = s.p4;
        for (double deg : options.anglesDeg) {
            ++r.candidatesTried;
            const glm::dvec3 candidate = RotateAxis(s.p4, unitAxis, glm::radians(deg));
            const std::optional<LightMatrix> m = fit(candidate);
            if (!m) {
                ++r.candidatesRejected;
                continue;
            }
            const double h = energy(*m, s.bestH);
            if (h < s.bestH) {
                s.bestH = h;
                s.best = m;
                nextP4 = candidate;
            }
        }
        s.p4 = nextP4;
        r.hAfterIteration.push_back(s.bestH);
    }
    return s;
}

// The search's axis refined by Ceres LBFGS on the sphere (OptimizerOptions::refine), kept when
// its energy is lower and the map does not collapse (Collapses); sets r.refineCollapsed.
void RefineAxis(const AxisFit& fit, const LightSamples& samples, const OptimizerOptions& options,
                AxisSearch& s, OptimizerResult& r) {
    double x[3] = {s.p4.x, s.p4.y, s.p4.z};
    ceres::GradientProblem problem(
        new ceres::AutoDiffFirstOrderFunction<RefinedEnergy, 3>(new RefinedEnergy(
            fit.hull->Vertices(), &samples, fit.map, fit.options, 1.0 / s.bestH, options.energy)),
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
        const double h = Energy(*m, samples, options.energy);
        if (h < s.bestH && Collapses(*s.best, *m, samples, options.collapseFactor)) {
            r.refineCollapsed = true;
        } else if (h < s.bestH) {
            s.bestH = h;
            s.best = m;
        }
    }
}

}  // namespace

OptimizerResult OptimizeLightMatrix(const LightSamples& samples, const glm::dvec3& initialP4,
                                    Resolution map, const OptimizerOptions& options) {
    if (options.maxSamples != 0 && samples.lsX.size() > options.maxSamples) {
        OptimizerOptions every = options;
        every.maxSamples = 0;
        return OptimizeLightMatrix(SamplesWithinBudget(samples, options), initialP4, map, every);
    }
    if (samples.lsRelevant.empty())
        throw DomainError(Subject::kCamera, "the camera sees nothing: no relevant points");
    OptimizerResult r;
    const FitOptions fitOptions{options.margin, options.shear};

    // The generators of the cone of relevant rays: the light-space images of the readback's 3D
    // hull vertices when the readback has them (see the header comment), else every point.
    const std::span<const glm::dvec3> lsCone =
        (options.hullOnce && !samples.lsRelevantHull.empty())
            ? std::span<const glm::dvec3>(samples.lsRelevantHull)
            : std::span<const glm::dvec3>(samples.lsRelevant);
    r.coneGenerators = lsCone.size();

    Stopwatch timer;
    std::optional<RelevantHull> hull;
    // Without the hull (the initial axis does not see every point) fit from every generator.
    if (options.hullOnce) hull = RelevantHull::Of(lsCone, glm::normalize(initialP4));
    if (hull) r.hullVertices = hull->Vertices().size();
    r.hullMs = timer.Ms();
    const AxisFit fit{hull ? &*hull : nullptr, lsCone, map, fitOptions};

    timer.Restart();
    const SearchEnergy energy(samples, options.energy);  // stops once the bound is reached
    AxisSearch s = SearchAxis(fit, energy, initialP4, options, r);
    r.searchMs = timer.Ms();
    if (!s.best) {
        // Not even the initial axis sees every relevant point; nothing to optimize.
        r.usedFallback = true;
        s.best = FitMapToPoints(glm::normalize(initialP4), lsCone, map, fitOptions);
        if (!s.best)
            throw DomainError(Subject::kLight,
                              "no light matrix from the initial axis sees every visible point");
        s.bestH = Energy(*s.best, samples, options.energy);
    }
    r.hBeforeRefine = s.bestH;

    // h = 0 without samples: nothing to refine. The other energies have the prior to go by.
    const bool anything = !samples.lsX.empty() || (options.energy.priorWeight > 0.0 &&
                                                   !samples.lsPrior.empty() && s.bestH > 0.0);
    if (options.refine && hull && hull->Vertices().size() >= 3 && anything) {
        timer.Restart();
        RefineAxis(fit, samples, options, s, r);
        r.refineMs = timer.Ms();
    }
    r.matrix = *s.best;
    r.h = s.bestH;
    return r;
}

}  // namespace lexel::spatial
