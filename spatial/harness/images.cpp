#include "lexel/spatial/harness/images.h"

#include <algorithm>
#include <cmath>

namespace lexel::spatial {
namespace {

constexpr float kAmbient = 0.15f;

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

}  // namespace

Image FrameImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                 std::span<const Shade> shades) {
    Image image = MakeImage(frame.resolution.width, frame.resolution.height, 3);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!frame.Covered(i)) {
            Put(image, i, 0.55f, 0.65f, 0.8f);
            continue;
        }
        const float v = shades[i] == Shade::kLit ? Lambert(frame, lightSpace, i) : kAmbient;
        Put(image, i, v, v, v);
    }
    return image;
}

Image MisclassificationImage(const CameraBuffer& frame, const LightSpace& lightSpace,
                             std::span<const Shade> shades, std::span<const std::uint8_t> truth) {
    Image image = MakeImage(frame.resolution.width, frame.resolution.height, 3);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!frame.Covered(i)) {
            Put(image, i, 1.0f, 1.0f, 1.0f);
            continue;
        }
        const float v = 0.35f + 0.4f * (truth[i] ? 0.0f : Lambert(frame, lightSpace, i));
        if (shades[i] == Shade::kShadowed && !truth[i])
            Put(image, i, 0.95f, 0.1f, 0.1f);
        else if (shades[i] == Shade::kLit && truth[i])
            Put(image, i, 0.1f, 0.3f, 0.95f);
        else
            Put(image, i, v, v, v);
    }
    return image;
}

Image ShadowMapImage(const ShadowMap& map, const LightSamples& samples) {
    const int w = map.resolution.width, h = map.resolution.height;
    Image image = MakeImage(w, h, 3);
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (float d : map.depth)
        if (std::isfinite(d)) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    const float span = hi > lo ? hi - lo : 1.0f;
    for (std::size_t i = 0; i < map.depth.size(); ++i) {
        const float d = map.depth[i];
        if (!std::isfinite(d)) {
            Put(image, i, 0.05f, 0.05f, 0.2f);
            continue;
        }
        const float v = 0.9f - 0.7f * (d - lo) / span;
        Put(image, i, v, v, v);
    }
    const auto dot = [&](const glm::dvec3& lsX, float r, float g, float b) {
        if (!InFront(map.matrix.p4, lsX)) return;
        const glm::dvec2 u = map.matrix.Map(lsX);
        const int x = static_cast<int>(std::floor(u.x)), y = static_cast<int>(std::floor(u.y));
        if (x < 0 || y < 0 || x >= w || y >= h) return;
        Put(image, static_cast<std::size_t>(y) * w + x, r, g, b);
    };
    for (const glm::dvec3& lsX : samples.lsRelevant) dot(lsX, 0.2f, 0.75f, 0.25f);
    for (const glm::dvec3& lsX : samples.lsX) dot(lsX, 0.95f, 0.1f, 0.1f);
    return image;
}

}  // namespace lexel::spatial
