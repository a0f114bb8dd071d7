// The experiment of Chong & Gortler's report §3 for one scene: per light and per method, the
// number of misclassified shadow pixels in the final frame against ground truth (Table 1's
// measure), the energy h of eq. (6) over the light's boundary samples, and the time taken to
// compute the light matrix.
//
// Ground truth is exact: one Embree shadow ray per front-facing visible pixel of the frame, from
// the pixel's world point (moved off its surface by kRayOffset scene radii along the normal) to
// the light. The report instead used a focused 4000² shadow map; EvaluationOptions::mapTruth also
// renders that map and reports how many pixels it classifies differently from the rays.
//
// Counted pixels: visible, facing the light (n·l > 0). Pixels facing away are in attached shadow
// for every method and for the truth alike, so they can never be misclassified.
//
// A partitioned method (partitions.h) renders one map per cascade and shades each pixel through
// the cascade CascadeFor picks by the pixel's planar eye depth; its h sums each sample's badness
// under the cascade that serves it. A virtual shadow map (virtual_shadow_map.h) renders its
// resident pages and shades each pixel through the page that serves it (page_shading.h). Every
// method's footprint is measured per counted pixel as σ₁(J⁻¹), J = ∂u/∂x in texels of the serving
// map per frame pixel, with ∂W/∂x exact on the pixel's plane (PlaneDerivatives): the most frame
// pixels one texel spans, > 1 where the map undersamples the view. Beside it, Lloyd et al. 2006's
// perspective aliasing w_l/w_i per covered counted pixel (PerspectiveAliasing) and the effective
// storage factor it implies.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/perspective_aliasing.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

class RayCaster;
class RayCastMapper;

// texels · aliasing² / framePixels: the storage factor S̄ (Lloyd 2006 eq. 12's texels over image
// pixels) that brings a worst aliasing `aliasing` to 1 by scaling every map's resolution alike.
// 0 when framePixels ≤ 0.
double EffectiveStorageFactor(std::int64_t texels, double aliasing, std::int64_t framePixels);

// The truth rays' origin offset along the surface normal, in scene radii: Embree works in float,
// in the scene's unit frame (ray_caster.h), where this is ~100 ulps of a coordinate.
inline constexpr double kRayOffset = 1e-5;
// A sample where |n · l| < kGrazingCos (the light within ~11.5° of the receiver's plane) is a
// grazing sample: its footprint is mostly projection aliasing (Lloyd 2006 eq. 1's cosine ratio),
// which no light matrix removes.
inline constexpr double kGrazingCos = 0.2;

struct EvaluationOptions {
    std::vector<std::string> methods;  // names from SpatialMethodNames() or of `given`
    // The case's own methods' clip matrices for the light evaluated (methods.h, GivenMatrix).
    std::vector<GivenMatrix> given;
    bool mapTruth = false;     // also render the report's focused truth map
    int truthMapSize = 4000;   // its resolution (square)
    bool keepBuffers = false;  // keep shades and maps (for images)
    // K: each method's errors are also measured with its map(s) moved by K sub-texel phases
    // (SubTexelPhases, sub_texel_phase.h; phase 0 the map as computed) and averaged. 1: the
    // single measurement. Costs K shadow passes and shadings per method (the matrix once).
    int phases = 1;
    // Adaptive phases: when above `phases`, a method whose mean over K phases is not settled
    // (its standard error above 2% of it and above a pixel: PhaseMeanSettled) is measured at 2K,
    // 4K, ... phases up to this many (CountOverPhases); optimal-oracle scores its candidates
    // alike. ≤ phases: exactly K.
    int maxPhases = 0;
    // Called after each method is measured, with its name (a progress bar); may be empty.
    std::function<void(std::string_view method)> onMethodDone;
};

// One cascade of a partitioned method: its matrix, map, depth interval and readback points
// (cascade.visiblePoints = 0: an empty partition), and what it serves in the frame.
struct CascadeOutcome {
    Cascade cascade;
    std::int64_t pixels = 0;  // counted frame pixels it shades
    double h = 0.0;           // eq. (6) over the samples it serves
};

