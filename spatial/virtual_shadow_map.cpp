// Virtual shadow maps (virtual_shadow_map.h).
#include "lexel/spatial/virtual_shadow_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "lexel/solvers/geometry.h"
#include "lexel/spatial/baseline_support.h"
#include "lexel/spatial/perspective_aliasing.h"

namespace lexel::spatial {

using namespace baseline_detail;

namespace {

// The square grows by this fraction (dimensionless) so that the farthest bounds corner maps
// strictly inside the last page, not onto its far edge.
constexpr double kSquareSlack = 1e-6;
// The bias search stops when its bracket is this narrow (levels).
constexpr double kBiasTolerance = 1.0 / 64.0;

// A page key as one integer: level + 16 in the top bits, x and y offset by 2^26 (clipmap windows
// may reach outside the square: negative pages), 28 bits each.
constexpr std::int64_t kPageOffset = std::int64_t{1} << 26;
std::uint64_t Encode(const PageKey& p) {
    return (static_cast<std::uint64_t>(p.level + 16) << 56) |
           (static_cast<std::uint64_t>(p.x + kPageOffset) << 28) |
           static_cast<std::uint64_t>(p.y + kPageOffset);
}
PageKey Decode(std::uint64_t key) {
    const std::uint64_t mask = (std::uint64_t{1} << 28) - 1;
    return {static_cast<int>(key >> 56) - 16,
            static_cast<int>(static_cast<std::int64_t>((key >> 28) & mask) - kPageOffset),
            static_cast<int>(static_cast<std::int64_t>(key & mask) - kPageOffset)};
}

// Level ℓ's texels per plane unit, and its texel coordinates of a plane point.
double LevelScale(const VirtualMapLayout& l, int level) {
    return std::ldexp(kVirtualMapTexels / (2.0 * l.halfSize), -level);
}
glm::dvec2 LevelTexel(const VirtualMapLayout& l, int level, const glm::dvec2& y) {
    const double offset = std::ldexp(0.5 * kVirtualMapTexels, -level);
    return LevelScale(l, level) * (y - l.centre) + glm::dvec2(offset) + l.phase;
}

}  // namespace

int VirtualPageTexels(Resolution budget) {
    const double texels = static_cast<double>(budget.Count());
    int side = 1;
    while (side < kVirtualMapTexels &&
           std::floor(texels / (4.0 * side * side)) >= static_cast<double>(kMinPoolPages))
        side *= 2;
    return side;
}

LightMatrix VirtualMapLayout::LevelMatrix(int level) const {
    const double s = LevelScale(*this, level);
    const double offset = std::ldexp(0.5 * kVirtualMapTexels, -level);
    // u = s (y − centre) + offset + phase with y = (b1·X, b2·X) / (p4·X).
    return {s * b1 + (offset + phase.x - s * centre.x) * p4,
            s * b2 + (offset + phase.y - s * centre.y) * p4, p4};
}

LightMatrix VirtualMapLayout::PageMatrix(const PageKey& page) const {
    LightMatrix m = LevelMatrix(page.level);
    m.p1 -= static_cast<double>(page.x) * pageTexels * m.p4;
    m.p2 -= static_cast<double>(page.y) * pageTexels * m.p4;
    return m;
}

std::optional<PageKey> VirtualMapLayout::PageAt(int level, const glm::dvec3& lsX) const {
    if (level < minLevel || level > maxLevel || !InFront(p4, lsX)) return std::nullopt;
    const glm::dvec2 g = LevelTexel(*this, level, ProjectToAxisPlane(p4, b1, b2, lsX));
    const double px = std::floor(g.x / pageTexels), py = std::floor(g.y / pageTexels);
    if (level >= 0) {
        const double pages =
            std::ldexp(static_cast<double>(kVirtualMapTexels) / pageTexels, -level);
        if (!(px >= 0.0 && py >= 0.0 && px < pages && py < pages)) return std::nullopt;
    } else {
        // The window: 16384 texels a side about the camera, snapped to whole pages.
        const double half = 0.5 * kVirtualMapTexels / pageTexels;
        const glm::dvec2 camera = std::ldexp(1.0, -level) * cameraTexel / double(pageTexels);
        const double cx = std::floor(camera.x + 0.5), cy = std::floor(camera.y + 0.5);
        if (!(px >= cx - half && px < cx + half && py >= cy - half && py < cy + half))
            return std::nullopt;
    }
    return PageKey{level, static_cast<int>(px), static_cast<int>(py)};
}

VirtualMapLayout MakeVirtualMapLayout(const BaselineContext& context) {
    CheckContext(context);
    const LightSpace& ls = *context.lightSpace;
    const NormalAxis axis = ChooseNormalAxis(context);
    VirtualMapLayout l;
    l.p4 = axis.p4;
    PlaneBasis(l.p4, &l.b1, &l.b2);
    const auto corners = context.wsBounds.Corners();
    std::vector<glm::dvec3> wsPoints(corners.begin(), corners.end());
    if (!axis.cornersInFront) wsPoints.assign(context.wsRelevant.begin(), context.wsRelevant.end());
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec3& x : wsPoints) {
        const glm::dvec3 lsX = ls.ToLight(x);
        if (!InFront(l.p4, lsX)) continue;
        const glm::dvec2 y = ProjectToAxisPlane(l.p4, l.b1, l.b2, lsX);
        lo = glm::min(lo, y), hi = glm::max(hi, y);
    }
    l.centre = 0.5 * (lo + hi);
    const double half = 0.5 * std::max(hi.x - lo.x, hi.y - lo.y);
    // A scene of one point still gets a square (1e-9 of its distance from the light's plane).
    l.halfSize = std::max(half, 1e-9 * glm::length(l.centre) + 1e-300) * (1.0 + kSquareSlack);
    l.pageTexels = VirtualPageTexels(context.map);
    l.poolPages = static_cast<int>(context.map.Count() /
                                   (static_cast<std::int64_t>(l.pageTexels) * l.pageTexels));
    l.maxLevel = static_cast<int>(std::lround(std::log2(kVirtualMapTexels / l.pageTexels)));
    const glm::dvec3 lsCamera = ls.ToLight(context.camera.position);
    if (!ls.IsPoint() && InFront(l.p4, lsCamera)) {
        l.clipmap = true;
        l.minLevel = -kClipmapFinerLevels;
        l.cameraTexel = LevelTexel(l, 0, ProjectToAxisPlane(l.p4, l.b1, l.b2, lsCamera));
    }
    return l;
}

