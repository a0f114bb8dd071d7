// The mesh pieces the warped shadow pass draws (warp_shaders.h). Hardware tessellation cuts a
// patch edge into at most GL_MAX_TESS_GEN_LEVEL (≥ 64) segments, so a triangle much larger than
// the map — a floor reaching far beyond the visible points a focused map covers — would be cut
// into segments tens of warped texels long where it crosses the map, and the warp's bends between
// their ends lost. So before the pass, each triangle that overlaps the map and has a warped edge
// longer than maxEdgeTexels (the level limit × the pass's segment length) is split into four at
// its edges' midpoints, recursively, at most kMaxWarpSplits times; pieces off the map stay whole.
// Every piece keeps its triangle's index (its plane gives the stored depth).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/map_warp.h"

namespace lexel::spatial::gl {

inline constexpr int kMaxWarpSplits = 10;

struct WarpPieces {
    std::vector<glm::vec3> unitVertices;  // three per piece, the mesh's unit frame
    std::vector<std::int32_t> triangle;   // per piece: the mesh triangle it lies on
    // Per piece: its longest warped edge in texels (+inf with a vertex behind the light's plane),
    // from which the pass's tessellation level follows (WarpDrawBatches).
    std::vector<double> longestEdge;
};

// Where the warped pass cuts its draw into several: the first piece of each batch, then the
// piece count. A batch holds consecutive pieces whose tessellated triangles (about level² for a
// piece tessellated at level ceil(longestEdge / segmentTexels), at most maxLevel) sum to at most
// kMaxTessTrianglesPerDraw, or one piece. Mesa's llvmpipe silently drops most of a draw's
// tessellated output beyond a few hundred thousand triangles (measured on the walkthrough: 32
// pieces at level 64 per draw render the whole map, 64 lose 1,092 of its 160,000 texels, one draw
// of all 120,117); no GL limit says so, so the pass stays under it on every driver.
inline constexpr double kMaxTessTrianglesPerDraw = 65536.0;
std::vector<std::size_t> WarpDrawBatches(std::span<const double> longestEdge, double segmentTexels,
                                         double maxLevel);

// `clipFromUnit` is the base matrix's clip map of unit-frame points (x_ndc = 2 b / W − 1 in base
// texels b, as ClipFromWorld); `warp` maps base texels to the map's. A triangle with a vertex
// behind the light's plane (clip w ≤ 0) is not split: GL clips it, and the warp of its pieces
// near that plane is approximate.
WarpPieces RefineForWarp(std::span<const glm::vec3> unitPositions,
                         std::span<const glm::uvec3> triangles, const glm::dmat4& clipFromUnit,
                         const MapWarp& warp, Resolution map, double maxEdgeTexels);

}  // namespace lexel::spatial::gl
