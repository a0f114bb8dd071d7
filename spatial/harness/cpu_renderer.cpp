// The CPU reference backend of render_backend.h: the rasterizer of raster.h with exact world
// points, plus the shared shadow decision ShadePoint.
#include <tbb/parallel_for.h>

#include <cmath>

#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/harness/raster.h"
#include "lexel/spatial/harness/ray_cast_map.h"
#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial {

ImageFromWorld ImageRows(const glm::dmat4& m) {
    ImageFromWorld rows;
    for (int c = 0; c < 4; ++c) rows[c] = glm::dvec3(m[c][0], m[c][1], m[c][3]);
    return rows;
}

RasterBuffer MakeRasterBuffer(Resolution resolution) {
    RasterBuffer b;
    b.resolution = resolution;
    b.depth.assign(resolution.Count(), std::numeric_limits<double>::infinity());
    b.triangle.assign(resolution.Count(), -1);
    b.wsPoint.assign(resolution.Count(), glm::dvec3(0.0));
    return b;
}

namespace {

// ShadePoint with M⁻¹ = (rows p1, p2, p4)⁻¹ given, so a pass inverts it once, not per pixel.
Shade ShadeWithInverse(const LightSpace& lightSpace, const ShadowMap& map,
                       const glm::dmat3& lsFromMap, const glm::dvec3& wsPoint,
                       const glm::dvec3& wsNormal) {
    if (map.warp) return ShadeWarpedPoint(lightSpace, map, wsPoint, wsNormal);
    if (!(glm::dot(wsNormal, lightSpace.DirectionToLight(wsPoint)) > 0.0))
        return Shade::kFacingAway;
    const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
    if (!InFront(map.matrix.p4, lsX)) return Shade::kLit;
    const glm::dvec2 u = map.matrix.Map(lsX);
    if (!(u.x >= 0.0 && u.y >= 0.0 && u.x < map.resolution.width && u.y < map.resolution.height))
        return Shade::kLit;
    const int tx = static_cast<int>(u.x), ty = static_cast<int>(u.y);
    const float stored = map.depth[static_cast<std::size_t>(ty) * map.resolution.width + tx];
    if (std::isinf(stored)) return Shade::kLit;

    const glm::dvec3 lsTexelCentre = lsFromMap * glm::dvec3(tx + 0.5, ty + 0.5, 1.0);
    return CompareWithTexel(stored,
                            ReceiverPlaneDepth(lightSpace, lsTexelCentre, wsPoint, wsNormal));
}

}  // namespace

Shade ShadePoint(const LightSpace& lightSpace, const ShadowMap& map, const glm::dvec3& wsPoint,
                 const glm::dvec3& wsNormal) {
    return ShadeWithInverse(lightSpace, map, glm::inverse(map.matrix.Rows()), wsPoint, wsNormal);
}

namespace {

class CpuRenderer final : public RenderBackend {
  public:
    explicit CpuRenderer(const TriangleMesh& geometry) : geometry_(geometry) {
        // A scene of one point (radius 0) covers no pixel: any positive length serves it.
        const double radius = geometry.ComputeBounds().Radius();
        sceneRadius_ = radius > 0.0 && std::isfinite(radius) ? radius : 1.0;
        normals_.resize(geometry.triangles.size());
        for (std::size_t t = 0; t < normals_.size(); ++t) normals_[t] = geometry.FaceNormal(t);
    }

    std::string_view Name() const override { return "cpu"; }

    CameraBuffer RenderCamera(const Camera& camera, Resolution resolution) const override {
        // Q·[x; 1] = Q_eye·[x - eye; 1], with Q_eye the same camera moved to the origin: the
        // same map, without the large translation whose cancellation would cost the window depth
        // its digits far from the origin (the readback's smoothness test needs ~1e-12).
        Camera eyeCentred = camera;
        eyeCentred.target = camera.target - camera.position;
        eyeCentred.position = glm::dvec3(0.0);
        const glm::dmat4 screenFromEye = eyeCentred.ScreenFromWorld(resolution);
        const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
        RasterBuffer raster = MakeRasterBuffer(resolution);
        // Depth key: distance along the view axis (= clip w); beyond the far plane is not seen.
        // The raster's points are eye-relative (world axes, origin at the eye).
        const auto viewDepth = [&](const glm::dvec3& eyeRelative) {
            const double z = glm::dot(forward, eyeRelative);
            return z <= camera.farPlane ? z : std::numeric_limits<double>::infinity();
        };
        RasterizeNearest(geometry_, ImageRows(screenFromEye), camera.nearPlane, viewDepth, &raster,
                         camera.position);

        CameraBuffer out;
        out.resolution = resolution;
        out.windowDepth.assign(resolution.Count(), 1.0);
        out.wsPosition = std::move(raster.wsPoint);
        out.wsNormal.assign(resolution.Count(), glm::dvec3(0.0));
        out.triangle = std::move(raster.triangle);
        tbb::parallel_for(std::size_t(0), resolution.Count(), [&](std::size_t i) {
            if (out.triangle[i] < 0) return;
            // The window depth is a function of the view depth alone (the projection's depth row
            // involves only z and w), so it comes from the eye-relative depth key, whose rounding
            // is relative to the distance from the eye, not from the world's origin.
            const glm::dvec4 h = screenFromEye * glm::dvec4(raster.depth[i] * forward, 1.0);
            out.windowDepth[i] = h.z / h.w;
            const glm::dvec3& ws = out.wsPosition[i];
            glm::dvec3 n = normals_[out.triangle[i]];
            if (glm::dot(n, camera.position - ws) < 0.0) n = -n;
            out.wsNormal[i] = n;
        });
        return out;
    }

    ShadowMap RenderShadowMap(const LightSpace& lightSpace, const LightMatrix& matrix,
                              Resolution resolution) const override {
        const ImageFromWorld view = ImageRows(MapFromWorld(lightSpace, matrix));
        RasterBuffer raster = MakeRasterBuffer(resolution);
        const auto lightDepth = [&](const glm::dvec3& wsPoint) {
            return lightSpace.Depth(wsPoint);
        };
        // w = p4·X is a length; 1e-9 scene radii keeps clipped vertices finite.
        RasterizeNearest(geometry_, view, 1e-9 * sceneRadius_, lightDepth, &raster);

        ShadowMap map;
        map.resolution = resolution;
        map.matrix = matrix;
        map.depth.resize(resolution.Count());
        for (std::size_t i = 0; i < map.depth.size(); ++i)
            map.depth[i] = static_cast<float>(raster.depth[i]);
        return map;
    }

    std::vector<Shade> ShadePixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                   const ShadowMap& map) const override {
        std::vector<Shade> shades(frame.resolution.Count(), Shade::kEmpty);
        const glm::dmat3 lsFromMap = glm::inverse(map.matrix.Rows());
        tbb::parallel_for(std::size_t(0), shades.size(), [&](std::size_t i) {
            if (frame.Covered(i))
                shades[i] = ShadeWithInverse(lightSpace, map, lsFromMap, frame.wsPosition[i],
                                             frame.wsNormal[i]);
        });
        return shades;
    }

  private:
    TriangleMesh geometry_;  // a copy: the backend owns what it draws, as a GPU backend would
    std::vector<glm::dvec3> normals_;
    double sceneRadius_ = 1.0;
};

}  // namespace

std::unique_ptr<RenderBackend> MakeCpuRenderer(const TriangleMesh& geometry) {
    return std::make_unique<CpuRenderer>(geometry);
}

}  // namespace lexel::spatial
