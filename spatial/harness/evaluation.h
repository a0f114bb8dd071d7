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
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

class RayCaster;

inline constexpr double kRayOffset = 1e-5;  // scene radii; Embree works in float
// A sample where |n · l| < kGrazingCos (the light within ~11.5° of the receiver's plane) is a
// grazing sample: its footprint is mostly projection aliasing (Lloyd 2006 eq. 1's cosine ratio),
// which no light matrix removes.
inline constexpr double kGrazingCos = 0.2;

struct EvaluationOptions {
    std::vector<std::string> methods;  // names from SpatialMethodNames()
    bool mapTruth = false;             // also render the report's focused truth map
    int truthMapSize = 4000;           // its resolution (square)
    bool keepBuffers = false;          // keep shades and maps (for images)
};

struct MethodOutcome {
    std::string method;
    LightMatrix matrix;
    double ms = 0.0;                      // wall time to compute the matrix
    std::int64_t misclassified = 0;       // counted pixels whose decision differs from the truth
    std::int64_t falseShadow = 0;         // ... of which the method shadows a lit pixel
    double h = 0.0;                       // eq. (6) over the boundary samples
    double hGrazing = 0.0;                // ... of which from grazing samples (kGrazingCos)
    std::vector<double> hAfterIteration;  // optimal*: h after each Algorithm 1 iteration
    double hBeforeRefine = 0.0;           // optimal-refined: h after the rotation search
    std::string winner;                   // optimal, optimal-refined: the start that won
    std::vector<Shade> shades;            // per frame pixel, when keepBuffers
    ShadowMap map;                        // when keepBuffers
};

struct LightOutcome {
    Light light;
    std::int64_t receiverPixels = 0;     // counted pixels
    std::int64_t truthShadowed = 0;      // ... that the rays find shadowed
    std::int64_t mapTruthDisagree = -1;  // focused truth map vs rays (-1: not computed)
    LightSamples samples;                // the optimization samples (boundary, relevant)
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

    // Misclassified counted pixels of any matrix for `light` (renders its map, traces the truth).
    std::int64_t Misclassified(const Light& light, const LightMatrix& matrix) const;

    const Scene& scene() const { return scene_; }
    const CameraBuffer& frame() const { return frame_; }
    const Readback& readback() const { return readback_; }
    const Bounds& bounds() const { return bounds_; }
    const RenderBackend& backend() const { return backend_; }

  private:
    std::vector<std::uint8_t> TraceTruth(const class LightSpace& lightSpace) const;

    const Scene& scene_;
    const RenderBackend& backend_;
    Bounds bounds_;
    CameraBuffer frame_;
    Readback readback_;
    std::unique_ptr<RayCaster> caster_;
};

}  // namespace lexel::spatial
