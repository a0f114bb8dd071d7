#include "lexel/cases/run/camera_path.h"

#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/temporal.h"

namespace lexel::cases {

namespace {

bool Counted(spatial::Shade s) {
    return s == spatial::Shade::kLit || s == spatial::Shade::kShadowed;
}

// What one pose leaves for the next: the truth and every method's shades.
struct PoseBuffers {
    std::vector<std::uint8_t> truth;
    std::vector<std::vector<spatial::Shade>> shades;  // per study method
};

// The shimmer along a walk, pose by pose: each pose's buffers against the previous pose's
// (ShimmerPercent per method), then the mean over the consecutive pairs.
class ShimmerWalk {
  public:
    explicit ShimmerWalk(std::size_t methods) : sum_(methods, 0.0) {}
    void Add(PoseBuffers now) {
        if (before_) {
            for (std::size_t m = 0; m < sum_.size(); ++m)
                sum_[m] +=
                    ShimmerPercent(before_->shades[m], before_->truth, now.shades[m], now.truth);
            ++pairs_;
        }
        before_ = std::move(now);
    }
    // Per method, the mean over the pairs in percent (0 with fewer than two poses).
    std::vector<double> Mean() const {
        std::vector<double> mean = sum_;
        if (pairs_ > 0)
            for (double& s : mean) s /= static_cast<double>(pairs_);
        return mean;
    }

  private:
    std::vector<double> sum_;
    std::optional<PoseBuffers> before_;
    std::size_t pairs_ = 0;
};

// `poseScene` is the scene seen from the pose; the evaluator keeps a reference to it, so it must
// outlive *evaluator.
spatial::LightOutcome EvaluatePose(const spatial::Scene& poseScene,
                                   const spatial::RenderBackend& backend, std::size_t light,
                                   std::size_t pose, const spatial::EvaluationOptions& options,
                                   std::unique_ptr<spatial::Evaluator>* evaluator) {
    *evaluator = MakeEvaluator(poseScene, backend, CameraPathField(pose));
    try {
        return (*evaluator)->Evaluate(poseScene.lights[light], options);
    } catch (const DomainError& e) {
        throw InputError(SpatialErrorField(e, LightField(light), CameraPathField(pose)) + ": " +
                         e.what());
    }
}

CameraPathStudy StudyLight(const spatial::Scene& scene, const spatial::RenderBackend& backend,
                           std::size_t l, const std::vector<std::string>& methods,
                           const std::function<void()>& onMethodDone) {
    spatial::EvaluationOptions options;
    options.methods = methods;
    if (onMethodDone) options.onMethodDone = [&](std::string_view) { onMethodDone(); };
    if (std::find(methods.begin(), methods.end(), spatial::kOptimalMethod) == methods.end())
        options.methods.push_back(spatial::kOptimalMethod);
    options.keepBuffers = true;
    const std::size_t optimal =
        std::find(options.methods.begin(), options.methods.end(), spatial::kOptimalMethod) -
        options.methods.begin();
    const double margin = spatial::OptimizerOptions{}.margin;
    CameraPathStudy study;
    study.methods = methods;
    study.methods.push_back(kOptimalWithHysteresis);
    ShimmerWalk walk(study.methods.size());
    std::optional<spatial::LightMatrix> previous;
    for (std::size_t k = 0; k < scene.cameraPath.size(); ++k) {
        // Declared before the evaluator, which holds a reference to it (it used to be a local of
        // EvaluatePose: Misclassified below then read a destroyed scene).
        spatial::Scene poseScene = scene;
        poseScene.camera = scene.cameraPath[k];
        std::unique_ptr<spatial::Evaluator> evaluator;
        spatial::LightOutcome o = EvaluatePose(poseScene, backend, l, k, options, &evaluator);
        const spatial::HysteresisDecision d = spatial::ApplyHysteresis(
            previous, o.methods[optimal].matrix, o.samples, scene.shadowMap, margin,
            spatial::kEdgeEnergy.kind);  // optimal's energy
        PoseOutcome pose;
        pose.changed = d.changed;
        pose.medianKept = d.medianPrevious;
        pose.medianNew = d.medianCandidate;
        pose.misclassifiedFresh = o.methods[optimal].metrics.misclassified;
        pose.misclassifiedHysteresis = d.changed
                                           ? pose.misclassifiedFresh
                                           : evaluator->Misclassified(scene.lights[l], d.matrix);
        study.poses.push_back(pose);
        previous = d.matrix;

        std::vector<spatial::Shade> withHysteresis =
            d.changed ? o.methods[optimal].buffers.shades
                      : evaluator->ShadeFrame(scene.lights[l], d.matrix);
        PoseBuffers now;
        now.truth = std::move(o.truth);
        for (std::size_t m = 0; m < methods.size(); ++m)
            now.shades.push_back(std::move(o.methods[m].buffers.shades));
        now.shades.push_back(std::move(withHysteresis));
        walk.Add(std::move(now));
    }
    study.shimmerPercent = walk.Mean();
    return study;
}

}  // namespace

double ShimmerPercent(std::span<const spatial::Shade> before,
                      std::span<const std::uint8_t> truthBefore,
                      std::span<const spatial::Shade> after,
                      std::span<const std::uint8_t> truthAfter) {
    if (before.size() != after.size() || truthBefore.size() != after.size() ||
        truthAfter.size() != after.size())
        throw std::invalid_argument("ShimmerPercent: the two poses' frames differ in size");
    std::int64_t stable = 0, flipped = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        if (!Counted(before[i]) || !Counted(after[i]) || truthBefore[i] != truthAfter[i]) continue;
        ++stable;
        flipped += before[i] != after[i];
    }
    return stable ? 100.0 * static_cast<double>(flipped) / static_cast<double>(stable) : 0.0;
}

