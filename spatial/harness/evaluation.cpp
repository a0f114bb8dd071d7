#include "lexel/spatial/harness/evaluation.h"

#include <span>

#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/harness/ray_caster.h"

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
    caster_ = std::make_unique<RayCaster>(scene.geometry);
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
        const float tFar = std::isinf(distance) ? std::numeric_limits<float>::infinity()
                                                : static_cast<float>(distance - offset);
        rays.push_back({glm::vec3(origin), glm::vec3(toLight), 0.0f, tFar});
        pixels.push_back(i);
    }
    std::vector<std::uint8_t> occluded(rays.size(), 0);
    caster_->OccludedBatch(rays, occluded);
    std::vector<std::uint8_t> truth(frame_.triangle.size(), 0);
    for (std::size_t k = 0; k < pixels.size(); ++k) truth[pixels[k]] = occluded[k];
    return truth;
}

namespace {

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

}  // namespace

std::int64_t Evaluator::Misclassified(const Light& light, const LightMatrix& matrix) const {
    const LightSpace lightSpace(light, bounds_);
    return CountWrong(
        backend_.ShadePixels(frame_, lightSpace,
                             backend_.RenderShadowMap(lightSpace, matrix, scene_.shadowMap)),
        TraceTruth(lightSpace), nullptr);
}

LightOutcome Evaluator::Evaluate(const Light& light, const EvaluationOptions& options) const {
    LightOutcome out;
    out.light = light;
    const LightSpace lightSpace(light, bounds_);

    MethodContext context;
    context.baseline = MakeBaselineContext(scene_, lightSpace, bounds_, readback_.wsRelevant,
                                           readback_.wsRelevantHull);

    // Step 1 of Algorithm 1: boundary samples from a standard (focused) shadow map.
    const LightMatrix focused = FocusedLightMatrix(context.baseline);
    const ShadowMap standardMap = backend_.RenderShadowMap(lightSpace, focused, scene_.shadowMap);
    out.samples = backend_.BoundarySamples(readback_, lightSpace, standardMap);
    context.samples = &out.samples;
    context.baseline.samples = &out.samples;

    // The counted frame pixels (covered, facing the light) and the truth there.
    std::vector<std::uint8_t> truth = TraceTruth(lightSpace);
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!frame_.Covered(i)) continue;
        const bool counted =
            glm::dot(frame_.wsNormal[i], lightSpace.DirectionToLight(frame_.wsPosition[i])) > 0.0;
        out.receiverPixels += counted;
        out.truthShadowed += counted && truth[i];
    }

    if (options.mapTruth) {
        const Resolution size{options.truthMapSize, options.truthMapSize};
        // The focused matrix is fitted for the case's map; scale its texels to the truth map's.
        glm::dmat3 toTruth(1.0);
        toTruth[0][0] = static_cast<double>(size.width) / scene_.shadowMap.width;
        toTruth[1][1] = static_cast<double>(size.height) / scene_.shadowMap.height;
        const ShadowMap truthMap =
            backend_.RenderShadowMap(lightSpace, focused.ThenAffine(toTruth), size);
        out.mapTruthDisagree =
            CountWrong(backend_.ShadePixels(frame_, lightSpace, truthMap), truth, nullptr);
    }

    // Which samples the light grazes (projection aliasing, evaluation.h).
    std::vector<std::uint8_t> grazing(out.samples.lsX.size(), 0);
    for (std::size_t s = 0; s < grazing.size(); ++s) {
        const std::size_t pixel = out.samples.pixel[s];
        const glm::dvec3& wsPoint = readback_.buffer.wsPosition[pixel];
        grazing[s] = std::abs(glm::dot(readback_.buffer.wsNormal[pixel],
                                       lightSpace.DirectionToLight(wsPoint))) < kGrazingCos;
    }

    for (const std::string& method : options.methods) {
        MethodOutcome m;
        m.method = method;
        const Stopwatch timer;
        const MethodMatrix computed = ComputeLightMatrix(method, context);
        m.ms = timer.Ms();
        m.matrix = computed.matrix;
        if (computed.optimizer) {
            m.hAfterIteration = computed.optimizer->hAfterIteration;
            m.hBeforeRefine = computed.optimizer->hBeforeRefine;
        }
        m.winner = computed.winner;
        ShadowMap map = backend_.RenderShadowMap(lightSpace, m.matrix, scene_.shadowMap);
        std::vector<Shade> shades = backend_.ShadePixels(frame_, lightSpace, map);
        m.misclassified = CountWrong(shades, truth, &m.falseShadow);
        m.h = Energy(m.matrix, out.samples);
        for (std::size_t s = 0; s < grazing.size(); ++s)
            if (grazing[s])
                m.hGrazing += SampleBadness(m.matrix, out.samples.lsX[s], out.samples.dXdx1[s],
                                            out.samples.dXdx2[s]);
        if (options.keepBuffers) {
            m.shades = std::move(shades);
            m.map = std::move(map);
        }
        out.methods.push_back(std::move(m));
    }
    if (options.keepBuffers) out.truth = std::move(truth);
    return out;
}

}  // namespace lexel::spatial
