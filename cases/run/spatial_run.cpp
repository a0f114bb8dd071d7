#include "lexel/cases/run/spatial_run.h"

#include <algorithm>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {

std::vector<std::string> CameraPathMethods(const spatial::Scene& scene,
                                           const std::vector<std::string>& methods) {
    std::vector<std::string> kept;
    for (const std::string& m : methods)
        if (std::none_of(scene.methods.begin(), scene.methods.end(),
                         [&](const spatial::CaseMethod& c) { return c.name == m; }))
            kept.push_back(m);
    return kept;
}

std::size_t SpatialRunSteps(const spatial::Scene& scene, const SpatialRunOptions& options) {
    return scene.lights.size() * options.methods.size() +
           CameraPathSteps(scene, CameraPathMethods(scene, options.methods));
}

SpatialRun RunSpatialCase(const spatial::Scene& scene, const SpatialRunOptions& options) {
    if (scene.lights.empty())
        throw InputError(
            "/lights: the case has no fixed lights; run `lexel sweep` for its light_sweep");
    SpatialRun run;
    run.backend = MakeRenderBackend(options.backend, scene.geometry);
    run.evaluator = MakeEvaluator(scene, *run.backend);
    spatial::EvaluationOptions evalOptions;
    evalOptions.methods = options.methods;
    evalOptions.mapTruth = options.mapTruth;
    evalOptions.keepBuffers = options.keepBuffers;
    evalOptions.phases = scene.phases;
    evalOptions.maxPhases = scene.maxPhases;
    if (options.onStep) evalOptions.onMethodDone = [&](std::string_view) { options.onStep(); };
    // Every fixed light must face some counted pixel; checked for all before any method runs.
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        CheckLightFacesPixels(*run.evaluator, scene.lights[l], LightField(l));
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        evalOptions.given = spatial::GivenMatricesOf(scene.methods, options.methods, false, l);
        try {
            run.outcomes.push_back(run.evaluator->Evaluate(scene.lights[l], evalOptions));
        } catch (const DomainError& e) {
            throw InputError(SpatialErrorField(e, LightField(l)) + ": " + e.what());
        }
    }
    if (!scene.cameraPath.empty()) {
        run.cameraPath = RunCameraPathStudy(
            scene, *run.backend, CameraPathMethods(scene, options.methods), options.onStep);
    }
    return run;
}

}  // namespace lexel::cases
