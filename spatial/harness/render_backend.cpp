#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial {

Readback RenderReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution) {
    return MakeReadback(backend.RenderCamera(camera, resolution),
                        camera.ScreenFromWorld(resolution));
}

}  // namespace lexel::spatial
