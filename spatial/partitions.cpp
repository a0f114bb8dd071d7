// Partitioned light matrices (partitions.h).
#include "lexel/spatial/partitions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lexel/solvers/convex_hull_3d.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/geometry.h"
#include "lexel/spatial/baseline_support.h"
#include "lexel/spatial/multi_start.h"

namespace lexel::spatial {

using baseline_detail::ToLightAll;

namespace {

// The k + 1 split depths of the z-partitioning schemes.
std::vector<double> Splits(PartitionScheme scheme, const BaselineContext& context, int k,
                           double lambda) {
    const Camera& camera = context.camera;
    if (scheme == PartitionScheme::kPssm)
        return PssmSplits(camera.nearPlane, camera.farPlane, k, lambda);
    if (scheme == PartitionScheme::kZpLispsm)
        return PssmSplits(camera.nearPlane, camera.farPlane, k, 1.0);
    // SDSM: logarithmic over the visible range (Lauritzen §3), the farthest point included.
    double zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
    for (const glm::dvec3& x : context.wsRelevant) {
        const double z = PlanarEyeDepth(camera, x);
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
    }
    zMin = std::max(zMin, camera.nearPlane);
    zMax = std::max(zMax, zMin * (1.0 + 1e-9));
    std::vector<double> splits = PssmSplits(zMin, zMax, k, 1.0);
    // The outer cascades reach the camera's near and far planes: a frame pixel nearer or farther
    // than every readback sample (the frame is finer than the readback) is served by the nearest
    // partition, as SDSM clamps to its first and last (Lauritzen §4).
    splits.front() = camera.nearPlane;
    splits.back() =
        std::max(camera.farPlane, std::nextafter(zMax, std::numeric_limits<double>::infinity()));
    return splits;
}

// Face partitioning's wedges (§5.1): the view frustum cut by the planes through the eye that
// contain a side edge and the light direction. Each wedge between two adjacent projected edges
// (less than 180° wide) is a cascade limited to it by two half-spaces; `bisectors` gets each
// wedge's view direction, the sum of its two unit edge directions.
std::vector<Cascade> FaceWedges(const BaselineContext& context,
                                std::vector<glm::dvec3>* bisectors) {
    const LightSpace& ls = *context.lightSpace;
    const glm::dvec3 eye = context.camera.position;
    const glm::dvec3 light = ls.IsPoint()
                                 ? glm::normalize(context.wsBounds.Center() - ls.light().position)
                                 : ls.light().direction;
    glm::dvec3 g1, g2;
    PlaneBasis(light, &g1, &g2);
    const auto corners = context.camera.FrustumCorners();
    struct Edge {
        glm::dvec3 ray, across;  // unit 3D edge direction; its part ⊥ the light
        double angle;
    };
    std::vector<Edge> edges;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 ray = glm::normalize(corners[i + 4] - corners[i]);
        const glm::dvec3 across = ray - glm::dot(ray, light) * light;
        edges.push_back({ray, across, std::atan2(glm::dot(g2, across), glm::dot(g1, across))});
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& a, const Edge& b) { return a.angle < b.angle; });
    std::vector<Cascade> wedges;
    for (std::size_t j = 0; j < edges.size(); ++j) {
        const Edge& a = edges[j];
        const Edge& b = edges[(j + 1) % edges.size()];
        const double span =
            std::remainder(b.angle - a.angle - std::numbers::pi, 2.0 * std::numbers::pi) +
            std::numbers::pi;
        if (!(span > 1e-9 && span < std::numbers::pi - 1e-9)) continue;  // reflex or degenerate
        // n·x + d ≥ 0 on b's side of the plane through the eye, a's edge and the light.
        const auto halfSpace = [&](const Edge& on, const Edge& toward) {
            glm::dvec3 n = glm::cross(light, on.across);
            if (glm::dot(n, toward.across) < 0.0) n = -n;
            return glm::dvec4(n, -glm::dot(n, eye));
        };
        Cascade wedge;
        wedge.wsHalfSpaces = {halfSpace(a, b), halfSpace(b, a)};
        wedges.push_back(wedge);
        bisectors->push_back(a.ray + b.ray);
    }
    return wedges;
}

