#include "lexel/spatial/harness/evaluation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <stdexcept>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/oracle.h"
#include "lexel/spatial/harness/page_shading.h"
#include "lexel/spatial/harness/ray_cast_map.h"
#include "lexel/spatial/harness/ray_caster.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/optimizer.h"

namespace lexel::spatial {

Evaluator::Evaluator(const Scene& scene, const RenderBackend& backend)
    : scene_(scene), backend_(backend), bounds_(scene.geometry.ComputeBounds()) {
    if (bounds_.Empty()) throw DomainError(Subject::kGeometry, "the scene has no triangles");
    frame_ = backend.RenderCamera(scene.camera, scene.camera.resolution);
    readback_ = RenderReadback(backend, scene.camera, scene.readback);
    if (readback_.wsRelevant.empty())
        throw DomainError(Subject::kCamera, "no geometry is visible at the readback resolution (" +
                                                std::to_string(scene.readback.width) + "×" +
                                                std::to_string(scene.readback.height) + ")");
    PlaneDerivatives(frame_, scene.camera.ScreenFromWorld(scene.camera.resolution), &frameDWdx1_,
                     &frameDWdx2_);
    frameDepth_.assign(frame_.wsPosition.size(), 0.0);
    for (std::size_t i = 0; i < frameDepth_.size(); ++i)
        if (frame_.Covered(i)) frameDepth_[i] = PlanarEyeDepth(scene.camera, frame_.wsPosition[i]);
    caster_ = std::make_unique<RayCaster>(scene.geometry);
    mapper_ = std::make_unique<RayCastMapper>(scene.geometry, *caster_);
}

Evaluator::~Evaluator() = default;

std::vector<std::uint8_t> Evaluator::TraceTruth(const LightSpace& lightSpace) const {
    const double offset = kRayOffset * bounds_.Radius();
    std::vector<ShadowRay> rays;
    std::vector<std::size_t> pixels;
    for (std::size_t i = 0; i < frame_.triangle.size(); ++i) {
        if (!frame_.Covered(i)) continue;
        const glm::dvec3& ws = frame_.wsPosition[i];
        const glm::dvec3 toLight = lightSpace.DirectionToLight(ws);
        if (!(glm::dot(frame_.wsNormal[i], toLight) > 0.0)) continue;
        const glm::dvec3 origin = ws + offset * frame_.wsNormal[i];
        const double distance = lightSpace.DistanceToLight(origin);
        const double tFar = std::isinf(distance) ? distance : distance - offset;
        rays.push_back(caster_->ToShadowRay(origin, toLight, 0.0, tFar));
        pixels.push_back(i);
    }
    std::vector<std::uint8_t> occluded(rays.size(), 0);
    caster_->OccludedBatch(rays, occluded);
    std::vector<std::uint8_t> truth(frame_.triangle.size(), 0);
    for (std::size_t k = 0; k < pixels.size(); ++k) truth[pixels[k]] = occluded[k];
    return truth;
}

namespace {

// The e that `optimal` minimizes in this scene (the evaluation's e column): kEdgeEnergy at the
// case's exponent.
EnergyOptions EdgeEnergyOf(const Scene& scene) {
    EnergyOptions e = kEdgeEnergy;
    e.exponent = scene.edgeExponent;
    return e;
}

// Counted pixels (a method shades exactly those lit or shadowed: ShadePoint's facing test is the
// counting rule) whose decision differs from the rays'; `falseShadow` gets the lit ones it shadows.
std::int64_t CountWrong(std::span<const Shade> shades, std::span<const std::uint8_t> truth,
                        std::int64_t* falseShadow) {
    std::int64_t wrong = 0, shadowWrong = 0;
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (shades[i] != Shade::kLit && shades[i] != Shade::kShadowed) continue;
        const bool shadowed = shades[i] == Shade::kShadowed;
        if (shadowed != static_cast<bool>(truth[i])) {
            ++wrong;
            shadowWrong += shadowed;
        }
    }
    if (falseShadow) *falseShadow = shadowWrong;
    return wrong;
}

// The frame shaded through one map, or through cascades: per pixel the shade of the cascade
// CascadeFor picks by its planar eye depth, and that cascade.
struct FrameShading {
    std::vector<Shade> shades;
    std::vector<ShadowMap> maps;        // one per cascade (one for a single map)
    std::vector<std::uint8_t> cascade;  // per pixel: the serving map's index
    std::vector<std::uint8_t> outside;  // per pixel: 1 where no cascade's depth interval holds it
};

FrameShading ShadeThroughCascades(const RenderBackend& backend, const CameraBuffer& frame,
                                  const LightSpace& lightSpace, std::span<const Cascade> cascades,
                                  std::span<const double> frameDepth) {
    FrameShading out;
    std::vector<std::vector<Shade>> perCascade;
    for (const Cascade& c : cascades) {
        out.maps.push_back(backend.RenderShadowMap(lightSpace, c.matrix, c.map));
        perCascade.push_back(backend.ShadePixels(frame, lightSpace, out.maps.back()));
    }
    const std::size_t n = frame.triangle.size();
    out.shades.assign(n, Shade::kEmpty);
    out.cascade.assign(n, 0);
    out.outside.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!frame.Covered(i)) continue;
        bool covered = true;
        const std::size_t c = CascadeFor(cascades, frameDepth[i], frame.wsPosition[i], &covered);
        out.shades[i] = perCascade[c][i];
        out.cascade[i] = static_cast<std::uint8_t>(c);
        out.outside[i] = !covered;
    }
    return out;
}

