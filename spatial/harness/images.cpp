#include "lexel/spatial/harness/images.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lexel::spatial {
namespace {

float Lambert(const CameraBuffer& frame, const LightSpace& lightSpace, std::size_t i) {
    const double cosine =
        glm::dot(frame.wsNormal[i], lightSpace.DirectionToLight(frame.wsPosition[i]));
    return kAmbient + (1.0f - kAmbient) * static_cast<float>(std::max(0.0, cosine));
}

void Put(Image& image, std::size_t i, float r, float g, float b) {
    image.pixels[3 * i] = r;
    image.pixels[3 * i + 1] = g;
    image.pixels[3 * i + 2] = b;
}

void Put(Image& image, std::size_t i, ImageColour c) { Put(image, i, c.r, c.g, c.b); }

bool Marked(std::span<const std::uint8_t> mask, std::size_t i) {
    return i < mask.size() && mask[i];
}

// Whether a light-space point maps inside a map's texels (in front of its plane first).
bool InsideMap(const LightMatrix& matrix, Resolution map, const glm::dvec3& lsX) {
    if (!InFront(matrix.p4, lsX)) return false;
    const glm::dvec2 u = matrix.Map(lsX);
    return u.x >= 0.0 && u.y >= 0.0 && u.x < map.width && u.y < map.height;
}

}  // namespace

std::vector<std::uint8_t> UncoveredPixels(const CameraBuffer& frame, const LightSpace& lightSpace,
                                          const Camera& camera, std::span<const Shade> shades,
                                          const LightMatrix& matrix, Resolution map,
                                          std::span<const Cascade> cascades) {
    std::vector<std::uint8_t> uncovered(shades.size(), 0);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (shades[i] != Shade::kLit && shades[i] != Shade::kShadowed) continue;
        const glm::dvec3& wsPoint = frame.wsPosition[i];
        const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
        if (cascades.empty()) {
            uncovered[i] = !InsideMap(matrix, map, lsX);
            continue;
        }
        bool covered = true;
        const Cascade& c =
            cascades[CascadeFor(cascades, PlanarEyeDepth(camera, wsPoint), wsPoint, &covered)];
        uncovered[i] = !covered || !InsideMap(c.matrix, c.map, lsX);
    }
    return uncovered;
}

Image FrameImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                 std::span<const Shade> shades, std::span<const std::uint8_t> uncovered) {
    Image image = MakeImage(frame.resolution.width, frame.resolution.height, 3);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!frame.Covered(i)) {
            Put(image, i, kSkyColour);
        } else if (Marked(uncovered, i)) {
            Put(image, i, kUncoveredColour);
        } else {
            const float v = shades[i] == Shade::kLit ? Lambert(frame, lightSpace, i) : kAmbient;
            Put(image, i, v, v, v);
        }
    }
    return image;
}

Image MisclassificationImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                             std::span<const Shade> shades, std::span<const std::uint8_t> truth,
                             std::span<const std::uint8_t> uncovered) {
    Image image = MakeImage(frame.resolution.width, frame.resolution.height, 3);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!frame.Covered(i)) {
            Put(image, i, kBackgroundColour);
            continue;
        }
        const float v = 0.35f + 0.4f * (truth[i] ? 0.0f : Lambert(frame, lightSpace, i));
        if (Marked(uncovered, i))
            Put(image, i, kUncoveredColour);
        else if (shades[i] == Shade::kShadowed && !truth[i])
            Put(image, i, kFalseShadowColour);
        else if (shades[i] == Shade::kLit && truth[i])
            Put(image, i, kFalseLightColour);
        else
            Put(image, i, v, v, v);
    }
    return image;
}

MapDepthRange DepthRangeOf(const ShadowMap& map) {
    MapDepthRange range{std::numeric_limits<float>::infinity(),
                        -std::numeric_limits<float>::infinity(), false};
    for (float d : map.depth)
        if (std::isfinite(d)) {
            range.nearest = std::min(range.nearest, d);
            range.farthest = std::max(range.farthest, d);
            range.any = true;
        }
    if (!range.any) range.nearest = range.farthest = 0.0f;
    return range;
}

Image ShadowMapImage(const ShadowMap& map, const LightSamples& samples) {
    const int w = map.resolution.width, h = map.resolution.height;
    Image image = MakeImage(w, h, 3);
    const MapDepthRange range = DepthRangeOf(map);
    const float span = range.farthest > range.nearest ? range.farthest - range.nearest : 1.0f;
    for (std::size_t i = 0; i < map.depth.size(); ++i) {
        const float d = map.depth[i];
        if (!std::isfinite(d)) {
            Put(image, i, kEmptyTexelColour);
            continue;
        }
        const float v = kNearGrey - (kNearGrey - kFarGrey) * (d - range.nearest) / span;
        Put(image, i, v, v, v);
    }
    const auto dot = [&](const glm::dvec3& lsX, ImageColour colour) {
        if (!InFront(map.matrix.p4, lsX)) return;
        const glm::dvec2 u = map.matrix.Map(lsX);
        const int x = static_cast<int>(std::floor(u.x)), y = static_cast<int>(std::floor(u.y));
        if (x < 0 || y < 0 || x >= w || y >= h) return;
        Put(image, static_cast<std::size_t>(y) * w + x, colour);
    };
    for (const glm::dvec3& lsX : samples.lsRelevant) dot(lsX, kVisiblePointColour);
    for (const glm::dvec3& lsX : samples.lsX) dot(lsX, kBoundarySampleColour);
    return image;
}

}  // namespace lexel::spatial
