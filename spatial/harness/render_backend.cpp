#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial {

Readback RenderReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution) {
    return MakeReadback(backend.RenderCamera(camera, resolution),
                        camera.ScreenFromWorld(resolution));
}

std::optional<ShadowMap> RenderBackend::RenderWarpedShadowMap(const LightSpace&, const MapWarp&,
                                                              Resolution) const {
    return std::nullopt;
}

LightSamples RenderBackend::BoundarySamples(const Readback& readback, const LightSpace& lightSpace,
                                            const ShadowMap& map) const {
    return MakeLightSamples(readback, lightSpace, ShadePixels(readback.buffer, lightSpace, map));
}

}  // namespace lexel::spatial