FrameShading ShadeThroughMap(const RenderBackend& backend, const CameraBuffer& frame,
                             const LightSpace& lightSpace, const LightMatrix& matrix,
                             Resolution resolution) {
    FrameShading out;
    out.maps.push_back(backend.RenderShadowMap(lightSpace, matrix, resolution));
    out.shades = backend.ShadePixels(frame, lightSpace, out.maps.back());
    out.cascade.assign(out.shades.size(), 0);
    out.outside.assign(out.shades.size(), 0);
    return out;
}

// A warped method's map (ray_cast_map.h): the backend's where it rasterizes the warp, else
// ray-cast; the frame shaded through it.
FrameShading ShadeThroughWarp(const RenderBackend& backend, const RayCastMapper& mapper,
                              const CameraBuffer& frame, const LightSpace& lightSpace,
                              const MapWarp& warp, Resolution resolution) {
    FrameShading out;
    std::optional<ShadowMap> map = backend.RenderWarpedShadowMap(lightSpace, warp, resolution);
    out.maps.push_back(map ? std::move(*map) : mapper.Render(lightSpace, warp, resolution));
    out.shades = backend.ShadePixels(frame, lightSpace, out.maps.back());
    out.cascade.assign(out.shades.size(), 0);
    out.outside.assign(out.shades.size(), 0);
    return out;
}

// A warped method's resolution: its own, or the scene's.
Resolution WarpResolution(const MethodMatrix& computed, Resolution scene) {
    return computed.resolution.width > 0 ? computed.resolution : scene;
}

// What shading a method's map(s) needs beside the method itself.
struct ShadingSetup {
    const RenderBackend& backend;
    const RayCastMapper& mapper;
    const CameraBuffer& frame;
    const LightSpace& lightSpace;
    const Camera& camera;
    Resolution shadowMap;                // the scene's map
    std::span<const double> frameDepth;  // per frame pixel: planar eye depth
};

// The frame shaded through the method's map(s) with their texel grids moved by `phase` texels
// (sub_texel_phase.h): every cascade alike; a virtual map's pages requested afresh on the moved
// grid at the bias it was built with (`vsmAtPhase`, called only for phase ≠ 0).
FrameShading ShadeMethod(const ShadingSetup& s, const MethodMatrix& computed,
                         const glm::dvec2& phase,
                         const std::function<VirtualShadowMap(const glm::dvec2&)>& vsmAtPhase) {
    const bool moved = phase != glm::dvec2(0.0);
    if (computed.virtualMap) {
        PageShading p = ShadeThroughPages(s.backend, s.frame, s.lightSpace, s.camera,
                                          moved ? vsmAtPhase(phase) : *computed.virtualMap);
        return {std::move(p.shades), std::move(p.maps), std::move(p.page), std::move(p.outside)};
    }
    if (computed.warp)
        return ShadeThroughWarp(s.backend, s.mapper, s.frame, s.lightSpace,
                                moved ? computed.warp->Shifted(phase) : *computed.warp,
                                WarpResolution(computed, s.shadowMap));
    if (computed.cascades.empty())
        return ShadeThroughMap(s.backend, s.frame, s.lightSpace, computed.matrix.Shifted(phase),
                               s.shadowMap);
    std::vector<Cascade> cascades = computed.cascades;
    for (Cascade& c : cascades) c.matrix = c.matrix.Shifted(phase);
    return ShadeThroughCascades(s.backend, s.frame, s.lightSpace, cascades, s.frameDepth);
}

