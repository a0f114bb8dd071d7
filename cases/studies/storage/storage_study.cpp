#include "lexel/cases/studies/storage/storage_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/backend.h"
#include "lexel/cases/run/evaluator_setup.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {

namespace {

HemisphereStudy Hemisphere(const spatial::ViewFrustum& frustum, const std::string& label,
                           const spatial::Scheme& scheme, int size) {
    HemisphereStudy out{label, spatial::StorageHemisphere(frustum, scheme, size), 0.0, 0.0};
    out.minStorage = std::numeric_limits<double>::infinity();
    for (const spatial::HemisphereCell& cell : out.grid.cells)
        if (cell.inside) {
            out.minStorage = std::min(out.minStorage, cell.storage);
            out.maxStorage = std::max(out.maxStorage, cell.storage);
        }
    return out;
}

}  // namespace

StorageStudy RunStorageStudy(const spatial::ViewFrustum& frustum, const StorageOptions& options) {
    spatial::ValidateFrustum(frustum);
    StorageStudy out;
    out.frustum = frustum;
    out.optimal = spatial::OptimalStorageFactor(frustum);
    for (double ratio : {20.0, 100.0, frustum.DepthRatio()})
        if (std::find(out.warpRatios.begin(), out.warpRatios.end(), ratio) ==
            out.warpRatios.end()) {
            spatial::ViewFrustum f = frustum;
            f.farPlane = ratio * frustum.nearPlane;
            out.warpRatios.push_back(ratio);
            out.warp.push_back(spatial::WarpSweep(f, options.warpPoints));
        }
    out.partitions = spatial::PartitionSweep(frustum, options.maxMaps);
    out.maps = spatial::MapCountSweep(frustum, options.maxMaps);
    out.crossover = spatial::ZpFpCrossover(frustum, options.maxFacePartitions);
    out.hemisphere.push_back(
        Hemisphere(frustum, "no warp", spatial::Scheme::Zp(1), options.hemisphereSize));
    out.hemisphere.push_back(
        Hemisphere(frustum, "LiSPSM", spatial::Scheme::ZpWarp(1, 0.0), options.hemisphereSize));
    out.hemisphere.push_back(
        Hemisphere(frustum, "FP + W", spatial::Scheme::FpZpWarp(1, 0.0), options.hemisphereSize));
    return out;
}

spatial::ViewFrustum FrustumOf(const spatial::Camera& camera) {
    spatial::ViewFrustum f;
    f.fovYDeg = camera.fovYDeg;
    f.aspect = static_cast<double>(camera.resolution.width) / camera.resolution.height;
    f.nearPlane = camera.nearPlane;
    f.farPlane = camera.farPlane;
    return f;
}

double BestSingleMapStorage(const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight) {
    const auto storage = [&](double logOffset) {
        return spatial::StorageFactorForWarpOffset(frustum, esToLight,
                                                   frustum.nearPlane * std::pow(10.0, logOffset));
    };
    // S̄(n') is unimodal along the overhead closed form (eq. 12: flat on [n, n'_LSPSM], rising
    // after); a grid first guards against a second basin for skewed lights.
    constexpr double kLogLo = -3.0, kLogHi = 6.0;
    constexpr int kGrid = 181;  // 0.05 decades apart
    double best = spatial::StorageFactorForWarpOffset(frustum, esToLight,
                                                      std::numeric_limits<double>::infinity());
    double bestLog = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < kGrid; ++i) {
        const double t = kLogLo + (kLogHi - kLogLo) * i / (kGrid - 1);
        const double s = storage(t);
        if (s < best) best = s, bestLog = t;
    }
    if (std::isnan(bestLog)) return best;
    // Golden-section search on the grid cell around the best point.
    const double step = (kLogHi - kLogLo) / (kGrid - 1);
    double a = bestLog - step, b = bestLog + step;
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double c = b - g * (b - a), d = a + g * (b - a);
    double sc = storage(c), sd = storage(d);
    for (int i = 0; i < 60; ++i) {
        if (sc < sd)
            b = d, d = c, sd = sc, c = b - g * (b - a), sc = storage(c);
        else
            a = c, c = d, sc = sd, d = a + g * (b - a), sd = storage(d);
    }
    return std::min({best, sc, sd});
}

