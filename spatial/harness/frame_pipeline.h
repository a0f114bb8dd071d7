// One frame of a renderer that shadows N lights with one light-matrix method, timed pass by pass:
// the measurement of Chong & Gortler's report §3, Tables 2–3 ("Render & Wait", "Optimization",
// "Convex Hull"), split the way §2.3–2.4 runs Algorithm 1:
//   optimal:  readback camera pass → readback (to the CPU, Appendix A derivatives, 3D hull) →
//             per light: focused matrix, standard shadow map, readback shading and boundary
//             samples (step 3), Algorithm 1 (2D hull, rotation search: FrameOptions::optimal, by
//             default the report's single start), final shadow map;
//   focused:  per light: focused matrix (frustum ∩ bounds, rectangle), final shadow map;
//   both:     the final camera pass, and per light the final shading of the frame.
// FrameOptions adds the report's two savings (§2.4): P updated only every few frames ("we only
// update P every three frames"), and step 1 from the light's previous final map instead of a
// fresh standard one ("every couple frames we generate standard shadow maps for step 1 instead
// of using the previous frame's"). The default runs Algorithm 1 in full every frame. Every
// pipeline runs the one schedule of frame_schedule.h (UpdatePolicy says which frames update);
// they differ only in how a pass runs.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/methods/method_info.h"

namespace lexel::spatial {

enum class FrameMethod { kFocused, kOptimal };

// What an optimal frame does (focused frames ignore it). A light that has no previous matrix or
// map (the first frame, or other lights than last frame) gets the full Algorithm 1.
struct FrameOptions {
    // The optimizer, one of OptimizerMethodNames (methods.h): by default `optimal-report`,
    // Algorithm 1 from focused's axis as the report ran it.
    std::string optimal = kReportOptimalMethod;
    bool optimize = true;     // run it; false: keep each light's previous matrix
    bool standardMap = true;  // step 1 from a standard (focused) map; false: the previous map
    // Time the GPU passes one by one. On a software renderer that brackets each pass with
    // glFinish (PassTimer::kFinish), which serializes the frame; false leaves the GPU passes at
    // 0 and `total` unperturbed (the frame-ratio benchmark). CPU stages are always timed.
    bool timePasses = true;
};

// Milliseconds. GPU passes are GPU time (timer queries) on a GPU pipeline and wall time on the CPU
// one; CPU stages are wall time. The parts need not add up to `total`.
struct FrameTimes {
    double total = 0.0;       // wall time, frame start to every pass finished
    double cameraPass = 0.0;  // the final frame's camera pass (+ the readback's, optimal)
    double readback = 0.0;    // optimal: the readback to the CPU and its derivatives (not its hull)
    double extraction = 0.0;  // optimal: per light, readback shading + boundary samples on the CPU
    double hull = 0.0;        // focused matrices (both); optimal: + the 3D hull and the 2D hulls
    double search = 0.0;      // optimal: Algorithm 1's rotation search
    double shadowMap = 0.0;   // every shadow-map pass (optimal: the standard maps too)
    double shading = 0.0;     // the final frame's shading, every light
    // The sum of the parts (what the report's "Render & Wait" + "Optimization" split).
    double Parts() const {
        return cameraPass + readback + extraction + hull + search + shadowMap + shading;
    }
};

class FramePipeline {
  public:
    virtual ~FramePipeline() = default;
    // One frame of `scene` seen from `camera` (scene.camera's resolution, readback and map sizes
    // come from `scene`), shadowing `lights`. Throws DomainError as Evaluator::Evaluate does.
    virtual FrameTimes RenderFrame(const Scene& scene, const Camera& camera,
                                   std::span<const Light> lights, FrameMethod method,
                                   FrameOptions options = {}) = 0;
    // How the passes are timed, in words (for reports).
    virtual std::string PassClock() const = 0;
    // The light matrices the last frame rendered its final maps with, one per light.
    virtual const std::vector<LightMatrix>& Matrices() const = 0;
};

// The frame on any RenderBackend (the CPU reference: every pass TBB-parallel, wall times).
std::unique_ptr<FramePipeline> MakeBackendFramePipeline(const RenderBackend& backend,
                                                        const TriangleMesh& geometry);
// The same on a CPU renderer it owns.
std::unique_ptr<FramePipeline> MakeCpuFramePipeline(const TriangleMesh& geometry);

}  // namespace lexel::spatial