int CameraPathStudy::Changes() const {
    int changes = 0;
    for (const PoseOutcome& p : poses) changes += p.changed;
    return changes;
}

std::vector<CameraPathStudy> RunCameraPathStudy(const spatial::Scene& scene,
                                                const spatial::RenderBackend& backend,
                                                const std::vector<std::string>& methods,
                                                const std::function<void()>& onMethodDone) {
    std::vector<CameraPathStudy> studies;
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        studies.push_back(StudyLight(scene, backend, l, methods, onMethodDone));
    return studies;
}

PathPoses MakePathPoses(const spatial::Scene& scene, const spatial::RenderBackend& backend,
                        std::size_t count) {
    PathPoses poses;
    poses.scenes.assign(count, scene);  // all made before the evaluators that refer to them
    for (std::size_t k = 0; k < count; ++k) {
        poses.scenes[k].camera = scene.cameraPath.at(k);
        poses.evaluators.push_back(MakeEvaluator(poses.scenes[k], backend, CameraPathField(k)));
    }
    return poses;
}

std::vector<double> ShimmerAlong(const PathPoses& poses, const spatial::Light& light,
                                 spatial::EvaluationOptions options,
                                 const std::string& lightField) {
    options.phases = 1;
    options.maxPhases = 0;
    options.keepBuffers = true;
    ShimmerWalk walk(options.methods.size());
    for (std::size_t k = 0; k < poses.evaluators.size(); ++k) {
        spatial::LightOutcome o;
        try {
            o = poses.evaluators[k]->Evaluate(light, options);
        } catch (const DomainError& e) {
            throw InputError(SpatialErrorField(e, lightField, CameraPathField(k)) + ": " +
                             e.what());
        }
        PoseBuffers now;
        now.truth = std::move(o.truth);
        for (spatial::MethodOutcome& m : o.methods)
            now.shades.push_back(std::move(m.buffers.shades));
        walk.Add(std::move(now));
    }
    return walk.Mean();
}

std::size_t CameraPathSteps(const spatial::Scene& scene, const std::vector<std::string>& methods) {
    const bool hasOptimal =
        std::find(methods.begin(), methods.end(), spatial::kOptimalMethod) != methods.end();
    return scene.lights.size() * scene.cameraPath.size() * (methods.size() + (hasOptimal ? 0 : 1));
}

}  // namespace lexel::cases
