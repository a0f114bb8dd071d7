// The GLSL 4.50 program of the warped shadow-map pass (GlRenderer::RenderWarpedShadowMap):
// rectilinear texture warping's map rendered as Rosen renders it (P. Rosen, "Rectilinear Texture
// Warping for Fast Adaptive Shadow Mapping", I3D 2012, §4.3): the geometry tessellated so finely
// that the warp, applied to each tessellated vertex, bends its triangles as the map bends space.
//   - the tessellation control stage sets each patch edge's level from its length on the warped
//     map: ceil(texels / segmentTexels), at most maxLevel (GL_MAX_TESS_GEN_LEVEL);
//   - the evaluation stage interpolates the patch's unit-frame vertices, maps the point through
//     the base matrix (its clip coordinates, as the linear shadow pass) and warps the base texel
//     coordinates b by the piecewise-linear axis warps (the knots in a buffer): u = φ(b) + δ;
//     clip = (ndc(u) · w, z, w), so GL clips and clamps exactly as in the linear pass;
//   - the fragment stage stores what every shadow map stores: the linear light depth along the
//     texel centre's ray (warp.Inverse of the texel centre: the base coordinates of each column
//     and row centre, in double, in a second buffer) to the patch's triangle plane, in double.
// Where the tessellated triangles' straight edges miss the warp's curve the GPU map's coverage
// differs from the ray-cast map's (measured: gl_tests, GlTest.Rtw*).
#pragma once

#include <string_view>

#include "lexel/spatial/gl/shaders.h"

namespace lexel::spatial::gl::shaders {

// The pieces (warp_refinement.h) are drawn unindexed, three vertices each, and piece k's mesh
// triangle is pieceTriangle[k], k = gl_VertexID / 3 (gl_PrimitiveID of a patch gave other
// triangles' ids on Mesa's llvmpipe).
inline constexpr std::string_view kWarpVertex = R"(#version 450 core
layout(location = 0) in vec3 unitVertex;
layout(std430, binding = 6) readonly buffer PieceTriangles { int pieceTriangle[]; };
out vec3 vsUnit;
flat out int vsTriangle;
void main() {
    vsUnit = unitVertex;
    vsTriangle = pieceTriangle[gl_VertexID / 3];
}
)";

// Shared by the control and evaluation stages: the base clip map and the axis warps.
#define LEXEL_WARP_FUNCTIONS                                                                 \
    "layout(location = 0) uniform mat4 clipFromUnit;\n"                                      \
    "layout(location = 1) uniform vec2 mapSize;\n"                                           \
    "layout(location = 2) uniform ivec2 knotCount;\n"                                        \
    "layout(location = 3) uniform vec4 knotRange;\n"                                         \
    "layout(location = 4) uniform vec2 phase;\n"                                             \
    "layout(std430, binding = 4) readonly buffer WarpKnots { float knot[]; };\n"             \
    "float WarpAxis(float b, int first, int count, float lo, float hi) {\n"                  \
    "    float step = (hi - lo) / float(count - 1);\n"                                       \
    "    float t = (b - lo) / step;\n"                                                       \
    "    float i = clamp(floor(t), 0.0, float(count - 2));\n"                                \
    "    int k = first + int(i);\n"                                                          \
    "    return knot[k] + (t - i) * (knot[k + 1] - knot[k]);\n"                              \
    "}\n"                                                                                    \
    "vec2 WarpedTexel(vec4 clip) {\n"                                                        \
    "    vec2 b = (clip.xy / clip.w + 1.0) * 0.5 * mapSize;\n"                               \
    "    return vec2(WarpAxis(b.x, 0, knotCount.x, knotRange.x, knotRange.y),\n"             \
    "                WarpAxis(b.y, knotCount.x, knotCount.y, knotRange.z, knotRange.w)) +\n" \
    "           phase;\n"                                                                    \
    "}\n"

inline constexpr std::string_view kWarpControl =
    "#version 450 core\n"
    "layout(vertices = 3) out;\n"
    "in vec3 vsUnit[];\n"
    "flat in int vsTriangle[];\n"
    "out vec3 tcsUnit[];\n"
    "patch out int patchTriangle;\n"
    "layout(location = 5) uniform float segmentTexels;\n"
    "layout(location = 6) uniform float maxLevel;\n" LEXEL_WARP_FUNCTIONS R"(
float Level(vec2 a, vec2 b, bool inFront) {
    if (!inFront) return maxLevel;
    return clamp(ceil(length(a - b) / segmentTexels), 1.0, maxLevel);
}
void main() {
    tcsUnit[gl_InvocationID] = vsUnit[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    patchTriangle = vsTriangle[0];
    vec2 u[3];
    bool inFront = true;
    for (int k = 0; k < 3; ++k) {
        vec4 c = clipFromUnit * vec4(vsUnit[k], 1.0);
        inFront = inFront && c.w > 0.0;
        u[k] = WarpedTexel(c);
    }
    // Off the map (the warped curves stay in their ends' box): no triangle at all.
    vec2 lo = min(u[0], min(u[1], u[2])), hi = max(u[0], max(u[1], u[2]));
    if (inFront && (hi.x < -1.0 || hi.y < -1.0 || lo.x > mapSize.x + 1.0 ||
                    lo.y > mapSize.y + 1.0)) {
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
        gl_TessLevelInner[0] = 0.0;
        return;
    }
    gl_TessLevelOuter[0] = Level(u[1], u[2], inFront);
    gl_TessLevelOuter[1] = Level(u[2], u[0], inFront);
    gl_TessLevelOuter[2] = Level(u[0], u[1], inFront);
    gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1],
                                                         gl_TessLevelOuter[2]));
}
)";

inline constexpr std::string_view kWarpEvaluation =
    "#version 450 core\n"
    "layout(triangles, equal_spacing, ccw) in;\n"
    "in vec3 tcsUnit[];\n"
    "patch in int patchTriangle;\n"
    "out vec3 unitPoint;\n"
    "flat out int triangleId;\n" LEXEL_WARP_FUNCTIONS R"(
void main() {
    vec3 p = gl_TessCoord.x * tcsUnit[0] + gl_TessCoord.y * tcsUnit[1] +
             gl_TessCoord.z * tcsUnit[2];
    unitPoint = p;
    triangleId = patchTriangle;
    vec4 c = clipFromUnit * vec4(p, 1.0);
    vec2 ndc = 2.0 * WarpedTexel(c) / mapSize - 1.0;
    gl_Position = vec4(ndc * c.w, c.z, c.w);
}
)";

inline constexpr std::string_view kWarpFragment =
    "#version 450 core\n"
    "layout(std430, binding = 2) readonly buffer FacePlanes { dvec4 wsFacePlane[]; };\n"
    "layout(std430, binding = 5) readonly buffer TexelBase { double texelBase[]; };\n"
    "layout(location = 7) uniform double invDepthScale;\n"
    "layout(location = 8) uniform int mapWidth;\n"
    "in vec3 unitPoint;\n"
    "flat in int triangleId;\n" LEXEL_LIGHT_UNIFORMS R"(
void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    dvec3 origin, direction;
    LightRay(dvec2(texelBase[t.x], texelBase[mapWidth + t.y]), origin, direction);
    double depth =
        FacePlaneDepth(wsFacePlane[triangleId], WorldPoint(unitPoint), origin, direction);
    gl_FragDepth = float(depth * invDepthScale);
}
)";

}  // namespace lexel::spatial::gl::shaders