std::optional<double> FootprintLevel(const VirtualMapLayout& layout, const Camera& camera,
                                     const LightSpace& lightSpace, const glm::dvec3& wsPoint) {
    const double alpha = PerspectiveAliasing(camera, lightSpace, layout.LevelMatrix(0), wsPoint);
    if (!(alpha > 0.0) || !std::isfinite(alpha)) return std::nullopt;
    return -std::log2(alpha);
}

int RequestedLevel(const VirtualMapLayout& layout, double footprintLevel, double lodBias) {
    const double level = std::ceil(footprintLevel + lodBias);
    if (!(level > layout.minLevel)) return layout.minLevel;
    if (!(level < layout.maxLevel)) return layout.maxLevel;
    return static_cast<int>(level);
}

std::optional<std::size_t> VirtualShadowMap::ServingPage(const Camera& camera,
                                                         const LightSpace& lightSpace,
                                                         const glm::dvec3& wsPoint,
                                                         int* level) const {
    const std::optional<double> footprint = FootprintLevel(layout, camera, lightSpace, wsPoint);
    if (!footprint) return std::nullopt;
    const glm::dvec3 lsX = lightSpace.ToLight(wsPoint);
    for (int l = RequestedLevel(layout, *footprint, lodBias); l <= layout.maxLevel; ++l) {
        const std::optional<PageKey> page = layout.PageAt(l, lsX);
        if (!page) continue;
        const std::uint64_t key = Encode(*page);
        const auto it = std::lower_bound(sortedKeys_.begin(), sortedKeys_.end(), key);
        if (it == sortedKeys_.end() || *it != key) continue;
        // The page's own matrix must agree (its rows round differently from PageAt's plane
        // coordinates): a point within rounding of the page's edge goes to the coarser level.
        const glm::dvec2 u = layout.PageMatrix(*page).Map(lsX);
        const double side = layout.pageTexels;
        if (!(u.x >= 0.0 && u.y >= 0.0 && u.x < side && u.y < side)) continue;
        if (level) *level = l;
        return sortedIndex_[static_cast<std::size_t>(it - sortedKeys_.begin())];
    }
    return std::nullopt;
}

