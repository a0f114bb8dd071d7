// The error model checked per boundary sample (spatial/error_model.h): for each
// light of a case and each single-map method, every boundary sample's predicted band (frame
// pixels, ExpectedBandWidth × the edge it stands for) beside the misclassified frame pixels
// measured nearest to it, averaged over the map's sub-texel phases.
//
// Phases: the method's matrix with its map shifted by (du, dv) texels (LightMatrix::Shifted) at
// the K phases every 3D measurement uses (SubTexelPhases, sub_texel_phase.h: phase 0 unshifted,
// then Roberts' R2 sequence in [−½, ½)²): J, the samples and every proxy are the same for all of
// them, only the texel grid moves.
//
// Assignment: each counted frame pixel misclassified in a phase goes to the nearest boundary
// sample (screen distance, frame pixels; a sample sits at its readback pixel's centre scaled to
// the frame) within that sample's radius 2 + ½‖n̂ᵀJ⁻¹‖ readback pixels, at most kMaxRadius: a
// misclassified pixel lies within half a texel across the true edge (½‖g‖ pixels), the edge within
// ‖n̂‖₁ ≤ √2 readback pixels of a boundary pixel's centre, and the pixel itself spans ½. A pixel no
// sample reaches is unexplained (thin shadows the readback misses, pixels no map covers, lights
// without samples) and counted apart. Samples whose shades give no edge normal (a shadow one
// pixel thin) still take pixels but are left out of the fit, as are samples out of range
// (ErrorModelSample::inRange).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "lexel/cases/run/backend.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// The largest assignment radius, in readback pixels (a map undersampling the view by more than
// ~12 pixels per texel across an edge loses the band's outer part to "unexplained").
inline constexpr double kMaxAssignRadius = 8.0;

struct ErrorModelSample {
    std::size_t light = 0;    // index into the study's lights
    std::size_t method = 0;   // index into the study's methods
    std::size_t sample = 0;   // index into the light's boundary samples
    std::uint32_t pixel = 0;  // its readback pixel
    glm::dvec2 normal{0.0};   // its edge normal (readback pixels, towards the shadow); 0: none
    double predicted = 0.0;   // frame pixels (ExpectedBandWidth); +inf where J is singular
    double predictedIsotropic = 0.0;  // the same with ‖n̂ᵀJ⁻¹‖/4
    double measured = 0.0;            // phase-averaged misclassified frame pixels assigned to it
    // Whether its radius 2 + ½‖n̂ᵀJ⁻¹‖ fits under kMaxAssignRadius: the whole predicted band can
    // be assigned to it. Out of range (J near singular: grazing light, a sample near the map's
    // plane) the model predicts a band wider than the pixels it could be measured on.
    bool inRange = true;
};

// Per method: phase-averaged misclassified counted frame pixels over all lights, and how many of
// them the samples explain.
struct ErrorModelTotals {
    double misclassified = 0.0;  // Σ over lights, mean over phases
    double explained = 0.0;      // ... assigned to a sample (with or without a normal)
    double singlePhase = 0.0;    // Σ over lights of the unshifted map's count (phase 0, 0)
    // ... of `misclassified`, the pixels the phase's map does not cover (shaded lit: a shifted
    // map loses up to half a texel at its border), never assigned to a sample.
    double uncovered = 0.0;
    // ... the pixels the map shadows where the rays light them (the rest it lights in shadow).
    double falseShadow = 0.0;
    // ... the pixels on the scene's floor plane (Scene::floorPlane; 0 without one): a planar
    // receiver of cast shadows, the model's own case. Off it lie walls and objects, among them
    // the curved and tessellated receivers the model leaves out (error_model.h).
    double onFloor = 0.0;
    double falseShadowOffFloor = 0.0;  // ... false shadows off the floor plane
    ErrorModelTotals& operator+=(const ErrorModelTotals& o);  // field by field
};

struct ErrorModelStudy {
    std::string caseName;
    std::vector<spatial::Light> lights;
    std::vector<std::string> methods;
    int phases = 0;  // K = n²
    spatial::Resolution readback, frame;
    std::vector<std::size_t> samplesPerLight;
    std::vector<ErrorModelSample> samples;  // light by light, method by method
    std::vector<ErrorModelTotals> totals;   // [method]
    double seconds = 0.0;
};

// Runs the study. `methods` must be single-map methods (not partitioned, virtual or warped) and
// `phases` a square ≥ 1 (the command checks both; std::invalid_argument otherwise). Calls
// `onLightDone` after each light. Throws InputError naming the camera or the light for input the
// evaluation cannot serve (as RunSweep does).
ErrorModelStudy RunErrorModelStudy(const spatial::Scene& scene,
                                   const std::vector<std::string>& methods,
                                   const std::vector<spatial::Light>& lights, int phases,
                                   BackendKind backend,
                                   const std::function<void()>& onLightDone = {});

}  // namespace lexel::cases
