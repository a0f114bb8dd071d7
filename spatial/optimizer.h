// The scene-optimized light matrix: Chong & Gortler's Algorithm 1 (report §2.3–2.4), with one
// convex hull per light instead of one per candidate, and an optional Ceres refinement of p4 on
// the unit sphere (`optimal-refined`).
//
// Algorithm 1 step 4, k times: the gradient g = ∂h/∂p4 (energy_gradient.h, affine rows fixed);
// the rotation axis p4 × (-g); for each candidate angle θ (OptimizerOptions::anglesDeg) the
// rotated axis, its affine part re-fitted (FitMapToPoints: the minimum-area rectangle around the
// visible points, long side on the long map side, with a margin); a candidate is rejected when a
// visible point is not strictly in front of p4·X = 0; the best h is kept. The fit needs only the
// vertices of the visible points' convex hull, for every axis (proof in optimizer.cpp).
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/energy.h"
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
    // The energy the search, the refinement and every choice among candidates minimize
    // (energy.h). The default, h alone, is the report's Algorithm 1, bit for bit.
    EnergyOptions energy;
    // The collapse guard (energy.h, Collapses): a refined matrix whose mean footprint over the
    // prior points exceeds collapseFactor times the searched matrix's is not accepted, whatever
    // its energy. 0: off (today's optimal-refined). kCollapseFactor is the guarded methods'.
    double collapseFactor = 0.0;
    // The view guard of the multi-start (OptimizeFromStarts, multi_start.h): a candidate whose
    // mean footprint over the prior points exceeds starveFactor times the least of the competing
    // starts' maps' is passed over, whatever its energy. 0: off (optimal-h, sdsm-optimal: on
    // its partitions it passed over better maps, RESULTS.md). kStarveFactor is `optimal`'s.
    // OptimizeLightMatrix alone ignores it.
    double starveFactor = 0.0;
    // The sample budget: with more boundary samples than this, the search, the refinement and
    // every choice among candidates run on this many of them, chosen by their pixels
    // (ThinSamples, samples.h), so a finer readback costs no more search time than the budget's;
    // 0: every sample (the report's). The returned energies are then over the kept samples.
    std::size_t maxSamples = 0;
};

// A refinement may trade the view's texels for its samples' by up to this factor in the mean
// footprint (readback pixels per texel, a length: 4× in texel area) before it counts as a
// collapse. Twice the footprint is already a quarter of the resolution over the view, far
// beyond what moving the axis for a few boundary samples should cost; the collapse that
// prompted the guard (h 784 → 0.14 on 7 samples) changes it by far more.
inline constexpr double kCollapseFactor = 2.0;

// How far `optimal`'s multi-start may widen the view's mean footprint (readback pixels per texel,
// over the prior points) past the best-fitted standard map's before the candidate counts as
// starving the view. Samples that are few, or lie where every map is fine, can pull e's search to
// maps that give the rest of the view five times the texel width: the courtyard's directional
// light 39 has no boundary sample and 15 at thin-shadow contacts (samples.h), and the map chosen
// on them (σ₁(J⁻¹) 47.8 pixels per texel over the view, focused-tight's 9.6) misclassifies 195
// pixels over 16 phases where every baseline misclassifies none. Measured on the eight shipped
// sets (RESULTS.md, "Thin shadows at contacts"): 4 passes over that map and moves no set beyond
// its noise; 2 passes over maps that measure better (the meshes' point lights +1.9 ± 1.7%).
inline constexpr double kStarveFactor = 4.0;

// `optimal`'s options: the search and the refinement on e with the prior (kEdgeEnergy), the
// collapse guard and the view guard on. The default OptimizerOptions are the report's Algorithm 1
// on h (optimal-h).
inline OptimizerOptions EdgeOptimizerOptions() {
    OptimizerOptions options;
    options.energy = kEdgeEnergy;
    options.collapseFactor = kCollapseFactor;
    options.starveFactor = kStarveFactor;
    return options;
}

struct OptimizerResult {
    LightMatrix matrix;
    // The chosen energy (OptimizerOptions::energy) of `matrix`: with the default, eq. (6) over the
    // samples, (texels per pixel)⁻² summed: dimensionless. So are hAfterIteration, hBeforeRefine.
    double h = 0.0;
    std::vector<double> hAfterIteration;  // [0] the initial axis, then after each iteration
    double hBeforeRefine = 0.0;
    int candidatesTried = 0, candidatesRejected = 0;
    std::size_t hullVertices = 0;
    std::size_t coneGenerators = 0;  // points the per-light hull started from (3D hull vertices)
    bool usedFallback = false;       // no valid candidate: the initial (focused) fit is returned
    bool refineCollapsed = false;    // the collapse guard rejected the refined matrix
    // Time profile (report Table 3): the per-light 2D hull, the rotation search, the refinement
    // (the per-frame 3D hull is Readback::relevantHullMs).
    double hullMs = 0.0, searchMs = 0.0, refineMs = 0.0;
};

// The cone of the relevant points through its extreme rays (optimizer.cpp), from any generators
// of it: all relevant points, or the light-space 3D hull vertices (lsRelevantHull).
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

// The samples the optimizer runs on under options.maxSamples (the caller checked that there are
// more): ThinSamplesForSearch when it fits from the hull (hullOnce), else ThinSamples (samples.h).
LightSamples SamplesWithinBudget(const LightSamples& samples, const OptimizerOptions& options);

// Algorithm 1 from `initialP4` (InitialLightAxis, baselines.h). Throws DomainError: kCamera when
// the samples have no relevant points; kLight when not even the initial axis sees them all.
OptimizerResult OptimizeLightMatrix(const LightSamples& samples, const glm::dvec3& initialP4,
                                    Resolution map, const OptimizerOptions& options = {});

// The refinement's objective, exposed so that tests can hold it to its definition: the energy of
// FitMapToPoints(p4, vertices, map, options), computed by the scalar-generic re-implementation of
// the fit that the Ceres refinement differentiates (the fit's combinatorial structure, found at
// p4 in double, held fixed). With `gradient`, also ∂h/∂p4 through the fit by automatic
// differentiation (ceres::Jet). nullopt where the objective is undefined: a vertex or sample not
// in front of p4, or fewer than 3 projected hull vertices.
std::optional<double> RefinedObjective(std::span<const glm::dvec3> vertices,
                                       const LightSamples& samples, const glm::dvec3& p4,
                                       Resolution map, const FitOptions& options,
                                       glm::dvec3* gradient = nullptr,
                                       const EnergyOptions& energy = {});

}  // namespace lexel::spatial