namespace {

// TSM's single map: the 80% rule with the focus at mid-depth puts the projection centre λ/3
// before the near plane (tsm.h: η = λ δ'(1 + ξ)/(λ(1 − ξ) − 2δ'), δ' = λ/2, ξ = −0.6), λ = f − n
// for an overhead light; over sin γ for others, as the schemes' LiSPSM (Lloyd 2006 §4.4).
SchemeValue TrapezoidStorage(const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight) {
    const glm::dvec3 toLight = glm::normalize(esToLight);
    const double sinGamma = glm::length(glm::cross(glm::dvec3(0.0, 0.0, -1.0), toLight));
    const double nPrime = sinGamma > 1e-3
                              ? (frustum.farPlane - frustum.nearPlane) / (3.0 * sinGamma)
                              : std::numeric_limits<double>::infinity();
    return {"TSM (n' = (f − n) / 3 sin γ)",
            spatial::StorageFactorForWarpOffset(frustum, esToLight, nPrime)};
}

}  // namespace

SchemeValue AnalyticStorageOf(spatial::StorageModel model, int partitions,
                              const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight) {
    const auto scheme = [&](const std::string& label, const spatial::Scheme& s) {
        return SchemeValue{label, spatial::EvaluateScheme(frustum, esToLight, s).storage};
    };
    const std::string k = std::to_string(partitions);
    using enum spatial::StorageModel;
    switch (model) {
        case kBestSingleMap:
            return {"best single map", BestSingleMapStorage(frustum, esToLight)};
        case kUnwarped:
            return scheme("no warp", spatial::Scheme::Zp(1));
        case kLispsm:
            return scheme("LiSPSM", spatial::Scheme::ZpWarp(1, 0.0));
        case kPsm:
            return scheme("PSM", spatial::Scheme::ZpWarp(1, 1.0));
        case kTrapezoid:
            return TrapezoidStorage(frustum, esToLight);
        case kLogPsm:
            return {"LogPSM", spatial::LogPsmStorageFactor(frustum, esToLight)};
        // RTW's warps follow the scene's importance: no closed form in Lloyd's analysis.
        case kAdaptive:
            return {"adaptive (RTW)", std::numeric_limits<double>::quiet_NaN()};
        case kZPartitions:
            return scheme("ZP (k = " + k + ")", spatial::Scheme::Zp(partitions));
        case kZPartitionsWarped:
            return scheme("ZP + W (k = " + k + ")", spatial::Scheme::ZpWarp(partitions));
        case kFacePartitionsWarped:
            return scheme("FP + W", spatial::Scheme::FpZpWarp(1));
        case kVirtualLevels: {
            // A virtual map's levels halve the texel width per level and each pixel takes the
            // level its footprint asks for: unwarped z-partitions with ratio ρ ≤ 2,
            // k = ⌈log₂ f/n⌉.
            const int levels =
                std::max(1, static_cast<int>(std::ceil(std::log2(frustum.DepthRatio()) - 1e-9)));
            return scheme("ZP, k = ⌈log₂ f/n⌉", spatial::Scheme::Zp(levels));
        }
    }
    return {"best single map", BestSingleMapStorage(frustum, esToLight)};
}

SchemeValue AnalyticStorageOf(const std::string& method, int partitions,
                              const spatial::ViewFrustum& frustum, const glm::dvec3& esToLight) {
    const spatial::MethodInfo* info = spatial::FindMethodInfo(method);
    return AnalyticStorageOf(info ? info->storage : spatial::StorageModel::kBestSingleMap,
                             partitions, frustum, esToLight);
}

namespace {

// The light's eye-space direction: a directional light's, or for a point light the direction
// from the centroid of the visible frame points (Lloyd's analysis is for directional lights).
glm::dvec3 EyeDirectionToLight(const spatial::Camera& camera, const spatial::Light& light,
                               const glm::dvec3& wsCentroid) {
    const glm::dvec3 wsToLight = light.type == spatial::Light::Type::kDirectional
                                     ? -light.direction
                                     : light.position - wsCentroid;
    return glm::normalize(glm::dvec3(camera.ViewFromWorld() * glm::dvec4(wsToLight, 0.0)));
}

}  // namespace