namespace {

// One readback pixel's request: its footprint level and the light-space points whose pages it
// asks for (its centre first, then its footprint's corners).
struct Asker {
    double footprint = 0.0;
    std::array<glm::dvec3, 5> lsPoints;
    int points = 0;
};

std::vector<Asker> Askers(const VirtualMapLayout& layout, const BaselineContext& context,
                          const Readback& readback) {
    const LightSpace& ls = *context.lightSpace;
    const CameraBuffer& buffer = readback.buffer;
    std::vector<Asker> askers;
    for (std::size_t i = 0; i < buffer.triangle.size(); ++i) {
        if (!buffer.Covered(i)) continue;
        const glm::dvec3& ws = buffer.wsPosition[i];
        const glm::dvec3& n = buffer.wsNormal[i];
        // No normal (a depth-only readback): it may face the light.
        if (n != glm::dvec3(0.0) && !(glm::dot(n, ls.DirectionToLight(ws)) > 0.0)) continue;
        const std::optional<double> footprint = FootprintLevel(layout, context.camera, ls, ws);
        if (!footprint) continue;
        Asker a;
        a.footprint = *footprint;
        a.lsPoints[a.points++] = ls.ToLight(ws);
        const glm::dvec3 d1 = 0.5 * readback.dWdx1[i], d2 = 0.5 * readback.dWdx2[i];
        if (readback.smooth[i] && std::isfinite(glm::dot(d1, d1) + glm::dot(d2, d2)))
            for (const double s1 : {-1.0, 1.0})
                for (const double s2 : {-1.0, 1.0})
                    a.lsPoints[a.points++] = ls.ToLight(ws + s1 * d1 + s2 * d2);
        askers.push_back(a);
    }
    return askers;
}

// Every asker's pages under `bias`, one key per page and asker (unsorted).
std::vector<std::uint64_t> RequestKeys(const VirtualMapLayout& layout,
                                       std::span<const Asker> askers, double bias) {
    const std::uint64_t coarse = Encode({layout.maxLevel, 0, 0});
    std::vector<std::uint64_t> keys;
    keys.reserve(askers.size() * 3);
    for (const Asker& a : askers) {
        int level = RequestedLevel(layout, a.footprint, bias);
        // A clipmap level whose window does not hold the pixel: the next coarser one.
        while (level < 0 && !layout.PageAt(level, a.lsPoints[0])) ++level;
        std::array<std::uint64_t, 6> mine;
        int m = 0;
        const auto add = [&](std::uint64_t key) {
            if (std::find(mine.begin(), mine.begin() + m, key) == mine.begin() + m) mine[m++] = key;
        };
        for (int k = 0; k < a.points; ++k)
            if (const std::optional<PageKey> page = layout.PageAt(level, a.lsPoints[k]))
                add(Encode(*page));
        add(coarse);
        keys.insert(keys.end(), mine.begin(), mine.begin() + m);
    }
    return keys;
}

std::int64_t DistinctPages(std::vector<std::uint64_t> keys) {
    std::sort(keys.begin(), keys.end());
    return std::unique(keys.begin(), keys.end()) - keys.begin();
}

// The smallest bias ≥ b0 (to kBiasTolerance) at which the distinct pages fit the pool. Raising
// the bias moves askers to coarser levels, whose pages contain the finer ones': the count never
// grows, so bisection applies. At b0 + (maxLevel − minLevel + 1) every asker is at maxLevel.
double FitBias(const VirtualMapLayout& layout, std::span<const Asker> askers, double b0) {
    const auto fits = [&](double b) {
        return DistinctPages(RequestKeys(layout, askers, b)) <= layout.poolPages;
    };
    if (fits(b0)) return b0;
    double lo = b0, hi = b0 + (layout.maxLevel - layout.minLevel + 1);
    while (hi - lo > kBiasTolerance) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace

VirtualShadowMap BuildVirtualShadowMap(const BaselineContext& context, const Readback& readback,
                                       const VirtualMapOptions& options) {
    VirtualShadowMap vsm;
    vsm.layout = MakeVirtualMapLayout(context);
    vsm.layout.phase = options.phase;
    const std::vector<Asker> askers = Askers(vsm.layout, context, readback);
    vsm.lodBias = options.fitPool ? FitBias(vsm.layout, askers, options.lodBias) : options.lodBias;
    std::vector<std::uint64_t> keys = RequestKeys(vsm.layout, askers, vsm.lodBias);
    std::sort(keys.begin(), keys.end());
    // Run lengths: requests per page.
    std::vector<std::pair<std::uint64_t, std::int64_t>> pages;
    for (std::uint64_t key : keys)
        if (!pages.empty() && pages.back().first == key)
            ++pages.back().second;
        else
            pages.emplace_back(key, 1);
    vsm.requested = static_cast<std::int64_t>(pages.size());
    // The most requested first; ties to the coarser level, then the smaller key.
    std::sort(pages.begin(), pages.end(), [](const auto& a, const auto& b) {
        if (a.second != b.second) return a.second > b.second;
        const int la = Decode(a.first).level, lb = Decode(b.first).level;
        if (la != lb) return la > lb;
        return a.first < b.first;
    });
    const std::size_t kept = std::min(pages.size(), static_cast<std::size_t>(vsm.layout.poolPages));
    std::vector<std::pair<std::uint64_t, std::uint32_t>> lookup;
    for (std::size_t i = 0; i < kept; ++i) {
        vsm.resident.push_back(Decode(pages[i].first));
        vsm.requests.push_back(pages[i].second);
        lookup.emplace_back(pages[i].first, static_cast<std::uint32_t>(i));
    }
    vsm.dropped = vsm.requested - static_cast<std::int64_t>(kept);
    if (kept < pages.size()) vsm.droppedRequests = pages[kept].second;
    std::sort(lookup.begin(), lookup.end());
    for (const auto& [key, index] : lookup) {
        vsm.sortedKeys_.push_back(key);
        vsm.sortedIndex_.push_back(index);
    }
    return vsm;
}

}  // namespace lexel::spatial
