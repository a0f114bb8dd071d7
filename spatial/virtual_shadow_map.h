// Virtual shadow maps (Unreal Engine 5; M. Sakmary, J. Ryan, J. Hall, A. Lustri, "Virtual Shadow
// Maps", GPU Zen 3, 2024, ch. 12): a very large virtual shadow map per light, cut into pages of
// P × P texels of which only those the frame needs are backed by a fixed pool of physical pages.
//
// lexel's version, at the same physical budget as one single map:
//   - levels. Level ℓ has texels 2^ℓ times as wide as level 0's; level 0 is a 16384² virtual map
//     (kVirtualMapTexels, UE5's 16k) over the square around the scene bounds as the light sees
//     them, about the normal map's axis (baselines.h), in the plane p4·X = 1 (light_matrix.h) —
//     an orthographic square for a directional light, a frustum for a point light. Levels
//     ℓ = 1 … maxLevel are its mips, the last one page (UE5's local lights, which are mip-mapped;
//     lexel's point lights lie outside the scene bounds, so one frustum serves where UE5 uses six
//     cube faces). A directional light adds the clipmap's finer levels ℓ = −1 …
//     −kClipmapFinerLevels (GPU Zen 3 §12.2: concentric cascades, each twice the size of the one
//     before): 16384 texels a side centred on the camera, the window snapped to whole pages; levels
//     ℓ ≥ 0 are the clipmap's levels whose window holds the whole scene;
//   - the pool. P is the largest power of two for which the budget's texels hold at least
//     kMinPoolPages pages; the pool is ⌊budget / P²⌋ pages, so it never holds more texels than
//     the single map (400² texels: P = 32, 156 pages, 159,744 texels);
//   - requests. Each readback pixel that faces the light (n·l > 0; the others are in attached
//     shadow whatever a map holds, ShadePoint) asks for the level its footprint asks for — GPU
//     Zen 3 §12.2's first heuristic, level = ⌈log₂(T_w / T_c0)⌉ with T_w the pixel's world size and
//     T_c0 level 0's texel's: here ⌈−log₂ α₀ + b⌉ with α₀ = w_l/w_i of level 0 at the pixel
//     (PerspectiveAliasing, Lloyd 2006 eq. 1, the frame camera's pixels) and b the LOD bias — and
//     for the pages that level's texels put under the pixel's centre and the four corners of its
//     footprint on its plane (x ± ½ ∂W/∂x¹ ± ½ ∂W/∂x², the frame pixels it stands for: the
//     readback's margin). Every such pixel also asks for the coarsest level's page (UE5 marks
//     coarse pages so that something is resident everywhere);
//   - allocation. The most-requested pages are resident, at most the pool's count; the rest are
//     dropped. With fitPool (UE5's dynamic resolution: r.Shadow.Virtual.DynamicRes, which raises
//     the resolution LOD bias as the pool fills) the bias is the smallest b ≥ lodBias, to 1/64 of
//     a level, at which every requested page fits;
//   - shading. A point is served by the resident page at its own level (the same footprint rule
//     and bias), else by the first resident page covering it at a coarser level; uncovered if
//     none. Every page is a linear map of its own (PageMatrix): a P × P shadow map rendered as any
//     other.
#pragma once

#include <compare>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/readback.h"

namespace lexel::spatial {

inline constexpr int kVirtualMapTexels = 16384;  // a side of level 0 (and of a clipmap window)
inline constexpr int kMinPoolPages = 64;         // the fewest pages the pool is cut into
inline constexpr int kClipmapFinerLevels = 8;  // directional: levels −1 … −8 about the camera

// The page side P for a budget of `budget.Count()` texels: the largest power of two with
// ⌊texels / P²⌋ ≥ kMinPoolPages (1 when even P = 1 gives fewer pages: a budget under 64 texels),
// at most kVirtualMapTexels.
int VirtualPageTexels(Resolution budget);

struct PageKey {
    int level = 0;     // 2^level times level 0's texel width
    int x = 0, y = 0;  // the page's column and row in its level's texel grid (texels / P)
    auto operator<=>(const PageKey&) const = default;
};

// Where a light's virtual map lies and how it is paged.
struct VirtualMapLayout {
    glm::dvec3 p4{0.0, 0.0, 1.0};         // the image plane's axis (the normal map's)
    glm::dvec3 b1{1, 0, 0}, b2{0, 1, 0};  // PlaneBasis(p4): the plane's coordinates y
    glm::dvec2 centre{0.0};               // level 0 spans centre ± halfSize on both plane axes
    double halfSize = 1.0;                // plane units (> 0)
    int pageTexels = 1;                   // P
    int poolPages = 0;                    // ⌊budget / P²⌋
    int minLevel = 0, maxLevel = 0;       // maxLevel: level 0's square in one page
    bool clipmap = false;                 // directional: levels < 0 are windows about the camera
    glm::dvec2 cameraTexel{0.0};          // clipmap: the camera's point in level 0's texels
    // Every level's texel grid moved by this many of its own texels (a sub-texel phase, issue
    // 25's phase averaging): u' = u + phase on every level, page boundaries included.
    glm::dvec2 phase{0.0};