struct Footprints {
    double mean = 0.0, max = 0.0;
    std::int64_t uncovered = 0;
    double perspectiveMax = 0.0, perspectiveP99 = 0.0;
};

// The nearest-rank q-quantile (q in [0, 1]) of the values; 0 for none. Reorders them.
double NearestRankQuantile(std::vector<double>& values, double q) {
    if (values.empty()) return 0.0;
    const auto rank = static_cast<std::size_t>(
        std::max(1.0, std::ceil(q * static_cast<double>(values.size()))) - 1.0);
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                     values.end());
    return values[rank];
}

// σ₁(J⁻¹) over the counted pixels of a shading (evaluation.h); a counted pixel outside its
// cascade's depth interval, behind its map's plane or outside its texels is uncovered instead.
Footprints MeasureFootprints(const Camera& camera, const LightSpace& lightSpace,
                             const CameraBuffer& frame, std::span<const glm::dvec3> dWdx1,
                             std::span<const glm::dvec3> dWdx2, const FrameShading& shading) {
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    Footprints f;
    double sum = 0.0;
    std::int64_t measured = 0;
    std::vector<double> perspective;
    for (std::size_t i = 0; i < shading.shades.size(); ++i) {
        if (shading.shades[i] != Shade::kLit && shading.shades[i] != Shade::kShadowed) continue;
        const ShadowMap& map = shading.maps[shading.cascade[i]];
        const glm::dvec3 lsX = lightSpace.ToLight(frame.wsPosition[i]);
        const glm::dvec2 u = MapCoordinates(map, lsX).value_or(glm::dvec2(-1.0));
        if (shading.outside[i] || !(u.x >= 0.0 && u.y >= 0.0 && u.x < map.resolution.width &&
                                    u.y < map.resolution.height)) {
            ++f.uncovered;
            continue;
        }
        const double aliasing =
            map.warp ? WarpPerspectiveAliasing(camera, lightSpace, *map.warp, frame.wsPosition[i])
                     : PerspectiveAliasing(camera, lightSpace, map.matrix, frame.wsPosition[i]);
        if (std::isfinite(aliasing)) perspective.push_back(aliasing);
        const double sigma = MapSampleBadness(map, lsX, lsFromWs * dWdx1[i], lsFromWs * dWdx2[i],
                                              Badness::kLargestSingularValue);
        if (!std::isfinite(sigma)) continue;  // J singular: the pixel's plane contains its ray
        sum += sigma;
        f.max = std::max(f.max, sigma);
        ++measured;
    }
    f.mean = measured > 0 ? sum / static_cast<double>(measured) : 0.0;
    if (!perspective.empty())
        f.perspectiveMax = *std::max_element(perspective.begin(), perspective.end());
    f.perspectiveP99 = NearestRankQuantile(perspective, 0.99);
    return f;
}

}  // namespace

double EffectiveStorageFactor(std::int64_t texels, double aliasing, std::int64_t framePixels) {
    if (framePixels <= 0) return 0.0;
    return static_cast<double>(texels) * aliasing * aliasing / static_cast<double>(framePixels);
}

std::vector<Shade> Evaluator::ShadeFrame(const Light& light, const LightMatrix& matrix) const {
    const LightSpace lightSpace(light, bounds_);
    return backend_.ShadePixels(frame_, lightSpace,
                                backend_.RenderShadowMap(lightSpace, matrix, scene_.shadowMap));
}

