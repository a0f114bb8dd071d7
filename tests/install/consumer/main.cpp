// A renderer using the installed package: the embedding guide's OptimizeShadows
// (optimize_shadows.h) on a toy renderer that traces a floor and a box exactly. The toy does what
// an engine does: a 1280×720 camera pass into a reversed-Z depth buffer with Vulkan's conventions
// ([0, 1] clip depth, NDC y down, infinite far plane), and per light a real shadow map rendered
// through the 4×4 lexel gives it (one ray per texel centre, depth stored as float where it lies in
// [0, 1]) with its own shadow test. Checks: the map-based mask agrees with exact shadow rays on 99%
// of the readback, h does not grow, every visible point of the readback lands in the optimized map
// at a depth in [0, 1], and 99% of the 1280×720 frame's do. Prints "N boundary samples; h a -> b"
// per light; exits 0 when every check holds.
#include <lexel/flatland.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "optimize_shadows.h"

namespace {

const glm::dvec3 kBoxLo(-1.0, 0.0, -1.0), kBoxHi(1.0, 2.0, 1.0);
constexpr double kFloorHalf = 20.0;

struct Hit {
    double t;
    glm::dvec3 wsNormal;
};

// The nearest hit of o + t d, t ∈ (tMin, tMax), with the floor y = 0 (|x|, |z| ≤ 20) or the box.
std::optional<Hit> Trace(glm::dvec3 o, glm::dvec3 d, double tMin, double tMax) {
    std::optional<Hit> hit;
    if (d.y != 0.0) {
        const double t = -o.y / d.y;
        const glm::dvec3 p = o + t * d;
        if (t > tMin && t < tMax && std::abs(p.x) <= kFloorHalf && std::abs(p.z) <= kFloorHalf)
            hit = Hit{t, {0.0, 1.0, 0.0}}, tMax = t;
    }
    double t0 = tMin, t1 = tMax;
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
        const double ta = (kBoxLo[k] - o[k]) / d[k], tb = (kBoxHi[k] - o[k]) / d[k];
        if (std::min(ta, tb) > t0) t0 = std::min(ta, tb), axis = k;
        t1 = std::min(t1, std::max(ta, tb));
    }
    if (axis >= 0 && t0 <= t1) {
        glm::dvec3 n(0.0);
        n[axis] = d[axis] > 0.0 ? -1.0 : 1.0;
        hit = Hit{t0, n};
    }
    return hit;
}

// The surface normal at a visible point (the renderer knows its G-buffer's normals).
glm::dvec3 NormalAt(glm::dvec3 p) {
    const double eps = 1e-4;
    for (int k = 0; k < 3; ++k) {
        const bool inside = glm::all(glm::lessThanEqual(kBoxLo - eps, p)) &&
                            glm::all(glm::lessThanEqual(p, kBoxHi + eps));
        if (inside && (std::abs(p[k] - kBoxLo[k]) < eps || std::abs(p[k] - kBoxHi[k]) < eps) &&
            !(k == 1 && p.y < eps)) {
            glm::dvec3 n(0.0);
            n[k] = std::abs(p[k] - kBoxHi[k]) < eps ? 1.0 : -1.0;
            return n;
        }
    }
    return {0.0, 1.0, 0.0};
}

glm::dvec3 Unproject(const glm::dmat4& worldFromClip, double x, double y, double z) {
    const glm::dvec4 h = worldFromClip * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(h) / h.w;
}

// A shadow map rendered through `clip` ([0, 1] depth), one ray per texel centre: NDC z of the
// nearest surface, +inf where nothing lies in the depth range. Texel row 0 at NDC y = -1.
std::vector<float> RenderShadowMap(const glm::dmat4& clip, Resolution map) {
    const glm::dmat4 worldFromClip = glm::inverse(clip);
    std::vector<float> depth(map.Count(), std::numeric_limits<float>::infinity());
    for (int ty = 0; ty < map.height; ++ty)
        for (int tx = 0; tx < map.width; ++tx) {
            const double x = 2.0 * (tx + 0.5) / map.width - 1.0,
                         y = 2.0 * (ty + 0.5) / map.height - 1.0;
            const glm::dvec3 a = Unproject(worldFromClip, x, y, 0.0),
                             b = Unproject(worldFromClip, x, y, 1.0);
            if (const auto hit = Trace(a, b - a, 0.0, 1.0)) {
                const glm::dvec4 h = clip * glm::dvec4(a + hit->t * (b - a), 1.0);
                depth[static_cast<std::size_t>(ty) * map.width + tx] =
                    static_cast<float>(h.z / h.w);
            }
        }
    return depth;
}

