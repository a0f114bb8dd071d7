#include "toy_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lexel::notebooks {

namespace {

// Entry parameter of the ray o + t d into the box, in (tMin, tMax), and the axis it enters
// through (the slab test); nullopt when it misses.
std::optional<std::pair<double, int>> EnterBox(glm::dvec3 o, glm::dvec3 d, glm::dvec3 lo,
                                               glm::dvec3 hi, double tMin, double tMax) {
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
        const double ta = (lo[k] - o[k]) / d[k], tb = (hi[k] - o[k]) / d[k];
        if (std::min(ta, tb) > tMin) tMin = std::min(ta, tb), axis = k;
        tMax = std::min(tMax, std::max(ta, tb));
    }
    if (tMin > tMax) return std::nullopt;
    return std::make_pair(tMin, axis);
}

}  // namespace

ToyRenderer::ToyRenderer(spatial::Resolution resolution) : resolution_(resolution) {
    camera_.position = {0.0, 1.7, 12.0};
    camera_.target = {0.0, 0.0, 0.0};
    camera_.resolution = resolution;
}

std::optional<ToyRenderer::Hit> ToyRenderer::Trace(glm::dvec2 xs) const {
    const glm::dvec3 o = camera_.position, d = camera_.RayDirection(xs, resolution_);
    std::optional<Hit> hit;
    double tBest = std::numeric_limits<double>::infinity();
    if (d.y < 0.0) {
        const double t = -o.y / d.y;
        const glm::dvec3 p = o + t * d;
        if (std::abs(p.x) <= floorHalf_ && std::abs(p.z) <= floorHalf_)
            tBest = t, hit = Hit{p, {0.0, 1.0, 0.0}};
    }
    if (const auto box = EnterBox(o, d, boxLo_, boxHi_, 0.0, tBest); box && box->second >= 0) {
        glm::dvec3 n(0.0);
        n[box->second] = d[box->second] > 0.0 ? -1.0 : 1.0;
        hit = Hit{o + box->first * d, n};
    }
    return hit;
}

std::vector<float> ToyRenderer::DepthBuffer() const {
    const glm::dmat4 screenFromWorld = ScreenFromWorld();
    std::vector<float> depth(resolution_.Count(), 1.0f);
    for (int y = 0; y < resolution_.height; ++y)
        for (int x = 0; x < resolution_.width; ++x)
            if (const auto hit = Trace({x + 0.5, y + 0.5})) {
                const glm::dvec4 h = screenFromWorld * glm::dvec4(hit->wsPoint, 1.0);
                depth[static_cast<std::size_t>(y) * resolution_.width + x] =
                    static_cast<float>(h.z / h.w);
            }
    return depth;
}

spatial::Bounds ToyRenderer::SceneBounds() const {
    spatial::Bounds bounds;
    bounds.Add({-floorHalf_, 0.0, -floorHalf_});
    bounds.Add({floorHalf_, 0.0, floorHalf_});
    bounds.Add(boxLo_);
    bounds.Add(boxHi_);
    return bounds;
}

std::vector<spatial::Shade> ToyRenderer::ShadowMask(const spatial::Readback& readback) const {
    std::vector<spatial::Shade> shades(readback.buffer.resolution.Count(), spatial::Shade::kEmpty);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        const int x = static_cast<int>(i % resolution_.width),
                  y = static_cast<int>(i / resolution_.width);
        const auto hit = Trace({x + 0.5, y + 0.5});
        if (!readback.buffer.Covered(i) || !hit) continue;
        const glm::dvec3 toLight = wsLight() - hit->wsPoint;
        // Segment parameters within 1e-6 of either end are the surface itself and the light.
        shades[i] = glm::dot(hit->wsNormal, toLight) <= 0.0 ? spatial::Shade::kFacingAway
                    : EnterBox(hit->wsPoint, toLight, boxLo_, boxHi_, 1e-6, 1.0 - 1e-6)
                        ? spatial::Shade::kShadowed
                        : spatial::Shade::kLit;
    }
    return shades;
}

}  // namespace lexel::notebooks
