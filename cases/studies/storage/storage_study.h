// `lexel storage`: Lloyd et al. 2006's storage factor S̄ (spatial/studies/storage_factor.h) for one
// view frustum — the data of the paper's Figs. 5–7, 10, 12 and 13 — and, for a 3D case, every
// method's measured storage factor (MethodOutcome::storageFactor) beside the analytic S̄ of its
// scheme for the case's own camera and beside S̄_opt.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/methods/method_info.h"
#include "lexel/spatial/studies/storage_factor.h"

namespace lexel::cases {

struct StorageOptions {
    int warpPoints = 41;        // η samples from -1 to 1 (Figs. 5–6), ≥ 2
    int hemisphereSize = 61;    // Fig. 7's image side, ≥ 1
    int maxMaps = 16;           // Figs. 10 and 12: k, j = 1..maxMaps
    int maxFacePartitions = 5;  // Fig. 13: j = 4m maps, m = 1..maxFacePartitions
};

// Fig. 7 for one scheme: S̄ over the hemisphere of lights, its smallest and largest value.
struct HemisphereStudy {
    std::string scheme;  // "no warp", "LiSPSM", "FP + W"
    spatial::HemisphereGrid grid;
    double minStorage = 0.0, maxStorage = 0.0;
};

struct StorageStudy {
    spatial::ViewFrustum frustum;
    double optimal = 0.0;  // S̄_opt (Appendix C)
    // Figs. 5–6, light overhead: S̄ against η for f/n = 20, 100 (the paper's) and the frustum's
    // own (n kept, f = ratio · n; fov and aspect the frustum's). Duplicate ratios appear once.
    std::vector<double> warpRatios;
    std::vector<std::vector<spatial::WarpSweepPoint>> warp;  // [ratio][η]
    std::vector<spatial::PartitionSweepPoint> partitions;    // Fig. 10
    std::vector<spatial::MapCountPoint> maps;                // Fig. 12
    std::vector<spatial::CrossoverPoint> crossover;          // Fig. 13
    std::vector<HemisphereStudy> hemisphere;                 // Fig. 7
};

// Throws spatial::StorageFactorError for a frustum outside ValidateFrustum's domain.
StorageStudy RunStorageStudy(const spatial::ViewFrustum& frustum,
                             const StorageOptions& options = {});

// ---- measured beside analytic, on a 3D case -----------------------------------------------------

// The view frustum of a camera (fov, aspect from its resolution, near, far).
spatial::ViewFrustum FrustumOf(const spatial::Camera& camera);

// The analytic S̄ (vertex rule, EvaluateScheme) a storage model gives the light, with k maps for
// the partitioned models: its scheme's label and value. kBestSingleMap: the smallest S̄ over n'
// (BestSingleMapStorage); kUnwarped "no warp" (η = ∞); kLispsm "LiSPSM" (η = 0); kPsm "PSM"
// (η = 1); kTrapezoid the single map of n' = (f − n) / (3 sin γ), the 80% rule with the focus at
// mid-depth; kLogPsm LogPSM (LogPsmStorageFactor: S̄_opt with the light overhead); kAdaptive
// "adaptive (RTW)" with no value (NaN: an empty cell, null in JSON), its warps having no closed
// form; kZPartitions "ZP" (unwarped, logarithmic splits); kZPartitionsWarped "ZP + W";
// kFacePartitionsWarped "FP + W" (one map per face, no z-split); kVirtualLevels ZP with
// k = ⌈log₂ f/n⌉ unwarped maps (ρ ≤ 2: a level per halving of the texel, as its pages have).
struct SchemeValue {
    std::string scheme;
    double storage = 0.0;
};
SchemeValue AnalyticStorageOf(spatial::StorageModel model, int partitions,
                              const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight);
// The model the method declares (MethodInfo::storage); the best single map for a name the
// registry does not know (a case's own method).
SchemeValue AnalyticStorageOf(const std::string& method, int partitions,
                              const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight);
// min over n' of StorageFactorForWarpOffset (a geometric grid of n' from 10⁻³ n to 10⁶ n and +∞,
// then golden-section refinement around the best): the least S̄ of any single warped map of
// Lloyd's family for this light, i.e. of any 4×4 perspective map with its centre on the eye's
// side of the frustum (§4.1).
double BestSingleMapStorage(const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight);

struct CaseStorageRow {
    std::string method;
    int maps = 1;
    std::int64_t texels = 0;
    double perspectiveMax = 0.0;               // measured max w_l/w_i
    double measured = 0.0, measuredP99 = 0.0;  // effective S̄ from the max and the 99th percentile
    SchemeValue camera, visible;  // the method's scheme, for the camera's and the visible depths
};

struct CaseStorageLight {
    spatial::Light light;
    glm::dvec3 esToLight{0.0};  // eye space (point lights: seen from the visible points' centroid)
    double gammaDeg = 0.0;      // angle between the light's travel direction and the view vector
    double optimalCamera = 0.0, optimalVisible = 0.0;        // S̄_opt
    double bestSingleCamera = 0.0, bestSingleVisible = 0.0;  // BestSingleMapStorage
    std::vector<CaseStorageRow> rows;
};

struct CaseStorage {
    std::string caseName;
    spatial::ViewFrustum camera;   // the case's camera
    spatial::ViewFrustum visible;  // the same with n, f the visible pixels' planar depth range
    int partitions = 0;            // k of the partitioned methods
    std::vector<CaseStorageLight> lights;
};

// Evaluates the case's fixed lights with `methods` (CPU renderer, no truth map, no camera path).
// Throws InputError naming the field for input the evaluation cannot serve.
CaseStorage RunCaseStorage(const spatial::Scene& scene, const std::vector<std::string>& methods);

}  // namespace lexel::cases
