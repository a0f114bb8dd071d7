#include "lexel/spatial/gl/warp_refinement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace lexel::spatial::gl {

namespace {

struct Vertex {
    glm::dvec3 unit;
    std::optional<glm::dvec2> texel;  // warped texels; nullopt behind the light's plane
};

struct Refiner {
    const glm::dmat4& clipFromUnit;
    const MapWarp& warp;
    Resolution map;
    double maxEdge;
    WarpPieces* out;

    Vertex Make(const glm::dvec3& unit) const {
        const glm::dvec4 c = clipFromUnit * glm::dvec4(unit, 1.0);
        if (!(c.w > 0.0)) return {unit, std::nullopt};
        const glm::dvec2 b = (glm::dvec2(c) / c.w + 1.0) * 0.5 * glm::dvec2(map.width, map.height);
        return {unit, glm::dvec2(warp.x.Apply(b.x), warp.y.Apply(b.y)) + warp.phase};
    }

    // Whether the piece overlaps the map and has an edge longer than maxEdge (the warped image
    // of a straight base edge stays in its ends' bounding box: the axis warps are monotone).
    bool NeedsSplit(const std::array<Vertex, 3>& v) const {
        if (!v[0].texel || !v[1].texel || !v[2].texel) return false;  // GL clips it
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        double longest = 0.0;
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, *v[k].texel), hi = glm::max(hi, *v[k].texel);
            longest = std::max(longest, glm::length(*v[k].texel - *v[(k + 1) % 3].texel));
        }
        const bool overlaps = hi.x >= 0.0 && hi.y >= 0.0 && lo.x <= map.width && lo.y <= map.height;
        return overlaps && longest > maxEdge;
    }

    void Emit(const std::array<Vertex, 3>& v, std::int32_t triangle) const {
        for (const Vertex& x : v) out->unitVertices.push_back(glm::vec3(x.unit));
        out->triangle.push_back(triangle);
        double longest = std::numeric_limits<double>::infinity();
        if (v[0].texel && v[1].texel && v[2].texel) {
            longest = 0.0;
            for (int k = 0; k < 3; ++k)
                longest = std::max(longest, glm::length(*v[k].texel - *v[(k + 1) % 3].texel));
        }
        out->longestEdge.push_back(longest);
    }

    void Refine(const std::array<Vertex, 3>& v, std::int32_t triangle, int depth) const {
        if (depth >= kMaxWarpSplits || !NeedsSplit(v)) return Emit(v, triangle);
        const Vertex m01 = Make(0.5 * (v[0].unit + v[1].unit));
        const Vertex m12 = Make(0.5 * (v[1].unit + v[2].unit));
        const Vertex m20 = Make(0.5 * (v[2].unit + v[0].unit));
        Refine({v[0], m01, m20}, triangle, depth + 1);
        Refine({m01, v[1], m12}, triangle, depth + 1);
        Refine({m20, m12, v[2]}, triangle, depth + 1);
        Refine({m01, m12, m20}, triangle, depth + 1);
    }
};

}  // namespace

std::vector<std::size_t> WarpDrawBatches(std::span<const double> longestEdge, double segmentTexels,
                                         double maxLevel) {
    std::vector<std::size_t> starts;
    double sum = 0.0;
    for (std::size_t i = 0; i < longestEdge.size(); ++i) {
        // The control stage's level (warp_shaders.h): ceil(length / segment) in [1, maxLevel];
        // NaN and +inf (behind the light's plane) at maxLevel.
        const double level =
            longestEdge[i] <= maxLevel * segmentTexels
                ? std::clamp(std::ceil(longestEdge[i] / segmentTexels), 1.0, maxLevel)
                : maxLevel;
        const double triangles = level * level;
        if (starts.empty() || sum + triangles > kMaxTessTrianglesPerDraw) {
            starts.push_back(i);
            sum = 0.0;
        }
        sum += triangles;
    }
    starts.push_back(longestEdge.size());
    return starts;
}

WarpPieces RefineForWarp(std::span<const glm::vec3> unitPositions,
                         std::span<const glm::uvec3> triangles, const glm::dmat4& clipFromUnit,
                         const MapWarp& warp, Resolution map, double maxEdgeTexels) {
    WarpPieces out;
    const Refiner refiner{clipFromUnit, warp, map, maxEdgeTexels, &out};
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        std::array<Vertex, 3> v;
        for (int k = 0; k < 3; ++k) v[k] = refiner.Make(glm::dvec3(unitPositions[triangles[t][k]]));
        refiner.Refine(v, static_cast<std::int32_t>(t), 0);
    }
    return out;
}

}  // namespace lexel::spatial::gl