// A virtual shadow map's pages for one light (virtual_shadow_map.h).
struct PageOutcome {
    std::int64_t requested = 0;  // distinct pages the readback's pixels asked for
    std::int64_t resident = 0;   // ... backed by the pool (the most requested)
    std::int64_t dropped = 0;    // requested − resident
    int pageTexels = 0;          // P: a page is P × P texels
    int poolPages = 0;           // the pool's pages (pool texels ≤ the single map's)
    double lodBias = 0.0;        // the bias the requests were made with (vsm-dynamic: fitted)
};

// How an optimizer method (IsOptimizerMethod, methods.h) reached its matrix; empty for the others.
struct OptimizerTrace {
    std::vector<double> hAfterIteration;  // optimal*: h after each Algorithm 1 iteration
    double hBeforeRefine = 0.0;           // optimal-refined: h after the rotation search
    std::string winner;  // optimal, optimal-refined: the start that won; optimal-oracle's start
};

// The images behind a method's counts, kept only when EvaluationOptions::keepBuffers (empty
// otherwise): what `lexel run --out` draws.
struct MethodBuffers {
    std::vector<Shade> shades;  // per frame pixel
    ShadowMap map;              // the map (a partitioned method's first; vsm*: the pool, PoolAtlas)
    std::vector<ShadowMap> cascadeMaps;         // partitioned methods: every cascade's
    std::vector<std::uint8_t> uncoveredPixels;  // vsm*: 1 where uncovered
};

// What every table reports of one method on one light: its time, its measured errors against
// the truth, its energies and footprints, and its texels.
struct MethodMetrics {
    double ms = 0.0;                 // wall time to compute the matrix
    std::int64_t misclassified = 0;  // counted pixels whose decision differs from the truth
    std::int64_t falseShadow = 0;    // ... of which the method shadows a lit pixel
    // Over EvaluationOptions::phases sub-texel phases (phase 0 gives the two counts above): the
    // mean misclassified and false-shadow pixels, and the standard error of the first mean
    // (MeanOverPhases; 0 for one phase). What the tables compare.
    double misclassifiedMean = 0.0, falseShadowMean = 0.0, misclassifiedError = 0.0;
    int phases = 1;  // the phases those means are over (more than K where adaptive)
    double h = 0.0;  // eq. (6) over the boundary samples
    // The edge energy e with the footprint prior (kEdgeEnergy at the case's exponent,
    // Scene::edgeExponent; energy.h) that `optimal` minimizes: of the map, or summed over the
    // cascades (each over the samples and prior points it serves); NaN for a warped or virtual map
    // (not a light matrix).
    double e = std::numeric_limits<double>::quiet_NaN();
    double hGrazing = 0.0;  // ... of which from grazing samples (kGrazingCos)
    // Counted pixels no map covers: outside every cascade's depth interval, behind the serving
    // map's plane or outside its texels (shaded lit, as ShadePoint does).
    std::int64_t uncovered = 0;
    double footprintMean = 0.0;  // σ₁(J⁻¹) over the covered counted pixels (frame pixels/texel)
    double footprintMax = 0.0;  // ... its maximum
    // Lloyd 2006's perspective aliasing w_l/w_i (PerspectiveAliasing) over the same pixels: its
    // maximum and 99th percentile (nearest rank), texel widths per pixel width.
    double perspectiveMax = 0.0, perspectiveP99 = 0.0;
    std::int64_t texels = 0;  // Σ over the method's maps of width × height
    // The effective storage factor: the texels the method would need, relative to the frame's
    // pixels, for its measured worst perspective aliasing to be 1 (all maps scaled alike):
    // texels · perspectiveMax² / frame pixels, Lloyd's S̄ measured (EffectiveStorageFactor).
    // storageFactorP99 the same with perspectiveP99.
    double storageFactor = 0.0, storageFactorP99 = 0.0;
};

// One method's result for one light: its matrix, its measured metrics (what every table
// reports), its cascades or pages, the optimizer's trace and, when kept, its buffers.
struct MethodOutcome {
    std::string method;
    LightMatrix matrix;
    MethodMetrics metrics;
    std::vector<CascadeOutcome> cascades;  // partitioned methods: per cascade
    int emptyPartitions = 0;               // ... those serving no readback point
    std::optional<PageOutcome> pages;      // virtual shadow maps (vsm*): their pages
    OptimizerTrace trace;                  // what the optimizer did (optimizer methods only)
    MethodBuffers buffers;                 // per-pixel images (EvaluationOptions::keepBuffers)
};