// The camera axis in the map plane of axis p4, for SDSM's box (camera X when it looks along p4).
glm::dvec2 CameraAxisInPlane(const BaselineContext& context, const glm::dvec3& p4) {
    const LightSpace& ls = *context.lightSpace;
    const Camera& camera = context.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    glm::dvec3 b1, b2;
    PlaneBasis(p4, &b1, &b2);
    for (const glm::dvec3& ws : {forward, right}) {
        const glm::dvec3 lsDir = ls.LsFromWsLinear() * ws;
        const glm::dvec2 inPlane(glm::dot(b1, lsDir), glm::dot(b2, lsDir));
        if (glm::length(inPlane) > 1e-6 * glm::length(lsDir)) return glm::normalize(inPlane);
    }
    return {1.0, 0.0};
}

LightMatrix SdsmBox(const BaselineContext& context, bool snap) {
    const LightSpace& ls = *context.lightSpace;
    const glm::dvec3 p4 = InitialLightAxis(ls, context.wsBounds, context.wsRelevant);
    FitOptions options;
    options.margin = context.margin;
    // A directional light's plane coordinates are world units over the frame's s: snap to
    // power-of-two multiples of one world unit.
    if (snap && !ls.IsPoint()) options.snapUnit = 1.0 / ls.ToLight(glm::dvec3(0.0)).z;
    // The box of the points is the box of their hull's vertices.
    const std::span<const glm::dvec3> wsFit =
        context.wsRelevantHull.empty() ? context.wsRelevant : context.wsRelevantHull;
    const auto m = FitMapBoxToPoints(p4, CameraAxisInPlane(context, p4), ToLightAll(ls, wsFit),
                                     context.map, options);
    if (!m) throw DomainError(Subject::kLight, "sdsm: a visible point is behind the light's plane");
    return *m;
}

// One partition's map at the context's resolution, for its points and samples.
LightMatrix FitPartition(PartitionScheme scheme, const BaselineContext& part,
                         const LightSamples& partSamples, const PartitionOptions& options) {
    switch (scheme) {
        case PartitionScheme::kPssm:
        case PartitionScheme::kSdsmRect:
            return FocusedTightLightMatrix(part);
        case PartitionScheme::kSdsm:
            return SdsmBox(part, options.snap);
        case PartitionScheme::kZpLispsm:
        case PartitionScheme::kFpLispsm:
            return LispsmTightLightMatrix(part);
        case PartitionScheme::kSdsmOptimal: {
            std::vector<OptimizerStart> starts = {{"sdsm", SdsmBox(part, false)}};
            for (OptimizerStart& s : StandardStarts(part)) starts.push_back(std::move(s));
            OptimizerOptions optimizer;
            optimizer.energy = options.energy;
            optimizer.maxSamples = options.maxSamples;
            return OptimizeFromStarts(partSamples, starts, part.map, optimizer).result.matrix;
        }
    }
    throw std::invalid_argument("unknown partition scheme");
}

// The vertices of the points' 3D convex hull (all of them when there are fewer than 4).
std::vector<glm::dvec3> HullVertices(std::span<const glm::dvec3> wsPoints) {
    std::vector<Eigen::Vector3d> points;
    points.reserve(wsPoints.size());
    for (const glm::dvec3& p : wsPoints) points.emplace_back(p.x, p.y, p.z);
    std::vector<glm::dvec3> vertices;
    for (std::size_t k : ConvexHullVertices3D(points)) vertices.push_back(wsPoints[k]);
    return vertices;
}

}  // namespace

LightSamples SamplesOfCascade(const LightSamples& samples, std::span<const glm::dvec3> wsRelevant,
                              const Camera& camera, std::span<const Cascade> cascades,
                              std::size_t cascade) {
    const auto serves = [&](const glm::dvec3& ws) {
        return CascadeFor(cascades, PlanarEyeDepth(camera, ws), ws) == cascade;
    };
    LightSamples out;
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        if (!serves(samples.wsX[s])) continue;
        out.lsX.push_back(samples.lsX[s]);
        out.dXdx1.push_back(samples.dXdx1[s]);
        out.dXdx2.push_back(samples.dXdx2[s]);
        out.pixel.push_back(samples.pixel[s]);
        out.wsX.push_back(samples.wsX[s]);
        if (samples.edgeNormal.size() == samples.lsX.size())
            out.edgeNormal.push_back(samples.edgeNormal[s]);
    }
    for (std::size_t k = 0; k < samples.wsPrior.size(); ++k) {
        if (!serves(samples.wsPrior[k])) continue;
        out.lsPrior.push_back(samples.lsPrior[k]);
        out.priorDXdx1.push_back(samples.priorDXdx1[k]);
        out.priorDXdx2.push_back(samples.priorDXdx2[k]);
        out.wsPrior.push_back(samples.wsPrior[k]);
    }
    for (std::size_t i = 0; i < wsRelevant.size() && i < samples.lsRelevant.size(); ++i)
        if (serves(wsRelevant[i])) out.lsRelevant.push_back(samples.lsRelevant[i]);
    out.boundaryPixels = out.lsX.size();
    return out;
}