glm::dmat4 Evaluator::ClipFromWorldOf(const Light& light, const LightMatrix& matrix,
                                      Resolution map) const {
    const LightSpace lightSpace(light, bounds_);
    DepthRange range;
    try {
        range = LightDepthRange(lightSpace, matrix, map, bounds_, readback_.wsRelevant);
    } catch (const std::invalid_argument&) {
        double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
        for (const glm::dvec3& wsCorner : bounds_.Corners()) {
            const double d = lightSpace.IsPoint() ? lightSpace.DistanceToLight(wsCorner)
                                                  : lightSpace.Depth(wsCorner);
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        }
        range = {lightSpace.IsPoint() ? 0.5 * nearest : nearest, farthest + (farthest - nearest)};
    }
    return ClipFromWorld(lightSpace, matrix, map, range, ClipDepth::kMinusOneToOne);
}

std::int64_t Evaluator::CountedPixels(const Light& light) const {
    const LightSpace lightSpace(light, bounds_);
    std::int64_t counted = 0;
    for (std::size_t i = 0; i < frame_.triangle.size(); ++i)
        counted +=
            frame_.Covered(i) &&
            glm::dot(frame_.wsNormal[i], lightSpace.DirectionToLight(frame_.wsPosition[i])) > 0.0;
    return counted;
}

LightMatrix Evaluator::OracleMatrix(const LightSpace& lightSpace, const MethodContext& context,
                                    std::span<const std::uint8_t> truth,
                                    const EvaluationOptions& options, std::string* winner) const {
    std::vector<OracleStart> starts;
    for (const std::string& name : FairMethodNames()) {
        try {
            starts.push_back({name, ComputeLightMatrix(name, context).matrix});
        } catch (const std::exception&) {
            // A start that cannot serve this light (no samples, no floor plane) is left out.
        }
    }
    const LightSamples& samples = *context.samples;
    const std::vector<glm::dvec3>& lsCone =
        samples.lsRelevantHull.empty() ? samples.lsRelevant : samples.lsRelevantHull;
    const std::optional<RelevantHull> hull =
        RelevantHull::Of(lsCone, glm::normalize(FocusedLightMatrix(context.baseline).p4));
    if (starts.empty() || !hull)
        throw DomainError(Subject::kLight, "optimal-oracle: no single matrix serves this light");
    // Scored on phases held out of every reported mean (those after the most a method may be
    // measured at: no winner's curse), to the same residual (CountOverPhases).
    const int heldOutFrom = MostPhases(options.phases, options.maxPhases);
    const auto score = [&](const LightMatrix& matrix) {
        const std::vector<std::int64_t> wrong = CountOverPhases(
            options.phases, options.maxPhases, heldOutFrom, [&](int, const glm::dvec2& shift) {
                return CountWrong(ShadeThroughMap(backend_, frame_, lightSpace,
                                                  matrix.Shifted(shift), scene_.shadowMap)
                                      .shades,
                                  truth, nullptr);
            });
        return MeanOverPhases(wrong).mean;
    };
    const OracleResult best = SearchOracleMatrix(starts, *hull, scene_.shadowMap, score);
    *winner = best.start;
    return best.matrix;
}

std::vector<std::uint8_t> Evaluator::TruthShadows(const Light& light) const {
    return TraceTruth(LightSpace(light, bounds_));
}

std::int64_t Evaluator::Misclassified(const Light& light, const LightMatrix& matrix) const {
    const LightSpace lightSpace(light, bounds_);
    return CountWrong(
        backend_.ShadePixels(frame_, lightSpace,
                             backend_.RenderShadowMap(lightSpace, matrix, scene_.shadowMap)),
        TraceTruth(lightSpace), nullptr);
}

namespace {

// The context every method gets for the light (MethodContext): the scene's cascades and optimizer
// settings, the baselines' context, the readback and the frame's size; the caller sets the
// samples.
MethodContext LightMethodContext(const Scene& scene, const LightSpace& lightSpace,
                                 const Bounds& bounds, const Readback& readback,
                                 std::span<const GivenMatrix> given) {
    MethodContext context;
    context.given = given;
    context.partitions = scene.partitions;
    context.partitions.maxSamples = scene.optimizerMaxSamples;
    context.maxSamples = scene.optimizerMaxSamples;
    context.edgeExponent = scene.edgeExponent;
    if (context.partitions.energy.kind == EnergyKind::kEdge)
        context.partitions.energy.exponent = scene.edgeExponent;
    context.baseline = MakeBaselineContext(scene, lightSpace, bounds, readback.wsRelevant,
                                           readback.wsRelevantHull);
    context.readback = &readback;
    context.frame = scene.camera.resolution;
    return context;
}

// The counted frame pixels (covered, facing the light) and how many the truth shadows.
void CountReceivers(const CameraBuffer& frame, const LightSpace& lightSpace,
                    std::span<const std::uint8_t> truth, LightOutcome* out) {
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!frame.Covered(i)) continue;
        const bool counted =
            glm::dot(frame.wsNormal[i], lightSpace.DirectionToLight(frame.wsPosition[i])) > 0.0;
        out->receiverPixels += counted;
        out->truthShadowed += counted && truth[i];
    }
}