struct LightOutcome {
    Light light;
    std::int64_t receiverPixels = 0;     // counted pixels
    std::int64_t truthShadowed = 0;      // ... that the rays find shadowed
    std::int64_t mapTruthDisagree = -1;  // focused truth map vs rays (-1: not computed)
    int phases = 1;     // EvaluationOptions::phases: each method was measured at this many phases,
    int maxPhases = 1;  // ... and at most this many (MethodMetrics::phases: how many)
    LightSamples samples;  // the optimization samples (boundary, relevant)
    std::vector<MethodOutcome> methods;
    std::vector<std::uint8_t> truth;  // per frame pixel 1 = shadowed (when keepBuffers)
};

class Evaluator {
  public:
    // Renders the frame (camera.resolution) and the readback (scene.readback) once; builds the
    // ray caster. Throws DomainError: kGeometry without triangles, kCamera when the readback sees
    // nothing.
    Evaluator(const Scene& scene, const RenderBackend& backend);
    ~Evaluator();

    // Throws DomainError (Subject::kLight) for a light inside the geometry, or one no light
    // matrix can serve.
    LightOutcome Evaluate(const Light& light, const EvaluationOptions& options) const;

    // The counted frame pixels for `light` (covered, n·l > 0) without evaluating anything: 0 when
    // the light lies in the plane of, or behind, every surface the camera sees. Throws
    // DomainError (Subject::kLight) when no light space can be built for it.
    std::int64_t CountedPixels(const Light& light) const;

    // Misclassified counted pixels of any matrix for `light` (renders its map, traces the truth).
    std::int64_t Misclassified(const Light& light, const LightMatrix& matrix) const;
    // The 4×4 a rasterizer takes for `matrix` on a map of `map` texels (ClipFromWorld, OpenGL's
    // depth in [-1, 1]), its depth range fitted to this scene (LightDepthRange over the scene's
    // bounds and the readback's visible points; where a visible point is behind the map's plane,
    // the range of the light's distances to the bounds' corners instead). What `lexel run` prints
    // as a method's clip_from_world; LightMatrixFromClip takes it back to `matrix`.
    glm::dmat4 ClipFromWorldOf(const Light& light, const LightMatrix& matrix, Resolution map) const;
    // The frame's shades through one matrix, at the scene's shadow-map resolution.
    std::vector<Shade> ShadeFrame(const Light& light, const LightMatrix& matrix) const;
    // The exact truth per frame pixel for `light`: 1 where a counted pixel's (covered, facing the
    // light) shadow ray is blocked, 0 elsewhere. What Misclassified compares against.
    std::vector<std::uint8_t> TruthShadows(const Light& light) const;

    const Scene& scene() const { return scene_; }
    const CameraBuffer& frame() const { return frame_; }
    const Readback& readback() const { return readback_; }
    const Bounds& bounds() const { return bounds_; }
    const RenderBackend& backend() const { return backend_; }

  private:
    std::vector<std::uint8_t> TraceTruth(const class LightSpace& lightSpace) const;
    // optimal-oracle (oracle.h): the best single matrix by the measured mean over phases held
    // out of the reported ones (those after options.maxPhases, at least K of them) against
    // `truth`; its winning start in *winner.
    LightMatrix OracleMatrix(const LightSpace& lightSpace, const struct MethodContext& context,
                             std::span<const std::uint8_t> truth, const EvaluationOptions& options,
                             std::string* winner) const;
    void Measure(const LightSpace& lightSpace, const struct MethodMatrix& computed,
                 const struct MethodContext& context, const LightOutcome& light,
                 std::span<const std::uint8_t> grazing, std::span<const std::uint8_t> truth,
                 const EvaluationOptions& options, MethodOutcome* m) const;

    const Scene& scene_;
    const RenderBackend& backend_;
    Bounds bounds_;
    CameraBuffer frame_;
    Readback readback_;
    std::vector<glm::dvec3> frameDWdx1_, frameDWdx2_;  // per frame pixel (PlaneDerivatives)
    std::vector<double> frameDepth_;                   // per frame pixel: planar eye depth
    std::unique_ptr<RayCaster> caster_;
    std::unique_ptr<RayCastMapper> mapper_;  // warped methods' maps (ray_cast_map.h)
};

}  // namespace lexel::spatial