// The renderer's shadow test at the readback's points: the receiver's plane depth on the texel
// centre's ray against the stored depth (receiver-plane depth bias), less 1e-6.
std::vector<Shade> ShadeReadback(const Readback& readback, const glm::dmat4& clip, Resolution map,
                                 const std::vector<float>& mapDepth, const Light& light) {
    const glm::dmat4 worldFromClip = glm::inverse(clip);
    std::vector<Shade> shades(readback.buffer.resolution.Count(), Shade::kEmpty);
    for (std::size_t i = 0; i < shades.size(); ++i) {
        if (!readback.buffer.Covered(i)) continue;
        const glm::dvec3 ws = readback.buffer.wsPosition[i], n = NormalAt(ws);
        if (!(glm::dot(n, light.position - ws) > 0.0)) {
            shades[i] = Shade::kFacingAway;
            continue;
        }
        shades[i] = Shade::kLit;
        const glm::dvec4 h = clip * glm::dvec4(ws, 1.0);
        const int tx = static_cast<int>(std::floor((h.x / h.w + 1.0) * 0.5 * map.width));
        const int ty = static_cast<int>(std::floor((h.y / h.w + 1.0) * 0.5 * map.height));
        if (!(h.w > 0.0) || tx < 0 || ty < 0 || tx >= map.width || ty >= map.height) continue;
        const float stored = mapDepth[static_cast<std::size_t>(ty) * map.width + tx];
        const double x = 2.0 * (tx + 0.5) / map.width - 1.0,
                     y = 2.0 * (ty + 0.5) / map.height - 1.0;
        const glm::dvec3 a = Unproject(worldFromClip, x, y, 0.0),
                         b = Unproject(worldFromClip, x, y, 1.0);
        const glm::dvec4 onPlane =
            clip * glm::dvec4(a + (glm::dot(n, ws - a) / glm::dot(n, b - a)) * (b - a), 1.0);
        if (stored < onPlane.z / onPlane.w - 1e-6) shades[i] = Shade::kShadowed;
    }
    return shades;
}

// Exact shadow rays from the readback's points: the mask a perfect shadow map would give.
bool Shadowed(glm::dvec3 ws, const Light& light) {
    return Trace(ws, light.position - ws, 1e-6, 1.0 - 1e-6).has_value();
}

// The renderer's camera pass: 1280×720, reversed-Z with an infinite far plane, NDC y down
// (Vulkan), one exact ray per pixel centre.
struct CameraPass {
    Resolution resolution{1280, 720};
    glm::dmat4 clipFromWorld{1.0};
    std::vector<float> depth;         // cleared to 0: reversed-Z's far
    std::vector<glm::dvec3> wsFrame;  // the visible points, for the checks

    DepthBuffer Buffer() const {
        return {resolution,
                depth,
                clipFromWorld,
                {ClipDepth::kZeroToOne, DepthDirection::kReversed, FirstRow::kAtNdcYMinusOne}};
    }
};

CameraPass RenderCameraPass() {
    Camera camera;
    camera.position = {0.0, 1.7, 12.0};
    camera.target = {0.0, 0.0, 0.0};
    CameraPass pass;
    camera.resolution = pass.resolution;
    glm::dmat4 projection = camera.ClipFromView();
    projection[1][1] = -projection[1][1];  // NDC y down
    projection[2][2] = 0.0;                // z_ndc = near / z_view
    projection[3][2] = camera.nearPlane;
    pass.clipFromWorld = projection * camera.ViewFromWorld();
    const Resolution res = pass.resolution;
    const glm::dmat4 worldFromClip = glm::inverse(pass.clipFromWorld);
    pass.depth.assign(res.Count(), 0.0f);
    for (int row = 0; row < res.height; ++row)
        for (int x = 0; x < res.width; ++x) {
            const double ndcX = 2.0 * (x + 0.5) / res.width - 1.0,
                         ndcY = 2.0 * (row + 0.5) / res.height - 1.0;        // row 0 at NDC y = -1
            const glm::dvec3 a = Unproject(worldFromClip, ndcX, ndcY, 1.0);  // the near plane
            if (const auto hit = Trace(camera.position, a - camera.position, 0.0, 1e9)) {
                const glm::dvec3 ws = camera.position + hit->t * (a - camera.position);
                const glm::dvec4 h = pass.clipFromWorld * glm::dvec4(ws, 1.0);
                pass.depth[static_cast<std::size_t>(row) * res.width + x] =
                    static_cast<float>(h.z / h.w);
                pass.wsFrame.push_back(ws);
            }
        }
    return pass;
}

