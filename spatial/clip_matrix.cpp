// Composition of the light matrix with the light frame, and the clip-space rows a rasterizer needs.
#include "lexel/spatial/clip_matrix.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <limits>
#include <stdexcept>

#include "lexel/solvers/clipping.h"

namespace lexel::spatial {

glm::dmat4 MapFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix) {
    // X = L x + X(0) (L = LsFromWsLinear, whose columns are the light-space images of the
    // world axes), so row_i = (p_i·L[0], p_i·L[1], p_i·L[2], p_i·X(0)).
    const glm::dvec3 lsOrigin = lightSpace.ToLight(glm::dvec3(0.0));
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    const glm::dmat3 rows = matrix.Rows();
    glm::dmat4 m(0.0);  // column-major: m[c][r]
    for (int c = 0; c < 4; ++c) {
        const glm::dvec3 column = rows * (c < 3 ? lsFromWs[c] : lsOrigin);
        m[c][0] = column[0];
        m[c][1] = column[1];
        m[c][3] = column[2];
    }
    return m;
}

glm::dmat4 ClipFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix, Resolution map,
                         DepthRange range, ClipDepth convention) {
    const glm::dmat4 texel = MapFromWorld(lightSpace, matrix);
    const glm::dvec4 row1 = glm::row(texel, 0), row2 = glm::row(texel, 1),
                     rowW = glm::row(texel, 3);
    const double n = range.near, f = range.far;
    const bool zeroToOne = convention == ClipDepth::kZeroToOne;
    glm::dvec4 rowZ;
    if (lightSpace.IsPoint()) {
        // z_clip = a w + b: z_ndc = a + b / w is -1 (0) at w = n and 1 at w = f.
        const double a = zeroToOne ? f / (f - n) : (f + n) / (f - n);
        const double b = zeroToOne ? -f * n / (f - n) : -2.0 * f * n / (f - n);
        rowZ = a * rowW + glm::dvec4(0.0, 0.0, 0.0, b);
    } else {
        // d(x) = dir·x - dir·o + s is affine in x; z_clip = a s d(x) + b w gives z_ndc =
        // a d (s / w) + b.
        const glm::dvec3 dir = lightSpace.light().direction;
        const double s = lightSpace.ToLight(glm::dvec3(0.0)).z;
        const glm::dvec4 rowD(dir, lightSpace.Depth(glm::dvec3(0.0)));
        const double a = (zeroToOne ? 1.0 : 2.0) / (f - n);
        const double b = zeroToOne ? -n / (f - n) : -(f + n) / (f - n);
        rowZ = (a * s) * rowD + b * rowW;
    }
    const glm::dvec4 rowX = (2.0 / map.width) * row1 - rowW;
    const glm::dvec4 rowY = (2.0 / map.height) * row2 - rowW;
    return glm::transpose(glm::dmat4(rowX, rowY, rowZ, rowW));
}

std::optional<LightMatrix> LightMatrixFromClip(const LightSpace& lightSpace,
                                               const glm::dmat4& clipFromWorld, Resolution map,
                                               const glm::dvec3& wsCenter, std::string* failure) {
    const glm::dvec4 rowX = glm::row(clipFromWorld, 0), rowY = glm::row(clipFromWorld, 1),
                     rowW = glm::row(clipFromWorld, 3);
    // ClipFromWorld's rowX = (2 / W) row1 - rowW, solved for row1 (and row2 alike).
    const glm::dvec4 row1 = (0.5 * map.width) * (rowX + rowW);
    const glm::dvec4 row2 = (0.5 * map.height) * (rowY + rowW);
    const glm::dmat4 texelFromWorld = glm::transpose(glm::dmat4(row1, row2, glm::dvec4(0.0), rowW));
    return FromScreenRows(lightSpace, texelFromWorld, wsCenter, failure);
}

double ClipDepthQuantity(const LightSpace& lightSpace, const LightMatrix& matrix,
                         const glm::dvec3& wsPoint) {
    const double w = glm::dot(matrix.p4, lightSpace.ToLight(wsPoint));
    if (!(w > 0.0)) return std::numeric_limits<double>::infinity();
    if (lightSpace.IsPoint()) return w;
    return lightSpace.ToLight(wsPoint).z * lightSpace.Depth(wsPoint) / w;
}

namespace {

// wsBounds ∩ the map's frustum: u¹ ∈ [0, W], u² ∈ [0, H] with u^i = row_i / row_4 are the four
// half-spaces row_1 ≥ 0, W row_4 - row_1 ≥ 0, row_2 ≥ 0, H row_4 - row_2 ≥ 0, which together
// imply row_4 ≥ 0 (in front of the light).
ConvexPolyhedron CastersInMap(const LightSpace& lightSpace, const LightMatrix& matrix,
                              Resolution map, const Bounds& wsBounds) {
    const std::array<glm::dvec3, 8> c = wsBounds.Corners();  // bit k of i: coordinate k at hi
    ConvexPolyhedron body = FrustumPolyhedron({c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6]});
    const glm::dmat4 texel = MapFromWorld(lightSpace, matrix);
    const glm::dvec4 row1 = glm::row(texel, 0), row2 = glm::row(texel, 1),
                     rowW = glm::row(texel, 3);
    const double width = map.width, height = map.height;
    for (const glm::dvec4& plane : {row1, width * rowW - row1, row2, height * rowW - row2}) {
        body = ClipPolyhedron(body, plane);
        if (body.faces.empty()) break;
    }
    return body;
}

}  // namespace

DepthRange LightDepthRange(const LightSpace& lightSpace, const LightMatrix& matrix, Resolution map,
                           const Bounds& wsCasterBounds, std::span<const glm::dvec3> wsReceivers,
                           double margin) {
    if (wsReceivers.empty())
        throw std::invalid_argument("LightDepthRange: no receivers (the camera sees nothing)");
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
    for (const glm::dvec3& wsPoint : wsReceivers) {
        const double q = ClipDepthQuantity(lightSpace, matrix, wsPoint);
        if (!std::isfinite(q))
            throw std::invalid_argument("LightDepthRange: a receiver is behind the map's plane");
        nearest = std::min(nearest, q);
        farthest = std::max(farthest, q);
    }
    if (!wsCasterBounds.Empty())
        for (const glm::dvec3& wsVertex :
             CastersInMap(lightSpace, matrix, map, wsCasterBounds).Vertices())
            nearest = std::min(nearest, ClipDepthQuantity(lightSpace, matrix, wsVertex));
    // A span of at least kMinSpan of the depth: a floor facing the light puts every receiver and
    // caster at one depth, and ClipFromWorld needs near < far; float rounding of the points (1e-7
    // of them) stays inside it.
    constexpr double kMinSpan = 1e-3;
    const double minSpan = kMinSpan * std::max(std::abs(nearest), std::abs(farthest));
    if (farthest - nearest < minSpan) {
        const double middle = 0.5 * (nearest + farthest);
        nearest = middle - 0.5 * minSpan;
        farthest = middle + 0.5 * minSpan;
    }
    // Each end out by margin × the span; a point light's near stays above half the nearest
    // caster (perspective depth needs near > 0).
    const double grow = margin * (farthest - nearest);
    const double near = nearest - grow;
    return {lightSpace.IsPoint() ? std::max(near, 0.5 * nearest) : near, farthest + grow};
}

}  // namespace lexel::spatial
