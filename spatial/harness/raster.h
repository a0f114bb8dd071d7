// A deterministic scanline-free triangle rasterizer for any projective view (the camera's Q or a
// light matrix P): the CPU reference for the passes of report Algorithm 1 and §3.
//
// A view is given by a 3×4 map from homogeneous world points to homogeneous image points
// (x·w, y·w, w), x and y in pixels. Triangles are clipped against w ≥ wMin (points behind the
// camera or the light's plane p4·X = 0 never map), projected, and every pixel centre inside is
// visited with the exact world point under it: for a projective map the perspective-correct
// barycentrics λ_i = (e_i/w_i) / Σ_j (e_j/w_j), with e_i the screen-space edge functions, give the
// point on the triangle whose image is the pixel centre exactly (Heckbert & Moreton 1995). The
// nearest point by a caller-chosen depth wins; ties go to the lower triangle index, so the result
// does not depend on the order in which threads visit triangles.
//
// Coverage follows the top-left rule on edge functions evaluated canonically (endpoints ordered
// lexicographically, sign flipped afterwards), so a pixel centre on an edge shared by two
// triangles belongs to exactly one of them: shared edges neither leak nor double-cover.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <vector>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// Rows 1, 2 and 4 of a 4×4 view matrix as one 3×4 (glm: 4 columns of dvec3).
using ImageFromWorld = glm::dmat4x3;

ImageFromWorld ImageRows(const glm::dmat4& m);  // rows 0, 1, 3 of m

// The result of a pass: per pixel the nearest depth key (+inf where nothing), the triangle
// (-1 where nothing) and the world point.
struct RasterBuffer {
    Resolution resolution;
    std::vector<double> depth;
    std::vector<std::int32_t> triangle;
    std::vector<glm::dvec3> wsPoint;
};

namespace raster_detail {

struct ClipVertex {
    glm::dvec3 image;     // (x·w, y·w, w)
    glm::dvec3 world;     // the world point
    glm::dvec3 relative;  // the same relative to the view origin
};

// Sutherland–Hodgman against the single plane w ≥ wMin; at most 4 vertices out.
inline int ClipNear(const std::array<ClipVertex, 3>& in, double wMin, ClipVertex* out) {
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const ClipVertex& a = in[i];
        const ClipVertex& b = in[(i + 1) % 3];
        const bool aIn = a.image.z >= wMin, bIn = b.image.z >= wMin;
        if (aIn) out[n++] = a;
        if (aIn != bIn) {
            const double t = (wMin - a.image.z) / (b.image.z - a.image.z);
            out[n++] = {a.image + t * (b.image - a.image), a.world + t * (b.world - a.world),
                        a.relative + t * (b.relative - a.relative)};
        }
    }
    return n;
}

// Edge function of (a, b) at p, evaluated with the endpoints in canonical order so that the
// shared edge of two triangles gives exactly opposite values.
inline double Edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    const bool swap = (b.x < a.x) || (b.x == a.x && b.y < a.y);
    const glm::dvec2& lo = swap ? b : a;
    const glm::dvec2& hi = swap ? a : b;
    const double e = (hi.x - lo.x) * (p.y - lo.y) - (hi.y - lo.y) * (p.x - lo.x);
    return swap ? -e : e;
}

// Top-left rule for counter-clockwise triangles in a y-down image: an edge owns the pixel centres
// exactly on it when it is a "top" edge (horizontal, pointing left... in y-down CCW-as-seen
// orientation) or a "left" edge. Expressed on the edge vector d = b - a of a positively oriented
// triangle (Edge > 0 inside).
inline bool OwnsTies(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 d = b - a;
    return d.y < 0.0 || (d.y == 0.0 && d.x > 0.0);
}

}  // namespace raster_detail

