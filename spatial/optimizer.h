// The scene-optimized light matrix: Chong & Gortler's Algorithm 1 (report §2.3–2.4), the hull-once
// speed-up, and a Ceres refinement of p4 on the unit sphere.
//
// Algorithm 1 step 4, k times: the gradient g = ∂h/∂p4 (energy_gradient.h, affine rows fixed);
// the rotation axis p4 × (-g); for each candidate angle θ ∈ {-10, 3, 5, 9, 16, 23, 30, 40, 50}°
// the rotated axis, its affine part re-fitted (light_matrix.h: minimum-area rectangle around the
// convex hull of the relevant points, long side on the long map side, margin for the subsampled
// readback), rejected when a relevant point is not strictly in front of p4·X = 0; keep the best h
// (each candidate's h through BoundedEnergy, samples.h, which stops once it reaches the best).
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
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

struct OptimizerOptions {
    int iterations = 3;                                                  // report §2.4: k = 3
    std::vector<double> anglesDeg = {-10, 3, 5, 9, 16, 23, 30, 40, 50};  // report §2.4
    // Fraction added to each half extent of the fitted rectangle: the readback is subsampled
    // (180² for a 750² frame), so visible points between samples can fall just outside a tight
    // fit (report §2.4, last paragraph).
    double margin = 0.02;
    // true: fit from the per-light 2D hull of the frame's 3D hull vertices (lsRelevantHull, or
    // every relevant point when the samples have none); false: re-fit from all relevant points
    // per candidate (the reference path).
    bool hullOnce = true;
    bool refine = false;  // optimal-refined
    int refineIterations = 40;
    // The report's affine shear (§2.3, Fig. 3), optimized exactly: every candidate's affine part
    // from the minimum-area enclosing parallelogram (FitOptions::shear, light_matrix.h).
    // `optimal-shear`. Combined with `refine`, the Ceres objective differentiates the sheared
    // fit through its locally constant structure (RefinedObjective).
    bool shear = false;
};

struct OptimizerResult {
    LightMatrix matrix;
    double h = 0.0;
    std::vector<double> hAfterIteration;  // [0] the initial axis, then after each iteration
    double hBeforeRefine = 0.0;
    int candidatesTried = 0, candidatesRejected = 0;
    std::size_t hullVertices = 0;
    std::size_t coneGenerators = 0;  // points the per-light hull started from (3D hull vertices)
    bool usedFallback = false;       // no valid candidate: the initial (focused) fit is returned
    // Time profile (report Table 3): the per-light 2D hull, the rotation search, the refinement
    // (the per-frame 3D hull is Readback::relevantHullMs).
    double hullMs = 0.0, searchMs = 0.0, refineMs = 0.0;
};

// The cone of the relevant points through its extreme rays (see the header comment), from any
// generators of it: all relevant points, or the light-space 3D hull vertices (lsRelevantHull).
class RelevantHull {
  public:
    // The hull of the points projected on the plane p4Reference·X = 1; nullopt when there are no
    // points or some point is not in front of it (InFront).
    static std::optional<RelevantHull> Of(std::span<const glm::dvec3> lsRelevant,
                                          const glm::dvec3& p4Reference);
    std::span<const glm::dvec3> Vertices() const { return vertices_; }
    // FitMapToPoints(p4, all relevant points) from the hull vertices only.
    std::optional<LightMatrix> Fit(const glm::dvec3& p4, Resolution map,
                                   const FitOptions& options) const;

  private:
    RelevantHull() = default;
    std::vector<glm::dvec3> vertices_;  // on the plane p4Reference·X = 1
};

// p4 rotated by `angle` radians about the unit axis (Rodrigues).
glm::dvec3 RotateAxis(const glm::dvec3& p4, const glm::dvec3& unitAxis, double angle);

// Algorithm 1 from `initialP4` (InitialLightAxis, baselines.h). Throws DomainError: kCamera when
// the samples have no relevant points; kLight when not even the initial axis sees them all.
OptimizerResult OptimizeLightMatrix(const LightSamples& samples, const glm::dvec3& initialP4,
                                    Resolution map, const OptimizerOptions& options = {});

// The refinement's objective, exposed so that tests can hold it to its definition: h of
// FitMapToPoints(p4, vertices, map, options), computed by the scalar-generic re-implementation of
// the fit that the Ceres refinement differentiates (the fit's combinatorial structure, found at
// p4 in double, held fixed). With `gradient`, also ∂h/∂p4 through the fit by automatic
// differentiation (ceres::Jet). nullopt where the objective is undefined: a vertex or sample not
// in front of p4, or fewer than 3 projected hull vertices.
std::optional<double> RefinedObjective(std::span<const glm::dvec3> vertices,
                                       const LightSamples& samples, const glm::dvec3& p4,
                                       Resolution map, const FitOptions& options,
                                       glm::dvec3* gradient = nullptr);

}  // namespace lexel::spatial
