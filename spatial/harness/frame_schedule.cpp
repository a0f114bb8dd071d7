// The frame schedule of frame_schedule.h: the report's §2.4 policy, and the frame's passes in
// order with the CPU stages between them timed by wall clock.
#include "lexel/spatial/harness/frame_schedule.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {

namespace {

bool SameLight(const Light& a, const Light& b) {
    return a.type == b.type && a.position == b.position && a.direction == b.direction;
}

// The baselines' context of a frame (the visible points from `readback`, none when null).
BaselineContext FrameBaselineContext(const Scene& scene, const Camera& camera,
                                     const LightSpace& lightSpace, const Bounds& wsBounds,
                                     const Readback* readback) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = camera;
    context.map = scene.shadowMap;
    context.wsBounds = wsBounds;
    if (readback) {
        context.wsRelevant = readback->wsRelevant;
        context.wsRelevantHull = readback->wsRelevantHull;
    }
    context.floorPlane = scene.floorPlane;
    return context;
}

// FrameOptions::optimal's matrix for one light from its samples, timed into t->hull (the 2D
// hull) and t->search (the rest). Throws std::invalid_argument for a method that is not one.
LightMatrix TimedOptimizer(const std::string& method, BaselineContext context,
                           const LightSamples& samples, const Scene& scene, FrameTimes* t) {
    if (!IsOptimizerMethod(method))
        throw std::invalid_argument("frame pipeline: '" + method + "' is not an optimizer");
    context.samples = &samples;
    MethodContext methodContext;
    methodContext.baseline = context;
    methodContext.samples = &samples;
    methodContext.maxSamples = scene.optimizerMaxSamples;
    methodContext.edgeExponent = scene.edgeExponent;
    const Stopwatch clock;
    const MethodMatrix m = ComputeLightMatrix(method, methodContext);
    const double ms = clock.Ms();
    const double hullMs = m.optimizer ? m.optimizer->hullMs : 0.0;
    t->hull += hullMs;
    t->search += ms - hullMs;
    return m.matrix;
}

bool Updates(LightStep step) {
    return step == LightStep::kUpdateFromStandard || step == LightStep::kUpdateFromPrevious;
}

}  // namespace

FrameOptions UpdatePolicy::At(int frame, FrameOptions base) const {
    base.optimize = frame % updateEvery == 0;
    base.standardMap = base.optimize && (frame / updateEvery) % standardEvery == 0;
    return base;
}

FramePlan PlanFrame(FrameMethod method, const FrameOptions& options,
                    const std::vector<bool>& kept) {
    FramePlan plan;
    plan.keepMaps = method == FrameMethod::kOptimal;
    for (const bool hasKept : kept) {
        LightStep step = LightStep::kFocused;
        if (method == FrameMethod::kOptimal) {
            if (hasKept && !options.optimize)
                step = LightStep::kKeep;
            else if (hasKept && !options.standardMap)
                step = LightStep::kUpdateFromPrevious;
            else
                step = LightStep::kUpdateFromStandard;
        }
        plan.lights.push_back(step);
        plan.readback = plan.readback || Updates(step);
    }
    return plan;
}

FramePlan FrameSchedule::Plan(std::span<const Light> lights, FrameMethod method,
                              const FrameOptions& options) {
    const bool sameLights = lights.size() == lights_.size() &&
                            std::equal(lights.begin(), lights.end(), lights_.begin(), SameLight);
    if (method == FrameMethod::kOptimal && !sameLights) {
        lights_.assign(lights.begin(), lights.end());
        kept_.assign(lights.size(), std::nullopt);
    }
    std::vector<bool> kept(lights.size(), false);
    if (method == FrameMethod::kOptimal)
        for (std::size_t l = 0; l < lights.size(); ++l) kept[l] = kept_[l].has_value();
    return PlanFrame(method, options, kept);
}

void FrameSchedule::Run(const Scene& scene, const Camera& camera, std::span<const Light> lights,
                        FrameMethod method, const FrameOptions& options, FramePasses& passes,
                        FrameTimes* t) {
    const FramePlan plan = Plan(lights, method, options);
    used_.clear();
    if (plan.readback) passes.RenderReadbackCamera(camera, scene.readback, t);
    passes.RenderFrameCamera(camera, t);
    std::optional<Readback> readback;
    if (plan.readback) {
        readback = passes.ReadReadback(camera, scene.readback, t);
        t->readback -= readback->relevantHullMs;
        t->hull += readback->relevantHullMs;
    }
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const LightSpace lightSpace(lights[l], wsBounds_);
        const LightMatrix matrix = MatrixOf(plan.lights[l], l, scene, camera, lightSpace,
                                            readback ? &*readback : nullptr, options, passes, t);
        passes.RenderFinalMap(l, lightSpace, matrix, scene.shadowMap, plan.keepMaps, t);
        passes.ShadeFrame(lightSpace, t);
        used_.push_back(matrix);
        if (plan.keepMaps) kept_[l] = matrix;
    }
}

// One light's matrix for its step: the kept P, or the focused matrix and, for an update,
// Algorithm 1 from it (steps 1 and 3 by `passes`, step 4 on the CPU).
LightMatrix FrameSchedule::MatrixOf(LightStep step, std::size_t light, const Scene& scene,
                                    const Camera& camera, const LightSpace& lightSpace,
                                    const Readback* readback, const FrameOptions& options,
                                    FramePasses& passes, FrameTimes* t) const {
    if (step == LightStep::kKeep) return *kept_[light];
    const Stopwatch stage;
    const LightMatrix focused =
        FocusedLightMatrix(FrameBaselineContext(scene, camera, lightSpace, wsBounds_, readback));
    t->hull += stage.Ms();
    if (!Updates(step)) return focused;
    const bool fromKept = step == LightStep::kUpdateFromPrevious;
    if (!fromKept) passes.RenderStandardMap(lightSpace, focused, scene.shadowMap, t);
    const LightSamples samples = passes.BoundarySamples(*readback, lightSpace, light, fromKept, t);
    return TimedOptimizer(options.optimal,
                          FrameBaselineContext(scene, camera, lightSpace, wsBounds_, readback),
                          samples, scene, t);
}

}  // namespace lexel::spatial