namespace {

// The covered frame pixels' planar eye-depth range (as `visible`: the camera's frustum with that
// near and far) and their centroid, world space.
void VisibleDepths(const spatial::Scene& scene, const spatial::CameraBuffer& frame,
                   spatial::ViewFrustum* visible, glm::dvec3* wsCentroid) {
    double zLo = std::numeric_limits<double>::infinity(), zHi = 0.0;
    glm::dvec3 sum(0.0);
    std::size_t covered = 0;
    for (std::size_t i = 0; i < frame.wsPosition.size(); ++i) {
        if (!frame.Covered(i)) continue;
        const double z = spatial::PlanarEyeDepth(scene.camera, frame.wsPosition[i]);
        zLo = std::min(zLo, z), zHi = std::max(zHi, z);
        sum += frame.wsPosition[i];
        ++covered;
    }
    *wsCentroid = sum / static_cast<double>(std::max<std::size_t>(1, covered));
    visible->nearPlane = zLo;
    visible->farPlane = zHi;
}

// One method's row: its measured storage beside its storage model's, for the camera's and the
// visible depths.
CaseStorageRow StorageRow(const spatial::MethodOutcome& m, const CaseStorage& out,
                          const glm::dvec3& esToLight) {
    CaseStorageRow row;
    row.method = m.method;
    row.maps = m.pages ? static_cast<int>(m.pages->resident)
                       : std::max<int>(1, static_cast<int>(m.cascades.size()));
    row.texels = m.metrics.texels;
    row.perspectiveMax = m.metrics.perspectiveMax;
    row.measured = m.metrics.storageFactor;
    row.measuredP99 = m.metrics.storageFactorP99;
    const int k = spatial::IsPartitionedMethod(m.method) ? row.maps : 1;
    row.camera = AnalyticStorageOf(m.method, k, out.camera, esToLight);
    row.visible = AnalyticStorageOf(m.method, k, out.visible, esToLight);
    return row;
}

}  // namespace

CaseStorage RunCaseStorage(const spatial::Scene& scene, const std::vector<std::string>& methods) {
    if (scene.lights.empty())
        throw InputError(
            "/lights: the case has no fixed lights; give a case with lights for --case");
    CaseStorage out;
    out.caseName = scene.name;
    out.camera = FrustumOf(scene.camera);
    out.partitions = scene.partitions.count;
    const auto backend = MakeRenderBackend(BackendKind::kCpu, scene.geometry);
    const std::unique_ptr<spatial::Evaluator> evaluator = MakeEvaluator(scene, *backend);
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        CheckLightFacesPixels(*evaluator, scene.lights[l], LightField(l));
    out.visible = out.camera;
    glm::dvec3 wsCentroid;
    VisibleDepths(scene, evaluator->frame(), &out.visible, &wsCentroid);

    spatial::EvaluationOptions options;
    options.methods = methods;
    const glm::dvec3 esView(0.0, 0.0, -1.0);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        spatial::LightOutcome outcome;
        try {
            outcome = evaluator->Evaluate(scene.lights[l], options);
        } catch (const DomainError& e) {
            throw InputError(SpatialErrorField(e, LightField(l)) + ": " + e.what());
        }
        CaseStorageLight light;
        light.light = scene.lights[l];
        light.esToLight = EyeDirectionToLight(scene.camera, light.light, wsCentroid);
        light.gammaDeg =
            glm::degrees(std::acos(std::clamp(-glm::dot(light.esToLight, esView), -1.0, 1.0)));
        light.optimalCamera = spatial::OptimalStorageFactor(out.camera);
        light.optimalVisible = spatial::OptimalStorageFactor(out.visible);
        light.bestSingleCamera = BestSingleMapStorage(out.camera, light.esToLight);
        light.bestSingleVisible = BestSingleMapStorage(out.visible, light.esToLight);
        for (const spatial::MethodOutcome& m : outcome.methods)
            light.rows.push_back(StorageRow(m, out, light.esToLight));
        out.lights.push_back(std::move(light));
    }
    return out;
}

}  // namespace lexel::cases
