// Pictures of the 3D experiment, for people rather than tables: the frame with each method's
// shadows, where it disagrees with the ground truth, and the shadow map with the optimization
// samples drawn in it (report Fig. 2).
#pragma once

#include <cstdint>
#include <span>

#include "lexel/spatial/harness/image_io.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// Lambert-shaded grey frame; shadowed and facing-away pixels get only the ambient term.
Image FrameImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                 std::span<const Shade> shades);

// The frame in grey with the method's errors against `truth` (1 = shadowed): red where the method
// shadows a lit pixel, blue where it lights a shadowed one.
Image MisclassificationImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                             std::span<const Shade> shades, std::span<const std::uint8_t> truth);

// The shadow map's depth (near light, far dark; empty texels dark blue) with the visible receiver
// points in green and the boundary samples in red, as the report's Fig. 2.
Image ShadowMapImage(const ShadowMap& map, const LightSamples& samples);

}  // namespace lexel::spatial
