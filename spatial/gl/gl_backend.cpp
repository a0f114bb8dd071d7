#include "lexel/spatial/gl/gl_backend.h"

#include "lexel/spatial/gl/gl_renderer.h"
#include "lexel/spatial/gl/visibility.h"
#include "lexel/spatial/harness/ray_cast_map.h"

namespace lexel::spatial::gl {

namespace {

class GlBackend final : public RenderBackend {
  public:
    explicit GlBackend(const TriangleMesh& geometry)
        : geometry_(geometry), renderer_(std::make_unique<GlRenderer>(geometry_)) {}

    std::string_view Name() const override { return "gl"; }

    CameraBuffer RenderCamera(const Camera& camera, Resolution resolution) const override {
        std::vector<std::int32_t> triangles;
        {
            const CurrentContext current(renderer_->context());
            renderer_->RenderCamera(CameraSlot::kFrame, camera, resolution);
            triangles = renderer_->ReadTriangles(CameraSlot::kFrame);
        }
        return CameraBufferFromTriangles(geometry_, camera, resolution, triangles);
    }

    ShadowMap RenderShadowMap(const LightSpace& lightSpace, const LightMatrix& matrix,
                              Resolution resolution) const override {
        const CurrentContext current(renderer_->context());
        renderer_->RenderShadowMap(0, lightSpace, matrix, resolution);
        return renderer_->ReadShadowMap(0);
    }

    // RTW's piecewise-linear warps by the vertex warp of tessellated geometry; LogPSM's
    // logarithm is no vertex warp: nullopt, and the harness ray-casts its map.
    std::optional<ShadowMap> RenderWarpedShadowMap(const LightSpace& lightSpace,
                                                   const MapWarp& warp,
                                                   Resolution resolution) const override {
        if (warp.x.kind() == AxisWarp::Kind::kLogarithmic ||
            warp.y.kind() == AxisWarp::Kind::kLogarithmic)
            return std::nullopt;
        const CurrentContext current(renderer_->context());
        renderer_->RenderWarpedShadowMap(0, lightSpace, warp, resolution);
        return renderer_->ReadShadowMap(0);
    }

    std::vector<Shade> ShadePixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                   const ShadowMap& map) const override {
        // A warped map is shaded on the CPU (ray_cast_map.h): the GPU pass maps through a matrix.
        if (map.warp) return ShadeWarpedPixels(frame, lightSpace, map);
        const CurrentContext current(renderer_->context());
        renderer_->UploadCamera(CameraSlot::kFrame, frame);
        renderer_->UploadShadowMap(0, map);
        renderer_->ShadePass(CameraSlot::kFrame, 0, lightSpace);
        return renderer_->ReadShades(CameraSlot::kFrame);
    }

    LightSamples BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                 const ShadowMap& map) const override {
        std::vector<std::uint32_t> pixels;
        std::vector<Shade> shades;
        {
            const CurrentContext current(renderer_->context());
            renderer_->UploadCamera(CameraSlot::kReadback, readback.buffer);
            renderer_->UploadShadowMap(0, map);
            renderer_->ShadePass(CameraSlot::kReadback, 0, lightSpace);
            pixels = renderer_->BoundaryPixels(CameraSlot::kReadback);
            // The decisions too (one byte a pixel): the edge normals and the prior's points
            // (samples.h) come from them, as MakeLightSamples' do.
            shades = renderer_->ReadShades(CameraSlot::kReadback);
        }
        return LightSamplesAtPixels(readback, lightSpace, pixels, shades);
    }

  private:
    TriangleMesh geometry_;  // a copy: the backend owns what it draws
    std::unique_ptr<GlRenderer> renderer_;
};

}  // namespace

std::unique_ptr<RenderBackend> MakeGlBackend(const TriangleMesh& geometry) {
    return std::make_unique<GlBackend>(geometry);
}

}  // namespace lexel::spatial::gl