// Which samples the light grazes (projection aliasing, evaluation.h).
std::vector<std::uint8_t> GrazingSamples(const LightSamples& samples, const Readback& readback,
                                         const LightSpace& lightSpace) {
    std::vector<std::uint8_t> grazing(samples.lsX.size(), 0);
    for (std::size_t s = 0; s < grazing.size(); ++s) {
        const std::size_t pixel = samples.pixel[s];
        const glm::dvec3& wsPoint = readback.buffer.wsPosition[pixel];
        grazing[s] = std::abs(glm::dot(readback.buffer.wsNormal[pixel],
                                       lightSpace.DirectionToLight(wsPoint))) < kGrazingCos;
    }
    return grazing;
}

// The pixels on which the focused map at size × size texels disagrees with the exact rays.
std::int64_t MapTruthDisagreement(const RenderBackend& backend, const CameraBuffer& frame,
                                  const LightSpace& lightSpace, const LightMatrix& focused,
                                  Resolution caseMap, int size,
                                  std::span<const std::uint8_t> truth) {
    // The focused matrix is fitted for the case's map; scale its texels to the truth map's.
    glm::dmat3 toTruth(1.0);
    toTruth[0][0] = static_cast<double>(size) / caseMap.width;
    toTruth[1][1] = static_cast<double>(size) / caseMap.height;
    const ShadowMap truthMap =
        backend.RenderShadowMap(lightSpace, focused.ThenAffine(toTruth), {size, size});
    return CountWrong(backend.ShadePixels(frame, lightSpace, truthMap), truth, nullptr);
}

}  // namespace

LightOutcome Evaluator::Evaluate(const Light& light, const EvaluationOptions& options) const {
    LightOutcome out;
    out.light = light;
    out.phases = options.phases;
    out.maxPhases = MostPhases(options.phases, options.maxPhases);
    const LightSpace lightSpace(light, bounds_);
    MethodContext context =
        LightMethodContext(scene_, lightSpace, bounds_, readback_, options.given);

    // Step 1 of Algorithm 1: boundary samples from a standard (focused) shadow map.
    const LightMatrix focused = FocusedLightMatrix(context.baseline);
    const ShadowMap standardMap = backend_.RenderShadowMap(lightSpace, focused, scene_.shadowMap);
    out.samples = backend_.BoundarySamples(readback_, lightSpace, standardMap);
    context.samples = &out.samples;
    context.baseline.samples = &out.samples;

    std::vector<std::uint8_t> truth = TraceTruth(lightSpace);
    CountReceivers(frame_, lightSpace, truth, &out);
    if (options.mapTruth)
        out.mapTruthDisagree = MapTruthDisagreement(backend_, frame_, lightSpace, focused,
                                                    scene_.shadowMap, options.truthMapSize, truth);
    const std::vector<std::uint8_t> grazing = GrazingSamples(out.samples, readback_, lightSpace);

    for (const std::string& method : options.methods) {
        MethodOutcome m;
        m.method = method;
        const Stopwatch timer;
        MethodMatrix computed;
        if (method == kOracleMethod)
            computed.matrix = OracleMatrix(lightSpace, context, truth, options, &computed.winner);
        else
            computed = ComputeLightMatrix(method, context);
        m.metrics.ms = timer.Ms();
        if (computed.optimizer) {
            m.trace.hAfterIteration = computed.optimizer->hAfterIteration;
            m.trace.hBeforeRefine = computed.optimizer->hBeforeRefine;
        }
        m.trace.winner = computed.winner;
        Measure(lightSpace, computed, context, out, grazing, truth, options, &m);
        out.methods.push_back(std::move(m));
        if (options.onMethodDone) options.onMethodDone(method);
    }
    if (options.keepBuffers) out.truth = std::move(truth);
    return out;
}

