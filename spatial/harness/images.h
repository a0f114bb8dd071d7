// Pictures of the 3D experiment, for people rather than tables: the frame with each method's
// shadows, where it disagrees with the ground truth, and the shadow map with the optimization
// samples drawn in it (report Fig. 2). The colours are named here so that a figure's key
// (cases/plot/image_figure.h) shows exactly the colours painted.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/image_io.h"
#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

struct ImageColour {
    float r, g, b;
};
inline constexpr ImageColour kSkyColour{0.55f, 0.65f, 0.8f};            // frame: no geometry
inline constexpr ImageColour kBackgroundColour{1.0f, 1.0f, 1.0f};       // error map: no geometry
inline constexpr ImageColour kFalseShadowColour{0.95f, 0.1f, 0.1f};     // lit pixel shadowed
inline constexpr ImageColour kFalseLightColour{0.1f, 0.3f, 0.95f};      // shadowed pixel lit
inline constexpr ImageColour kUncoveredColour{1.0f, 0.72f, 0.0f};       // counted, no map covers it
inline constexpr ImageColour kEmptyTexelColour{0.05f, 0.05f, 0.2f};     // map: nothing rendered
inline constexpr ImageColour kVisiblePointColour{0.2f, 0.75f, 0.25f};   // map: readback point
inline constexpr ImageColour kBoundarySampleColour{0.95f, 0.1f, 0.1f};  // map: boundary sample
inline constexpr float kAmbient = 0.15f;  // the grey of shadowed and facing-away pixels
// The shadow map's grey for linear light depth: kNearGrey at the nearest stored depth, kFarGrey
// at the farthest.
inline constexpr float kNearGrey = 0.9f, kFarGrey = 0.2f;

// Per frame pixel, 1 where a counted pixel (shade lit or shadowed) is uncovered as the evaluation
// counts it (MethodOutcome::uncovered): behind the serving map's plane or outside its texels, or,
// for cascades, outside every cascade's depth interval and half-spaces. The serving map is
// `matrix` at `map` texels (through `warp` when given: a warped map, map_warp.h), or with
// `cascades` the one CascadeFor picks by the pixel's planar eye depth for `camera`.
std::vector<std::uint8_t> UncoveredPixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                          const Camera& camera, std::span<const Shade> shades,
                                          const LightMatrix& matrix, Resolution map,
                                          std::span<const Cascade> cascades = {},
                                          const MapWarp* warp = nullptr);

// Lambert-shaded grey frame; shadowed and facing-away pixels get only the ambient term; pixels
// without geometry kSkyColour; `uncovered` pixels (optional, UncoveredPixels) kUncoveredColour.
Image FrameImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                 std::span<const Shade> shades, std::span<const std::uint8_t> uncovered = {});

// The frame in grey (darker where truly shadowed) with the method's errors against `truth` (1 =
// shadowed): kFalseShadowColour where the method shadows a lit pixel, kFalseLightColour where it
// lights a shadowed one; `uncovered` pixels (optional) kUncoveredColour over either.
Image MisclassificationImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                             std::span<const Shade> shades, std::span<const std::uint8_t> truth,
                             std::span<const std::uint8_t> uncovered = {});

// The smallest and largest finite depth of a map; `any` false when every texel is empty.
struct MapDepthRange {
    float nearest = 0.0f, farthest = 0.0f;
    bool any = false;
};
MapDepthRange DepthRangeOf(const ShadowMap& map);

// The shadow map's depth (kNearGrey at the nearest depth to kFarGrey at the farthest; empty
// texels kEmptyTexelColour) with the visible receiver points in kVisiblePointColour and the
// boundary samples in kBoundarySampleColour, as the report's Fig. 2.
Image ShadowMapImage(const ShadowMap& map, const LightSamples& samples);

}  // namespace lexel::spatial
