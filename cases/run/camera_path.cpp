#include "lexel/cases/run/camera_path.h"

#include <optional>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/temporal.h"

namespace lexel::cases {

int CameraPathStudy::Changes() const {
    int changes = 0;
    for (const PoseOutcome& p : poses) changes += p.changed;
    return changes;
}

std::vector<CameraPathStudy> RunCameraPathStudy(const spatial::Scene& scene,
                                                const spatial::RenderBackend& backend) {
    spatial::EvaluationOptions evalOptions;
    evalOptions.methods = {"optimal"};
    const double margin = spatial::OptimizerOptions{}.margin;
    std::vector<CameraPathStudy> studies(scene.lights.size());
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const spatial::Light& light = scene.lights[l];
        std::optional<spatial::LightMatrix> previous;
        for (std::size_t k = 0; k < scene.cameraPath.size(); ++k) {
            spatial::Scene poseScene = scene;
            poseScene.camera = scene.cameraPath[k];
            const auto evaluator = MakeEvaluator(poseScene, backend, CameraPathField(k));
            spatial::LightOutcome o;
            try {
                o = evaluator->Evaluate(light, evalOptions);
            } catch (const DomainError& e) {
                throw InputError(SpatialErrorField(e, LightField(l), CameraPathField(k)) + ": " +
                                 e.what());
            }
            const spatial::HysteresisDecision d = spatial::ApplyHysteresis(
                previous, o.methods[0].matrix, o.samples, scene.shadowMap, margin);
            PoseOutcome pose;
            pose.changed = d.changed;
            pose.medianKept = d.medianPrevious;
            pose.medianNew = d.medianCandidate;
            pose.misclassifiedFresh = o.methods[0].misclassified;
            pose.misclassifiedHysteresis =
                d.changed ? pose.misclassifiedFresh : evaluator->Misclassified(light, d.matrix);
            studies[l].poses.push_back(pose);
            previous = d.matrix;
        }
    }
    return studies;
}

}  // namespace lexel::cases