double PartitionedEnergy(std::span<const Cascade> cascades, const LightSamples& samples,
                         std::span<const glm::dvec3> wsRelevant, const Camera& camera) {
    return PartitionedEnergy(cascades, samples, wsRelevant, camera, EnergyOptions{});
}

double PartitionedEnergy(std::span<const Cascade> cascades, const LightSamples& samples,
                         std::span<const glm::dvec3> wsRelevant, const Camera& camera,
                         const EnergyOptions& energy) {
    double total = 0.0;
    for (std::size_t i = 0; i < cascades.size(); ++i)
        total += Energy(cascades[i].matrix,
                        SamplesOfCascade(samples, wsRelevant, camera, cascades, i), energy);
    return total;
}

std::vector<Cascade> PartitionedLightMatrices(PartitionScheme scheme,
                                              const BaselineContext& context,
                                              const LightSamples& samples,
                                              const PartitionOptions& options) {
    if (options.count < 1 || options.count > kMaxCascades)
        throw std::invalid_argument("partitions: count must be in [1, kMaxCascades]");
    std::vector<Cascade> cascades;
    std::vector<glm::dvec3> bisectors;
    if (scheme == PartitionScheme::kFpLispsm) {
        cascades = FaceWedges(context, &bisectors);
    } else {
        const std::vector<double> splits = Splits(scheme, context, options.count, options.lambda);
        for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
            Cascade c;
            c.zNear = splits[i];
            c.zFar = splits[i + 1];
            cascades.push_back(c);
        }
    }
    if (cascades.empty()) throw DomainError(Subject::kLight, "fp-lispsm: no face wedge");
    const Resolution equal =
        AllocateCascadeMaps(context.map, std::vector<double>(cascades.size(), 1.0),
                            CascadeAllocation::kEqual)
            .front();
    std::vector<double> costs(cascades.size(), 0.0);
    const double exponent = EnergyExponent(options.energy);
    for (std::size_t i = 0; i < cascades.size(); ++i) {
        std::vector<glm::dvec3> wsPoints;
        for (const glm::dvec3& x : context.wsRelevant)
            if (CascadeFor(cascades, PlanarEyeDepth(context.camera, x), x) == i)
                wsPoints.push_back(x);
        LightSamples partSamples =
            SamplesOfCascade(samples, context.wsRelevant, context.camera, cascades, i);
        // Algorithm 1's searches need only the partition's hull vertices (as the single maps use
        // the frame's; optimizer.h): the same maps at a fraction of the cost. The one-shot fits
        // of the other schemes are cheaper over the points than Qhull.
        const std::vector<glm::dvec3> wsHull = scheme == PartitionScheme::kSdsmOptimal
                                                   ? HullVertices(wsPoints)
                                                   : std::vector<glm::dvec3>{};
        partSamples.lsRelevantHull = ToLightAll(*context.lightSpace, wsHull);
        BaselineContext part = context;
        part.map = equal;
        part.wsRelevantHull = wsHull;
        part.samples = &partSamples;
        Cascade& c = cascades[i];
        c.map = equal;
        c.visiblePoints = wsPoints.size();
        if (wsPoints.empty()) {  // an empty partition keeps a valid map of the whole view
            part.wsRelevant = context.wsRelevant;
            part.wsRelevantHull = context.wsRelevantHull;
            c.matrix = FocusedTightLightMatrix(part);
            continue;
        }
        part.wsRelevant = wsPoints;
        if (scheme == PartitionScheme::kFpLispsm)
            part.camera.target = part.camera.position + bisectors[i];
        c.matrix = FitPartition(scheme, part, partSamples, options);
        costs[i] = Energy(c.matrix, partSamples, options.energy) *
                   std::pow(static_cast<double>(equal.Count()), exponent);
    }
    if (options.allocation == CascadeAllocation::kLagrange) {
        for (double& c : costs)
            if (!std::isfinite(c)) c = 0.0;  // no usable energy: it keeps the least texels
        const std::vector<Resolution> maps =
            AllocateCascadeMaps(context.map, costs, CascadeAllocation::kLagrange, exponent);
        for (std::size_t i = 0; i < cascades.size(); ++i) {
            cascades[i].matrix = RescaleMap(cascades[i].matrix, equal, maps[i]);
            cascades[i].map = maps[i];
        }
    }
    return cascades;
}

}  // namespace lexel::spatial