// Rasterizes `mesh` through `view` into `buffer` (which must be sized and initialised: depth
// +inf, triangle -1). `view` maps homogeneous points relative to wsViewOrigin, x - wsViewOrigin,
// and DepthFn(const glm::dvec3& relative) → double gives the depth key (smaller is nearer) of
// the point under a pixel centre so relative; the buffer keeps the world point, interpolated from
// the world vertices (so a point of a plane y = 0 has y = 0 exactly). With the eye as the view
// origin a scene far from the world's origin keeps its digits in the image position and the
// depth: no large translation cancels, and their rounding is relative to the distance from the
// eye, not from the origin. wMin > 0 is the clip distance in the units of w. Parallel over bands
// of rows.
template <class DepthFn>
void RasterizeNearest(const TriangleMesh& mesh, const ImageFromWorld& view, double wMin,
                      const DepthFn& depthOf, RasterBuffer* buffer,
                      const glm::dvec3& wsViewOrigin = glm::dvec3(0.0)) {
    using namespace raster_detail;
    const Resolution res = buffer->resolution;
    constexpr int kBandRows = 16;
    const int bandCount = (res.height + kBandRows - 1) / kBandRows;

    // Project and clip once; remember each piece's pixel-row span to bin it into bands.
    struct Piece {
        std::array<glm::dvec2, 3> xy;
        std::array<double, 3> invW;
        std::array<glm::dvec3, 3> world, relative;
        glm::dvec2 lo, hi;
        std::int32_t triangle;
    };
    std::vector<Piece> pieces;
    pieces.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::array<ClipVertex, 3> v;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& ws = mesh.positions[mesh.triangles[t][k]];
            const glm::dvec3 relative = ws - wsViewOrigin;
            v[k] = {view * glm::dvec4(relative, 1.0), ws, relative};
        }
        ClipVertex clipped[4];
        const int n = ClipNear(v, wMin, clipped);
        for (int f = 1; f + 1 < n; ++f) {
            Piece p;
            const ClipVertex* c[3] = {&clipped[0], &clipped[f], &clipped[f + 1]};
            for (int k = 0; k < 3; ++k) {
                p.invW[k] = 1.0 / c[k]->image.z;
                p.xy[k] = glm::dvec2(c[k]->image) * p.invW[k];
                p.world[k] = c[k]->world;
                p.relative[k] = c[k]->relative;
            }
            // Orient counter-clockwise in the image (Edge > 0 inside); drop degenerate ones.
            double area = Edge(p.xy[0], p.xy[1], p.xy[2]);
            if (area < 0.0) {
                std::swap(p.xy[1], p.xy[2]);
                std::swap(p.invW[1], p.invW[2]);
                std::swap(p.world[1], p.world[2]);
                std::swap(p.relative[1], p.relative[2]);
                area = -area;
            }
            if (!(area > 0.0)) continue;
            p.lo = glm::min(p.xy[0], glm::min(p.xy[1], p.xy[2]));
            p.hi = glm::max(p.xy[0], glm::max(p.xy[1], p.xy[2]));
            if (p.hi.x < 0.0 || p.hi.y < 0.0 || p.lo.x > res.width || p.lo.y > res.height) continue;
            // Clamp before any integer conversion: a vertex near w = wMin maps far outside.
            p.lo = glm::clamp(p.lo, glm::dvec2(-1.0), glm::dvec2(res.width + 1, res.height + 1));
            p.hi = glm::clamp(p.hi, glm::dvec2(-1.0), glm::dvec2(res.width + 1, res.height + 1));
            p.triangle = static_cast<std::int32_t>(t);
            pieces.push_back(p);
        }
    }
    std::vector<std::vector<std::uint32_t>> bands(bandCount);
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
        const int b0 = std::max(0, static_cast<int>(std::floor(pieces[i].lo.y - 0.5)) / kBandRows);
        const int b1 =
            std::min(bandCount - 1, static_cast<int>(std::ceil(pieces[i].hi.y - 0.5)) / kBandRows);
        for (int b = b0; b <= b1; ++b) bands[b].push_back(i);
    }

    tbb::parallel_for(0, bandCount, [&](int band) {
        const int rowLo = band * kBandRows, rowHi = std::min(res.height, rowLo + kBandRows);
        for (std::uint32_t index : bands[band]) {
            const Piece& p = pieces[index];
            const int x0 = std::max(0, static_cast<int>(std::ceil(p.lo.x - 0.5)));
            const int x1 = std::min(res.width - 1, static_cast<int>(std::floor(p.hi.x - 0.5)));
            const int y0 = std::max(rowLo, static_cast<int>(std::ceil(p.lo.y - 0.5)));
            const int y1 = std::min(rowHi - 1, static_cast<int>(std::floor(p.hi.y - 0.5)));
            const bool owns[3] = {OwnsTies(p.xy[1], p.xy[2]), OwnsTies(p.xy[2], p.xy[0]),
                                  OwnsTies(p.xy[0], p.xy[1])};
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    const glm::dvec2 c(x + 0.5, y + 0.5);
                    const double e[3] = {Edge(p.xy[1], p.xy[2], c), Edge(p.xy[2], p.xy[0], c),
                                         Edge(p.xy[0], p.xy[1], c)};
                    bool inside = true;
                    for (int k = 0; k < 3; ++k)
                        inside = inside && (e[k] > 0.0 || (e[k] == 0.0 && owns[k]));
                    if (!inside) continue;
                    const double b0 = e[0] * p.invW[0], b1 = e[1] * p.invW[1],
                                 b2 = e[2] * p.invW[2];
                    const double sum = b0 + b1 + b2;
                    const glm::dvec3 relative =
                        (b0 * p.relative[0] + b1 * p.relative[1] + b2 * p.relative[2]) / sum;
                    const double key = depthOf(relative);
                    const std::size_t at = static_cast<std::size_t>(y) * res.width + x;
                    if (key < buffer->depth[at] ||
                        (key == buffer->depth[at] && p.triangle < buffer->triangle[at])) {
                        buffer->depth[at] = key;
                        buffer->triangle[at] = p.triangle;
                        buffer->wsPoint[at] =
                            (b0 * p.world[0] + b1 * p.world[1] + b2 * p.world[2]) / sum;
                    }
                }
            }
        }
    });
}

RasterBuffer MakeRasterBuffer(Resolution resolution);

}  // namespace lexel::spatial