// Whether a world point lands in a shadow map rendered through `clip`, at a depth in [0, 1].
bool InMap(const glm::dmat4& clip, const glm::dvec3& ws) {
    const glm::dvec4 h = clip * glm::dvec4(ws, 1.0);
    return h.w > 0.0 && std::abs(h.x) <= h.w && std::abs(h.y) <= h.w && h.z >= 0.0 && h.z <= h.w;
}

// Every readback point lands in the optimized map at a depth in [0, 1]; frame points between the
// readback's samples may not (the floor's far edge, seen at a grazing angle: 8 frame rows per
// readback row there span up to 2.6 world units beyond the last sample), 1% at most. Prints a
// line per light.
bool OptimizedMapsCoverTheView(const CameraPass& pass,
                               const std::vector<OptimizedShadow>& shadows) {
    const Readback readback = MakeReadback(DownsampleDepth(pass.Buffer()).View());
    bool ok = true;
    for (std::size_t l = 0; l < shadows.size(); ++l) {
        const OptimizedShadow& s = shadows[l];
        std::size_t readbackOut = 0, frameOut = 0;
        for (const glm::dvec3& ws : readback.wsRelevant) readbackOut += !InMap(s.clipFromWorld, ws);
        for (const glm::dvec3& ws : pass.wsFrame) frameOut += !InMap(s.clipFromWorld, ws);
        std::printf(
            "light %zu: %zu boundary samples; h %.6g -> %.6g; outside the map or its depth "
            "range: %zu of %zu readback points, %zu of %zu frame points\n",
            l, s.samples, s.hStandard, s.h, readbackOut, readback.wsRelevant.size(), frameOut,
            pass.wsFrame.size());
        ok = ok && s.samples > 0 && std::isfinite(s.h) && s.h <= s.hStandard && readbackOut == 0 &&
             frameOut <= pass.wsFrame.size() / 100;
    }
    return ok;
}

}  // namespace

int main() {
    const CameraPass pass = RenderCameraPass();
    const std::vector<Light> lights = {Light{Light::Type::kPoint, {10.0, 15.0, 6.0}, {}},
                                       Light{Light::Type::kPoint, {-12.0, 9.0, -4.0}, {}}};
    Bounds wsSceneBounds;
    wsSceneBounds.Add({-kFloorHalf, 0.0, -kFloorHalf});
    wsSceneBounds.Add({kFloorHalf, 0.0, kFloorHalf});
    wsSceneBounds.Add(kBoxLo);
    wsSceneBounds.Add(kBoxHi);
    const Resolution map{512, 512};

    std::size_t agree = 0, compared = 0;
    const ShadowMask shadowMask = [&](std::size_t l, const Readback& readback,
                                      const glm::dmat4& lightClip) {
        const std::vector<Shade> mask =
            ShadeReadback(readback, lightClip, map, RenderShadowMap(lightClip, map), lights[l]);
        for (std::size_t i = 0; i < mask.size(); ++i)
            if (mask[i] == Shade::kLit || mask[i] == Shade::kShadowed) {
                ++compared;
                agree += (mask[i] == Shade::kShadowed) ==
                         Shadowed(readback.buffer.wsPosition[i], lights[l]);
            }
        return mask;
    };
    const std::vector<OptimizedShadow> shadows =
        OptimizeShadows(pass.Buffer(), lights, wsSceneBounds, map, shadowMask);

    bool ok = shadows.size() == lights.size() && compared > 0 && agree >= 0.99 * compared;
    std::printf("standard-map mask agrees with exact rays on %zu of %zu readback pixels\n", agree,
                compared);
    ok = OptimizedMapsCoverTheView(pass, shadows) && ok;
    // The flatland package links too: the thesis's lexel-plane angle convention.
    std::printf("flatland: axis at 90 degrees is a lexel plane at %.1f degrees\n",
                lexel::flatland::LexelPlaneDegFromAxis(std::acos(0.0)));
    return ok ? 0 : 1;
}
