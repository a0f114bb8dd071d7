// The one frame schedule of the timed pipelines (frame_pipeline.h): the report's update policy
// (Chong & Gortler, "Scene Optimized Shadow Mapping", EG tech report ~2006, §2.3–2.4), frame by
// frame, and which passes each frame runs with which inputs. Every FramePipeline executes it
// (FrameSchedule::Run); a pipeline only says how a pass runs (FramePasses).
//   - UpdatePolicy: Algorithm 1 every U-th frame, P kept between ("we only update P every three
//     frames"), and of those updates every S-th takes step 1 from a standard map, the others from
//     the light's previous final map ("every couple frames we generate standard shadow maps for
//     step 1 instead of using the previous frame's");
//   - PlanFrame: one frame's passes, light by light;
//   - FrameSchedule: the per-light state between frames, and the frame's passes in order:
//       readback camera pass (when a light updates), final camera pass, readback to the CPU,
//       then per light: focused matrix, [standard map], [boundary samples, Algorithm 1],
//       final shadow map, shading of the frame.
//     The readback's camera pass is issued before the frame's and read after it, so that a GPU
//     overlaps the transfer with the frame's rendering (§2.4: "much of the readback time can occur
//     concurrently with our frame rendering").
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/harness/frame_pipeline.h"

namespace lexel::spatial {

// §2.4's two savings as frame numbers (1, 1: Algorithm 1 in full every frame; the report's: 3, 2).
struct UpdatePolicy {
    int updateEvery = 1;    // U ≥ 1: Algorithm 1 on frames k with k mod U = 0
    int standardEvery = 1;  // S ≥ 1: of those, frames k with (k / U) mod S = 0 from a standard map
    // The optimal frame k ≥ 0's options: `base` with optimize and standardMap set.
    FrameOptions At(int frame, FrameOptions base = {}) const;
};

// What one light gets in a frame.
enum class LightStep {
    kFocused,             // the focused matrix (focused frames)
    kKeep,                // the light's kept P, no work of Algorithm 1 (optimal, no update)
    kUpdateFromStandard,  // Algorithm 1, step 1 from a fresh standard (focused) map
    kUpdateFromPrevious,  // Algorithm 1, step 1 from the light's kept final map
};

struct FramePlan {
    bool readback = false;  // the readback camera pass and its transfer: a light updates
    bool keepMaps = false;  // the final maps and matrices are kept for the next optimal frame
    std::vector<LightStep> lights;
};

// The plan of one frame of `method` under `options` for lights of which those with kept[l]
// have a kept matrix and final map (from the last optimal frame over the same lights). A light
// without one gets the full Algorithm 1 from a standard map.
FramePlan PlanFrame(FrameMethod method, const FrameOptions& options, const std::vector<bool>& kept);

// How a pipeline runs the passes of a frame. Each pass adds its own time to `t`; FrameSchedule
// times the CPU stages between them (the focused matrices into t->hull, the optimizer into
// t->hull and t->search) and moves Readback::relevantHullMs from t->readback to t->hull.
class FramePasses {
  public:
    virtual ~FramePasses() = default;
    // Step 1's camera pass, at `resolution` (scene.readback).
    virtual void RenderReadbackCamera(const Camera& camera, Resolution resolution,
                                      FrameTimes* t) = 0;
    // The final frame's camera pass, at camera.resolution.
    virtual void RenderFrameCamera(const Camera& camera, FrameTimes* t) = 0;
    // Step 2: the readback camera pass on the CPU (MakeReadback), its whole time in t->readback.
    virtual Readback ReadReadback(const Camera& camera, Resolution resolution, FrameTimes* t) = 0;
    // Step 1's standard map for one light through `focused`, replacing the previous standard map.
    virtual void RenderStandardMap(const LightSpace& lightSpace, const LightMatrix& focused,
                                   Resolution resolution, FrameTimes* t) = 0;
    // Step 3: the boundary samples of `readback` shaded against the standard map just rendered,
    // or (fromKept) against light `light`'s kept final map.
    virtual LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                         std::size_t light, bool fromKept, FrameTimes* t) = 0;
    // Light `light`'s final shadow map; `keep`: it becomes the light's kept final map.
    virtual void RenderFinalMap(std::size_t light, const LightSpace& lightSpace,
                                const LightMatrix& matrix, Resolution resolution, bool keep,
                                FrameTimes* t) = 0;
    // The frame's shading with the final map RenderFinalMap rendered last.
    virtual void ShadeFrame(const LightSpace& lightSpace, FrameTimes* t) = 0;
};

class FrameSchedule {
  public:
    explicit FrameSchedule(const Bounds& wsBounds) : wsBounds_(wsBounds) {}

    // The plan of the next frame (PlanFrame over the kept state). An optimal frame whose lights
    // differ from the last optimal frame's first forgets the kept state.
    FramePlan Plan(std::span<const Light> lights, FrameMethod method, const FrameOptions& options);
    // One frame: Plan, then its passes through `passes` (see the header comment). Throws
    // DomainError as Evaluator::Evaluate does, std::invalid_argument when options.optimal is
    // not an optimizer (IsOptimizerMethod, methods.h).
    void Run(const Scene& scene, const Camera& camera, std::span<const Light> lights,
             FrameMethod method, const FrameOptions& options, FramePasses& passes, FrameTimes* t);
    // The matrices the last frame rendered its final maps with, one per light.
    const std::vector<LightMatrix>& Matrices() const { return used_; }

  private:
    LightMatrix MatrixOf(LightStep step, std::size_t light, const Scene& scene,
                         const Camera& camera, const LightSpace& lightSpace,
                         const Readback* readback, const FrameOptions& options, FramePasses& passes,
                         FrameTimes* t) const;

    Bounds wsBounds_;
    std::vector<Light> lights_;  // of the last optimal frame
    std::vector<std::optional<LightMatrix>> kept_;
    std::vector<LightMatrix> used_;  // by the last frame
};

}  // namespace lexel::spatial
