// The GLSL 4.50 programs of the OpenGL backend: the camera pass, the shadow-map pass, the shading
// pass (ShadePoint's decision, render_backend.h) and the boundary-pixel extraction of report
// Algorithm 1 step 3 (samples.h). Uniform locations and bindings are fixed here and used by
// gl_renderer.cpp.
#pragma once

#include <string_view>

namespace lexel::spatial::gl::shaders {

// Both geometry passes: positions in the mesh's unit frame (scene.h: centred on its bounds and
// scaled to unit size, so a float carries ~1e-7 of the scene whatever its size and position)
// through a 4×4 clip-from-unit matrix.
inline constexpr std::string_view kGeometryVertex = R"(#version 450 core
layout(location = 0) in vec3 unitVertex;
layout(location = 0) uniform mat4 clipFromUnit;
out vec3 unitPoint;
void main() {
    unitPoint = unitVertex;
    gl_Position = clipFromUnit * vec4(unitVertex, 1.0);
}
)";

// The camera pass: per pixel the triangle (gl_PrimitiveID of the one draw call = the mesh's
// triangle index), the point in the unit frame and the face normal turned towards the eye (as
// CpuRenderer; the frame is a translation and a positive scale, so normals are the world's).
inline constexpr std::string_view kCameraFragment = R"(#version 450 core
layout(location = 1) uniform vec3 unitEye;
layout(std430, binding = 0) readonly buffer FaceNormals { vec4 wsFaceNormal[]; };
in vec3 unitPoint;
layout(location = 0) out int triangle;
layout(location = 1) out vec4 position;
layout(location = 2) out vec4 normal;
void main() {
    vec3 n = wsFaceNormal[gl_PrimitiveID].xyz;
    if (dot(n, unitEye - unitPoint) < 0.0) n = -n;
    triangle = gl_PrimitiveID;
    position = vec4(unitPoint, 1.0);
    normal = vec4(n, 0.0);
}
)";

// The light and its matrix in double (GLSL 4.00 fp64, core since OpenGL 4.0), shared by the
// shadow and shading passes: X = lsFromWs p + lsOffset, u = (mapFromLs X).xy / (mapFromLs X).z,
// and the light ray through the texel centre c: from wsLight (point) or from
// wsLight + (lsThird / X.z) wsFromLs X (directional), along normalize(wsFromLs X) (point)
// or wsLightDirection (directional), X = lsFromMap (c, 1). In float the ray's direction carries
// ~1e-7 relative error, which a grazing receiver turns into more than the 1e-5 bias. WorldPoint
// takes a unit-frame float point back to world coordinates in double.
#define LEXEL_LIGHT_UNIFORMS                                                                    \
    "layout(location = 10) uniform int pointLight;\n"                                           \
    "layout(location = 11) uniform dmat3 lsFromWs;\n"                                           \
    "layout(location = 12) uniform dvec3 lsOffset;\n"                                           \
    "layout(location = 13) uniform dmat3 mapFromLs;\n"                                          \
    "layout(location = 14) uniform dmat3 lsFromMap;\n"                                          \
    "layout(location = 15) uniform dmat3 wsFromLs;\n"                                           \
    "layout(location = 16) uniform dvec3 wsLight;\n"                                            \
    "layout(location = 17) uniform dvec3 wsLightDirection;\n"                                   \
    "layout(location = 18) uniform double lsThird;\n"                                           \
    "layout(location = 19) uniform double depthOffset;\n"                                       \
    "layout(location = 20) uniform dvec3 wsUnitOrigin;\n"                                       \
    "layout(location = 21) uniform double wsUnitScale;\n"                                       \
    "dvec3 WorldPoint(vec3 unitPoint) {\n"                                                      \
    "    return wsUnitOrigin + wsUnitScale * dvec3(unitPoint);\n"                               \
    "}\n"                                                                                       \
    "void LightRay(dvec2 texelCentre, out dvec3 origin, out dvec3 direction) {\n"               \
    "    dvec3 X = lsFromMap * dvec3(texelCentre, 1.0);\n"                                      \
    "    if (pointLight != 0) {\n"                                                              \
    "        origin = wsLight;\n"                                                               \
    "        direction = normalize(wsFromLs * X);\n"                                            \
    "    } else {\n"                                                                            \
    "        origin = wsLight + (lsThird / X.z) * (wsFromLs * X);\n"                            \
    "        direction = wsLightDirection;\n"                                                   \
    "    }\n"                                                                                   \
    "}\n"                                                                                       \
    "// The shadow-map passes' depth: along the ray to the face plane n·x = w, or where the\n" \
    "// ray misses it (a degenerate triangle's) the fragment's own depth along the ray.\n"      \
    "double FacePlaneDepth(dvec4 plane, dvec3 point, dvec3 origin, dvec3 direction) {\n"        \
    "    double depth = dot(point - origin, direction);\n"                                      \
    "    double facing = dot(plane.xyz, direction);\n"                                          \
    "    if (facing != 0.0) {\n"                                                                \
    "        double t = (plane.w - dot(plane.xyz, origin)) / facing;\n"                         \
    "        if (t > 0.0 && !isinf(t)) depth = t;\n"                                            \
    "    }\n"                                                                                   \
    "    return depth;\n"                                                                       \
    "}\n"