namespace {

// h of a partitioned method: each sample's badness under the cascade that serves it, summed in
// sample order (per cascade, and the grazing part).
void MeasureCascadeEnergy(const Camera& camera, std::span<const Cascade> cascades,
                          const LightSamples& samples, std::span<const std::uint8_t> grazing,
                          MethodOutcome* m) {
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        const glm::dvec3& ws = samples.wsX[s];
        const std::size_t c = CascadeFor(cascades, PlanarEyeDepth(camera, ws), ws);
        const double badness =
            SampleBadness(cascades[c].matrix, samples.lsX[s], samples.dXdx1[s], samples.dXdx2[s]);
        m->metrics.h += badness;
        m->cascades[c].h += badness;
        if (grazing[s]) m->metrics.hGrazing += badness;
    }
}

}  // namespace

namespace {

using VsmAtPhase = std::function<VirtualShadowMap(const glm::dvec2&)>;

// The misclassified pixels of `shading` (phase 0: the map as computed) and their mean, standard
// error and false shadows over the sub-texel phases (sub_texel_phase.h).
void CountOverMapPhases(const ShadingSetup& setup, const MethodMatrix& computed,
                        const FrameShading& shading, std::span<const std::uint8_t> truth,
                        const EvaluationOptions& options, const VsmAtPhase& vsmAtPhase,
                        MethodMetrics* metrics) {
    metrics->misclassified = CountWrong(shading.shades, truth, &metrics->falseShadow);
    double falseShadows = 0.0;
    const std::vector<std::int64_t> wrong =
        CountOverPhases(options.phases, options.maxPhases, 0, [&](int k, const glm::dvec2& phase) {
            std::int64_t falseShadow = metrics->falseShadow;
            const std::int64_t count =
                k == 0 ? metrics->misclassified
                       : CountWrong(ShadeMethod(setup, computed, phase, vsmAtPhase).shades, truth,
                                    &falseShadow);
            falseShadows += static_cast<double>(falseShadow);
            return count;
        });
    const PhaseMean mean = MeanOverPhases(wrong);
    metrics->misclassifiedMean = mean.mean;
    metrics->misclassifiedError = mean.standardError;
    metrics->phases = static_cast<int>(wrong.size());
    metrics->falseShadowMean = falseShadows / static_cast<double>(wrong.size());
}

// The footprint metrics, the maps' texels and the effective storage factors (max and 99th
// percentile) over a frame of framePixels pixels.
void SetFootprintMetrics(const Footprints& footprints, const FrameShading& shading,
                         std::int64_t framePixels, MethodMetrics* metrics) {
    metrics->footprintMean = footprints.mean;
    metrics->footprintMax = footprints.max;
    metrics->uncovered = footprints.uncovered;
    metrics->perspectiveMax = footprints.perspectiveMax;
    metrics->perspectiveP99 = footprints.perspectiveP99;
    for (const ShadowMap& map : shading.maps)
        metrics->texels += static_cast<std::int64_t>(map.resolution.width) * map.resolution.height;
    metrics->storageFactor =
        EffectiveStorageFactor(metrics->texels, metrics->perspectiveMax, framePixels);
    metrics->storageFactorP99 =
        EffectiveStorageFactor(metrics->texels, metrics->perspectiveP99, framePixels);
}

// h (its grazing part) and e of a single map or warp: e only for a light matrix.
void MeasureSingleMapEnergy(const MethodMatrix& computed, const ShadowMap& map,
                            const LightSamples& samples, std::span<const std::uint8_t> grazing,
                            const EnergyOptions& edgeEnergy, MethodOutcome* m) {
    MethodMetrics& metrics = m->metrics;
    metrics.h = computed.warp ? WarpEnergy(*computed.warp, samples) : Energy(m->matrix, samples);
    if (!computed.warp) metrics.e = Energy(m->matrix, samples, edgeEnergy);
    for (std::size_t s = 0; s < grazing.size(); ++s)
        if (grazing[s])
            metrics.hGrazing +=
                MapSampleBadness(map, samples.lsX[s], samples.dXdx1[s], samples.dXdx2[s],
                                 Badness::kFrobeniusInverseSquared);
}

// A partitioned method's cascades with their counted pixels and empty partitions, h per cascade
// and e over the cascades.
void MeasureCascades(const Scene& scene, const MethodMatrix& computed, const MethodContext& context,
                     const FrameShading& shading, const LightSamples& samples,
                     std::span<const std::uint8_t> grazing, MethodOutcome* m) {
    for (const Cascade& c : computed.cascades) {
        m->cascades.push_back({c, 0, 0.0});
        m->emptyPartitions += c.visiblePoints == 0;
    }
    for (std::size_t i = 0; i < shading.shades.size(); ++i)
        if (shading.shades[i] == Shade::kLit || shading.shades[i] == Shade::kShadowed)
            ++m->cascades[shading.cascade[i]].pixels;
    MeasureCascadeEnergy(scene.camera, computed.cascades, samples, grazing, m);
    m->metrics.e = PartitionedEnergy(computed.cascades, samples, context.baseline.wsRelevant,
                                     scene.camera, EdgeEnergyOf(scene));
}

// The buffers the images need (EvaluationOptions::keepBuffers): the shades, and the map (a
// virtual map's pool as an atlas; every cascade's map for a partitioned method).
void KeepBuffers(const MethodMatrix& computed, FrameShading&& shading, MethodOutcome* m) {
    m->buffers.shades = std::move(shading.shades);
    if (computed.virtualMap) {
        m->buffers.map = PoolAtlas(shading.maps, computed.virtualMap->layout.pageTexels);
        m->buffers.uncoveredPixels = std::move(shading.outside);
        return;
    }
    m->buffers.map = shading.maps.front();
    if (!computed.cascades.empty()) m->buffers.cascadeMaps = std::move(shading.maps);
}

}  // namespace

