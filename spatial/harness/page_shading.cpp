#include "lexel/spatial/harness/page_shading.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace lexel::spatial {

namespace {

// The most frame pixels shaded against a page in one compact buffer.
constexpr std::size_t kChunkPixels = 1 << 16;

// The frame pixels in `pixels` as a camera buffer of their own, laid out in a near-square image
// (a GPU backend shades images no wider than its texture limit), the rest uncovered.
CameraBuffer CompactBuffer(const CameraBuffer& frame, std::span<const std::uint32_t> pixels) {
    const int width =
        std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(pixels.size())))));
    const int height = std::max(1, static_cast<int>((pixels.size() + width - 1) / width));
    CameraBuffer out;
    out.resolution = {width, height};
    const std::size_t n = out.resolution.Count();
    out.windowDepth.assign(n, 1.0);
    out.wsPosition.assign(n, glm::dvec3(0.0));
    out.wsNormal.assign(n, glm::dvec3(0.0));
    out.triangle.assign(n, -1);
    for (std::size_t k = 0; k < pixels.size(); ++k) {
        const std::size_t i = pixels[k];
        out.windowDepth[k] = frame.windowDepth[i];
        out.wsPosition[k] = frame.wsPosition[i];
        out.wsNormal[k] = frame.wsNormal[i];
        out.triangle[k] = frame.triangle[i];
    }
    return out;
}

}  // namespace

PageShading ShadeThroughPages(const RenderBackend& backend, const CameraBuffer& frame,
                              const LightSpace& lightSpace, const Camera& camera,
                              const VirtualShadowMap& vsm) {
    if (vsm.resident.size() > kMaxShadedPages)
        throw std::invalid_argument("ShadeThroughPages: " + std::to_string(vsm.resident.size()) +
                                    " resident pages, at most " + std::to_string(kMaxShadedPages));
    const std::size_t n = frame.triangle.size();
    PageShading out;
    out.shades.assign(n, Shade::kEmpty);
    out.page.assign(n, 0);
    out.outside.assign(n, 0);
    out.level.assign(n, 0);
    // Which page serves each covered pixel (kNone: none).
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> serving(n, kNone);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        if (!frame.Covered(i)) return;
        int level = 0;
        const std::optional<std::size_t> page =
            vsm.ServingPage(camera, lightSpace, frame.wsPosition[i], &level);
        if (page) {
            serving[i] = static_cast<std::uint32_t>(*page);
            out.level[i] = static_cast<std::int8_t>(level);
        }
    });
    // The covered pixels grouped by serving page (a counting sort: 4 bytes a pixel).
    std::vector<std::uint32_t> first(vsm.resident.size() + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!frame.Covered(i)) continue;
        if (serving[i] == kNone) {
            // Lit, or in attached shadow: ShadePoint outside every map.
            const bool facing =
                glm::dot(frame.wsNormal[i], lightSpace.DirectionToLight(frame.wsPosition[i])) > 0.0;
            out.shades[i] = facing ? Shade::kLit : Shade::kFacingAway;
            out.outside[i] = facing;
            continue;
        }
        out.page[i] = static_cast<std::uint8_t>(serving[i]);
        ++first[serving[i] + 1];
    }
    for (std::size_t p = 0; p < vsm.resident.size(); ++p) first[p + 1] += first[p];
    std::vector<std::uint32_t> byPage(first.back());
    {
        std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
        for (std::size_t i = 0; i < n; ++i)
            if (serving[i] != kNone) byPage[next[serving[i]]++] = static_cast<std::uint32_t>(i);
    }
    serving = {};
    const Resolution pageSize{vsm.layout.pageTexels, vsm.layout.pageTexels};
    if (vsm.resident.empty()) {  // nothing asked for a page: one empty map, every pixel outside
        ShadowMap none;
        none.resolution = pageSize;
        none.matrix = vsm.layout.PageMatrix({vsm.layout.maxLevel, 0, 0});
        none.depth.assign(pageSize.Count(), std::numeric_limits<float>::infinity());
        out.maps.push_back(std::move(none));
    }
    for (std::size_t p = 0; p < vsm.resident.size(); ++p) {
        out.maps.push_back(
            backend.RenderShadowMap(lightSpace, vsm.layout.PageMatrix(vsm.resident[p]), pageSize));
        // In chunks of at most kChunkPixels, so a page serving most of the frame (a coarse one)
        // never copies the whole frame at once.
        for (std::uint32_t k = first[p]; k < first[p + 1]; k += kChunkPixels) {
            const std::span<const std::uint32_t> chunk(
                byPage.data() + k, std::min<std::size_t>(kChunkPixels, first[p + 1] - k));
            const std::vector<Shade> shades =
                backend.ShadePixels(CompactBuffer(frame, chunk), lightSpace, out.maps.back());
            for (std::size_t c = 0; c < chunk.size(); ++c) out.shades[chunk[c]] = shades[c];
        }
    }
    return out;
}

double PageEnergy(const VirtualShadowMap& vsm, const Camera& camera, const LightSpace& lightSpace,
                  const LightSamples& samples, std::span<const std::uint8_t> grazing,
                  double* grazingPart) {
    double h = 0.0, g = 0.0;
    for (std::size_t s = 0; s < samples.lsX.size(); ++s) {
        const std::optional<std::size_t> page = vsm.ServingPage(camera, lightSpace, samples.wsX[s]);
        if (!page) continue;
        const double badness = SampleBadness(vsm.layout.PageMatrix(vsm.resident[*page]),
                                             samples.lsX[s], samples.dXdx1[s], samples.dXdx2[s]);
        h += badness;
        if (s < grazing.size() && grazing[s]) g += badness;
    }
    if (grazingPart) *grazingPart = g;
    return h;
}

ShadowMap PoolAtlas(std::span<const ShadowMap> pages, int pageTexels) {
    const int columns =
        std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(pages.size())))));
    const int rows = std::max(1, static_cast<int>((pages.size() + columns - 1) / columns));
    ShadowMap atlas;
    atlas.resolution = {columns * pageTexels, rows * pageTexels};
    // p1 = p2 = −p4: every point maps to (−1, −1), outside the atlas.
    atlas.matrix = {glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(0, 0, 1)};
    atlas.depth.assign(atlas.resolution.Count(), std::numeric_limits<float>::infinity());
    for (std::size_t p = 0; p < pages.size(); ++p) {
        const int x0 = static_cast<int>(p % columns) * pageTexels;
        const int y0 = static_cast<int>(p / columns) * pageTexels;
        for (int y = 0; y < pageTexels; ++y)
            for (int x = 0; x < pageTexels; ++x)
                atlas.depth[static_cast<std::size_t>(y0 + y) * atlas.resolution.width + x0 + x] =
                    pages[p].depth[static_cast<std::size_t>(y) * pageTexels + x];
    }
    return atlas;
}

}  // namespace lexel::spatial