    // The map of level `level`'s texel grid: u = level 0's texels / 2^level (for ℓ ≥ 0 the
    // square fills [0, 16384 / 2^ℓ)²; for ℓ < 0 it extends past the window).
    LightMatrix LevelMatrix(int level) const;
    // The page's own P × P shadow map: its level's texels shifted by (x P, y P).
    LightMatrix PageMatrix(const PageKey& page) const;
    // The page of `level` under light-space point lsX: nullopt when lsX is not in front of p4, or
    // lies outside the level's square (ℓ ≥ 0) or window (ℓ < 0).
    std::optional<PageKey> PageAt(int level, const glm::dvec3& lsX) const;
};

// The layout for the context's light: the normal axis (ChooseNormalAxis), the square around the
// bounds corners' (or, where the normal axis sees only them, the visible points') projections,
// P and the pool from context.map's texels, the clipmap window about context.camera for a
// directional light. Throws as the baselines do.
VirtualMapLayout MakeVirtualMapLayout(const BaselineContext& context);

// −log₂ α₀ at a world point: the level whose texels are exactly as wide as the frame camera's
// pixel there (fractional); +inf or NaN free: nullopt where α₀ is not finite and positive.
std::optional<double> FootprintLevel(const VirtualMapLayout& layout, const Camera& camera,
                                     const LightSpace& lightSpace, const glm::dvec3& wsPoint);
// The integer level a point of footprint level L asks for under LOD bias b: ⌈L + b⌉, clamped to
// [minLevel, maxLevel].
int RequestedLevel(const VirtualMapLayout& layout, double footprintLevel, double lodBias);

struct VirtualMapOptions {
    double lodBias = 0.0;   // b: added to every footprint level (> 0: coarser)
    bool fitPool = true;    // raise b until every requested page fits the pool
    glm::dvec2 phase{0.0};  // VirtualMapLayout::phase: the grid's sub-texel phase (texels)
};

struct VirtualShadowMap {
    VirtualMapLayout layout;
    double lodBias = 0.0;                // the bias the requests were made with
    std::vector<PageKey> resident;       // the physical pages, most requested first
    std::vector<std::int64_t> requests;  // per resident page: readback pixels that asked for it
    std::int64_t requested = 0;          // distinct pages asked for
    std::int64_t dropped = 0;            // requested − resident
    std::int64_t droppedRequests = 0;    // the most requests of any dropped page (0: none)

    // The resident page serving a world point (index into `resident`): the page at its own level
    // (RequestedLevel of its FootprintLevel under lodBias), else the first resident one covering
    // it at a coarser level; nullopt when none does (uncovered). *level gets the serving level.
    std::optional<std::size_t> ServingPage(const Camera& camera, const LightSpace& lightSpace,
                                           const glm::dvec3& wsPoint, int* level = nullptr) const;

  private:
    friend VirtualShadowMap BuildVirtualShadowMap(const BaselineContext&, const Readback&,
                                                  const VirtualMapOptions&);
    std::vector<std::uint64_t> sortedKeys_;   // resident pages' keys, sorted
    std::vector<std::uint32_t> sortedIndex_;  // ... their index into `resident`
};

// The requests of the readback's pixels (the header comment), the bias (options), and the pool's
// pages. context.camera is the frame camera (its resolution sets the pixels' footprint);
// `readback` the one context.wsRelevant came from. Throws as the baselines do.
VirtualShadowMap BuildVirtualShadowMap(const BaselineContext& context, const Readback& readback,
                                       const VirtualMapOptions& options = {});

}  // namespace lexel::spatial