void Evaluator::Measure(const LightSpace& lightSpace, const MethodMatrix& computed,
                        const MethodContext& context, const LightOutcome& light,
                        std::span<const std::uint8_t> grazing, std::span<const std::uint8_t> truth,
                        const EvaluationOptions& options, MethodOutcome* m) const {
    const LightSamples& samples = light.samples;
    m->matrix = computed.matrix;
    const ShadingSetup setup{backend_,      *mapper_,         frame_,     lightSpace,
                             scene_.camera, scene_.shadowMap, frameDepth_};
    const VsmAtPhase vsmAtPhase = [&](const glm::dvec2& phase) {
        VirtualMapOptions vsmOptions;
        vsmOptions.lodBias = computed.virtualMap->lodBias;
        vsmOptions.fitPool = false;
        vsmOptions.phase = phase;
        return BuildVirtualShadowMap(context.baseline, readback_, vsmOptions);
    };
    // Phase 0 (the map as computed) gives the single counts, the footprints and the buffers.
    FrameShading shading = ShadeMethod(setup, computed, glm::dvec2(0.0), vsmAtPhase);
    CountOverMapPhases(setup, computed, shading, truth, options, vsmAtPhase, &m->metrics);
    const std::int64_t framePixels =
        static_cast<std::int64_t>(scene_.camera.resolution.width) * scene_.camera.resolution.height;
    SetFootprintMetrics(
        MeasureFootprints(scene_.camera, lightSpace, frame_, frameDWdx1_, frameDWdx2_, shading),
        shading, framePixels, &m->metrics);
    if (const auto& vsm = computed.virtualMap) {
        m->metrics.h =
            PageEnergy(*vsm, scene_.camera, lightSpace, samples, grazing, &m->metrics.hGrazing);
        m->pages =
            PageOutcome{vsm->requested,        static_cast<std::int64_t>(vsm->resident.size()),
                        vsm->dropped,          vsm->layout.pageTexels,
                        vsm->layout.poolPages, vsm->lodBias};
    } else if (computed.cascades.empty()) {
        MeasureSingleMapEnergy(computed, shading.maps.front(), samples, grazing,
                               EdgeEnergyOf(scene_), m);
    } else {
        MeasureCascades(scene_, computed, context, shading, samples, grazing, m);
    }
    if (options.keepBuffers) KeepBuffers(computed, std::move(shading), m);
}

}  // namespace lexel::spatial
