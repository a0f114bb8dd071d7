// The frame shaded through a virtual shadow map (spatial/virtual_shadow_map.h): each resident
// page rendered as a P × P shadow map of its own through the backend (the same shadow pass as
// every other map, on the CPU or the GPU), and each frame pixel shaded against the page that
// serves it (VirtualShadowMap::ServingPage: its footprint's level, else coarser; none: uncovered,
// shaded lit as ShadePoint does outside a map). Only the pixels a page serves are shaded against
// it, as a compact buffer, so a frame costs one shading of its pixels whatever the page count.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lexel/spatial/harness/render_backend.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/virtual_shadow_map.h"

namespace lexel::spatial {

// At most this many resident pages: the per-pixel page index is a byte. The pool never holds more
// (P is the largest power of two leaving at least 64 pages, so fewer than 256 remain).
inline constexpr std::size_t kMaxShadedPages = 255;

struct PageShading {
    std::vector<Shade> shades;  // per frame pixel (kEmpty where nothing is seen)
    // Per resident page, in VirtualShadowMap::resident order (one empty page when none is).
    std::vector<ShadowMap> maps;
    std::vector<std::uint8_t> page;  // per pixel: the serving page's index (0 where none)
    // Per pixel: 1 where a counted pixel (covered, facing the light) has no serving page.
    std::vector<std::uint8_t> outside;
    std::vector<std::int8_t> level;  // per pixel: the serving page's level (0 where none)
};

// std::invalid_argument when the map has more than kMaxShadedPages resident pages.
PageShading ShadeThroughPages(const RenderBackend& backend, const CameraBuffer& frame,
                              const LightSpace& lightSpace, const Camera& camera,
                              const VirtualShadowMap& vsm);

// h (eq. 6) of a virtual shadow map: each sample's badness under the page serving its world
// point (samples no page serves add nothing: they are shaded lit, outside every map); *grazing
// (optional) gets the part from samples with grazing[s] set.
double PageEnergy(const VirtualShadowMap& vsm, const Camera& camera, const LightSpace& lightSpace,
                  const LightSamples& samples, std::span<const std::uint8_t> grazing,
                  double* grazingPart = nullptr);

// The physical pool as one image-sized map: the resident pages' depths tiled row by row in
// resident order (for pictures; its matrix maps nothing).
ShadowMap PoolAtlas(std::span<const ShadowMap> pages, int pageTexels);

}  // namespace lexel::spatial
