#include "lexel/spatial/harness/ray_cast_map.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/ray_caster.h"
#include "lexel/spatial/perspective_aliasing.h"

namespace lexel::spatial {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Whether the warp is the plain matrix (no warp, no phase).
bool IsPlainMatrix(const MapWarp& warp) { return warp.IsLinear() && warp.phase == glm::dvec2(0.0); }

}  // namespace

RayCastMapper::RayCastMapper(const TriangleMesh& mesh, const RayCaster& caster) : caster_(caster) {
    planes_.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < planes_.size(); ++t) {
        const glm::dvec3 n = mesh.FaceNormal(t);
        planes_[t] = glm::dvec4(n, glm::dot(n, mesh.positions[mesh.triangles[t][0]]));
    }
}

ShadowMap RayCastMapper::Render(const LightSpace& lightSpace, const MapWarp& warp,
                                Resolution resolution) const {
    if (resolution.width < 1 || resolution.height < 1)
        throw std::invalid_argument("RayCastMapper::Render: an empty map");
    const std::size_t count = resolution.Count();
    // Each texel's ray: origin and unit direction in world, depth 0 at the origin
    // (LightSpace::Ray).
    std::vector<glm::dvec3> origins(count), directions(count);
    std::vector<ShadowRay> rays(count);
    tbb::parallel_for(0, resolution.height, [&](int y) {
        for (int x = 0; x < resolution.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * resolution.width + x;
            lightSpace.Ray(warp.Inverse(glm::dvec2(x + 0.5, y + 0.5)), &origins[i], &directions[i]);
            rays[i] = caster_.ToShadowRay(origins[i], directions[i], 0.0, kInf);
        }
    });
    std::vector<std::int32_t> hit(count, -1);
    caster_.IntersectBatch(rays, hit);

    ShadowMap map;
    map.resolution = resolution;
    map.matrix = warp.base;
    if (!IsPlainMatrix(warp)) map.warp = warp;
    map.depth.assign(count, std::numeric_limits<float>::infinity());
    tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) {
        if (hit[i] < 0) return;
        const glm::dvec4& plane = planes_[static_cast<std::size_t>(hit[i])];
        const double facing = glm::dot(glm::dvec3(plane), directions[i]);
        // The ray lies in the triangle's plane (it grazes the hit edge): Embree's own t.
        double depth = kInf;
        if (facing != 0.0) depth = (plane.w - glm::dot(glm::dvec3(plane), origins[i])) / facing;
        if (!(depth > 0.0) || !std::isfinite(depth)) {
            const auto h = caster_.Intersect(origins[i], directions[i], 0.0, kInf);
            depth = h ? h->t : kInf;
        }
        map.depth[i] = static_cast<float>(depth);
    });
    return map;
}

std::optional<glm::dvec2> MapCoordinates(const ShadowMap& map, const glm::dvec3& lsX) {
    if (map.warp) return map.warp->Forward(lsX);
    if (!InFront(map.matrix.p4, lsX)) return std::nullopt;
    return map.matrix.Map(lsX);
}

bool MapJacobianAt(const ShadowMap& map, const glm::dvec3& lsX, glm::dvec3* du1dX,
                   glm::dvec3* du2dX) {
    if (map.warp) return map.warp->Jacobian(lsX, du1dX, du2dX);
    if (!InFront(map.matrix.p4, lsX)) return false;
    map.matrix.MapJacobian(lsX, du1dX, du2dX);
    return true;
}

double MapSampleBadness(const ShadowMap& map, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                        const glm::dvec3& dXdx2, Badness badness) {
    if (map.warp) return WarpSampleBadness(*map.warp, lsX, dXdx1, dXdx2, badness);
    return SampleBadness(map.matrix, lsX, dXdx1, dXdx2, badness);
}

Shade ShadeWarpedPoint(const LightSpace& lightSpace, const ShadowMap& map,
                       const glm::dvec3& wsPoint, const glm::dvec3& wsNormal) {
    if (!(glm::dot(wsNormal, lightSpace.DirectionToLight(wsPoint)) > 0.0))
        return Shade::kFacingAway;
    const MapWarp warp = map.warp ? *map.warp : MapWarp::Linear(map.matrix);
    const auto u = warp.Forward(lightSpace.ToLight(wsPoint));
    if (!u) return Shade::kLit;
    if (!(u->x >= 0.0 && u->y >= 0.0 && u->x < map.resolution.width &&
          u->y < map.resolution.height))
        return Shade::kLit;
    const int tx = static_cast<int>(u->x), ty = static_cast<int>(u->y);
    const float stored = map.depth[static_cast<std::size_t>(ty) * map.resolution.width + tx];
    if (std::isinf(stored)) return Shade::kLit;
    const glm::dvec3 lsTexelCentre = warp.Inverse(glm::dvec2(tx + 0.5, ty + 0.5));
    return CompareWithTexel(stored,
                            ReceiverPlaneDepth(lightSpace, lsTexelCentre, wsPoint, wsNormal));
}

std::vector<Shade> ShadeWarpedPixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                     const ShadowMap& map) {
    std::vector<Shade> shades(frame.resolution.Count(), Shade::kEmpty);
    tbb::parallel_for(std::size_t(0), shades.size(), [&](std::size_t i) {
        if (frame.Covered(i))
            shades[i] = ShadeWarpedPoint(lightSpace, map, frame.wsPosition[i], frame.wsNormal[i]);
    });
    return shades;
}

// Lloyd 2006 eq. 1's factor (perspective_aliasing.h) of the warp's rows at the point.
double WarpPerspectiveAliasing(const Camera& camera, const LightSpace& lightSpace,
                               const MapWarp& warp, const glm::dvec3& wsPoint) {
    const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
    glm::dvec3 du1dX, du2dX;
    if (!warp.Jacobian(lsX, &du1dX, &du2dX)) return kInf;
    return PerspectiveAliasingOfRows(camera, lightSpace, du1dX, du2dX, wsPoint);
}

}  // namespace lexel::spatial