// The receiver-plane depth test (spatial/harness/receiver_plane.h, whose C++ this text mirrors
// line for line; tests/spatial/gl/receiver_plane_test.cpp holds the two equal): the depth of the
// receiver's plane (normal n through p) along the light ray through the texel centre c (map
// coordinates), and the comparison with the stored depth. The shade codes are those of Shade.
#define LEXEL_RECEIVER_PLANE_TEST                                                                  \
    "const uint kEmpty = 0u, kLit = 1u, kShadowed = 2u, kFacingAway = 3u;\n"                       \
    "const double kRelativeBias = 1e-5;\n"                                                         \
    "double ReceiverPlaneDepth(dvec2 texelCentre, dvec3 p, dvec3 n) {\n"                           \
    "    dvec3 origin, direction;\n"                                                               \
    "    LightRay(texelCentre, origin, direction);\n"                                              \
    "    double facing = dot(n, direction);\n"                                                     \
    "    if (facing != 0.0) {\n"                                                                   \
    "        double t = dot(n, p - origin) / facing;\n"                                            \
    "        if (t > 0.0 && !isinf(t)) return t;\n"                                                \
    "    }\n"                                                                                      \
    "    return pointLight != 0 ? length(p - wsLight) : dot(wsLightDirection, p) + depthOffset;\n" \
    "}\n"                                                                                          \
    "uint CompareWithTexel(double storedDepth, double receiverDepth) {\n"                          \
    "    return storedDepth < receiverDepth * (1.0 - kRelativeBias) ? kShadowed : kLit;\n"         \
    "}\n"

// The shadow-map pass: linear light depth (LightSpace::Depth) at the texel centre — the distance
// along the light ray through the texel centre to the fragment's triangle plane (n·x = d, from
// the mesh in double), as the CPU renderer computes it at the exact point — divided by a power of
// two, so that the stored float times that power is the depth the shader computed. Interpolating
// the world point in float instead loses the 1e-5 bias on strongly warped maps (measured:
// plane-optimal for a sweep light with p4 · e3 = 0.045: 1,496 texels off by more than 1e-5 and
// 162,000 pixels decided otherwise), and a float plane through the interpolated point loses it
// at grazing angles (the off-plane rounding divided by n · direction).
inline constexpr std::string_view kShadowFragment =
    "#version 450 core\n"
    "layout(std430, binding = 2) readonly buffer FacePlanes { dvec4 wsFacePlane[]; };\n"
    "layout(location = 4) uniform double invDepthScale;\n"
    "in vec3 unitPoint;\n" LEXEL_LIGHT_UNIFORMS R"(
void main() {
    dvec3 origin, direction;
    LightRay(dvec2(gl_FragCoord.xy), origin, direction);
    double depth =
        FacePlaneDepth(wsFacePlane[gl_PrimitiveID], WorldPoint(unitPoint), origin, direction);
    gl_FragDepth = float(depth * invDepthScale);
}
)";

// ShadePoint per pixel of a camera buffer (render_backend.h): attached shadow, then the
// receiver-plane depth test. A full-screen triangle: one fragment per pixel of the shade image.
inline constexpr std::string_view kFullScreenVertex = R"(#version 450 core
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // (0,0), (2,0), (0,2)
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
)";

inline constexpr std::string_view kShadeFragment =
    "#version 450 core\n"
    "layout(binding = 0) uniform sampler2D shadowDepth;\n"
    "layout(binding = 1) uniform isampler2D triangleImage;\n"
    "layout(binding = 2) uniform sampler2D positionImage;\n"
    "layout(binding = 3) uniform sampler2D normalImage;\n"
    "layout(location = 0) uniform double depthScale;\n"
    "layout(location = 1) uniform ivec2 mapSize;\n"
    "layout(location = 0) out uint shade;\n" LEXEL_LIGHT_UNIFORMS LEXEL_RECEIVER_PLANE_TEST R"(

uint ShadeOf(ivec2 pixel) {
    if (texelFetch(triangleImage, pixel, 0).x < 0) return kEmpty;
    dvec3 p = WorldPoint(texelFetch(positionImage, pixel, 0).xyz);
    dvec3 n = dvec3(texelFetch(normalImage, pixel, 0).xyz);
    dvec3 toLight = pointLight != 0 ? normalize(wsLight - p) : -wsLightDirection;
    if (!(dot(n, toLight) > 0.0)) return kFacingAway;
    dvec3 X = lsFromWs * p + lsOffset;
    dvec3 h = mapFromLs * X;
    if (!(h.z > 1e-9 * length(X))) return kLit;
    dvec2 u = h.xy / h.z;
    if (!(u.x >= 0.0 && u.y >= 0.0 && u.x < double(mapSize.x) && u.y < double(mapSize.y)))
        return kLit;
    ivec2 texel = ivec2(u);
    float stored = texelFetch(shadowDepth, texel, 0).x;
    if (stored >= 1.0) return kLit;  // cleared: nothing drawn there
    return CompareWithTexel(double(stored) * depthScale,
                            ReceiverPlaneDepth(dvec2(texel) + 0.5, p, n));
}

void main() { shade = ShadeOf(ivec2(gl_FragCoord.xy)); }
)";

// Report Algorithm 1 step 3: the boundary pixels (a lit or shadowed receiver with an 8-neighbour
// lit or shadowed the other way, as BoundaryPixels in samples.h), appended in any order.
inline constexpr std::string_view kBoundaryCompute = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 3, r8ui) readonly uniform uimage2D shadeImage;
layout(std430, binding = 1) buffer Boundary { uint count; uint pixel[]; };
void main() {
    ivec2 size = imageSize(shadeImage);
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, size))) return;
    uint here = imageLoad(shadeImage, q).x;
    if (here != 1u && here != 2u) return;
    bool boundary = false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 r = q + ivec2(dx, dy);
            if (any(lessThan(r, ivec2(0))) || any(greaterThanEqual(r, size))) continue;
            uint there = imageLoad(shadeImage, r).x;
            boundary = boundary || ((there == 1u || there == 2u) && there != here);
        }
    if (boundary) pixel[atomicAdd(count, 1u)] = uint(q.y * size.x + q.x);
}
)";

}  // namespace lexel::spatial::gl::shaders
