// The GLSL 4.50 programs of the OpenGL backend: the camera pass, the shadow-map pass, the shading
// pass (ShadePoint's decision, render_backend.h) and the boundary-pixel extraction of report
// Algorithm 1 step 3 (samples.h). Uniform locations and bindings are fixed here and used by
// gl_renderer.cpp.
#pragma once

#include <string_view>

namespace lexel::spatial::gl::shaders {

// Both geometry passes: world positions through a 4×4 clip-from-world matrix.
inline constexpr std::string_view kGeometryVertex = R"(#version 450 core
layout(location = 0) in vec3 wsVertex;
layout(location = 0) uniform mat4 clipFromWorld;
out vec3 wsPoint;
void main() {
    wsPoint = wsVertex;
    gl_Position = clipFromWorld * vec4(wsVertex, 1.0);
}
)";

// The camera pass: per pixel the triangle (gl_PrimitiveID of the one draw call = the mesh's
// triangle index), the world point and the face normal turned towards the eye (as CpuRenderer).
inline constexpr std::string_view kCameraFragment = R"(#version 450 core
layout(location = 1) uniform vec3 wsEye;
layout(std430, binding = 0) readonly buffer FaceNormals { vec4 wsFaceNormal[]; };
in vec3 wsPoint;
layout(location = 0) out int triangle;
layout(location = 1) out vec4 position;
layout(location = 2) out vec4 normal;
void main() {
    vec3 n = wsFaceNormal[gl_PrimitiveID].xyz;
    if (dot(n, wsEye - wsPoint) < 0.0) n = -n;
    triangle = gl_PrimitiveID;
    position = vec4(wsPoint, 1.0);
    normal = vec4(n, 0.0);
}
)";

// The shadow-map pass: linear light depth (LightSpace::Depth) divided by a power of two, so that
// the stored float times that power is the depth the shader computed, bit for bit.
inline constexpr std::string_view kShadowFragment = R"(#version 450 core
layout(location = 1) uniform int pointLight;
layout(location = 2) uniform vec3 wsLight;      // point: the light; directional: its unit direction
layout(location = 3) uniform float depthOffset; // directional: Depth(0)
layout(location = 4) uniform float invDepthScale;
in vec3 wsPoint;
void main() {
    float depth = pointLight != 0 ? length(wsPoint - wsLight) : dot(wsLight, wsPoint) + depthOffset;
    gl_FragDepth = depth * invDepthScale;
}
)";

// ShadePoint per pixel of a camera buffer (render_backend.h): attached shadow, receiver-plane
// depth along the ray through the texel centre, relative bias 1e-5. Codes are those of Shade. A
// full-screen triangle: one fragment per pixel of the shade image.
inline constexpr std::string_view kFullScreenVertex = R"(#version 450 core
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // (0,0), (2,0), (0,2)
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
)";

inline constexpr std::string_view kShadeFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D shadowDepth;
layout(binding = 1) uniform isampler2D triangleImage;
layout(binding = 2) uniform sampler2D positionImage;
layout(binding = 3) uniform sampler2D normalImage;
layout(location = 0) uniform mat3 lsFromWorld;      // X = lsFromWorld p + lsOffset
layout(location = 1) uniform vec3 lsOffset;
layout(location = 2) uniform mat3 mapFromLs;        // rows p1, p2, p4
layout(location = 3) uniform mat3 lsFromMap;        // its inverse
layout(location = 4) uniform mat3 worldFromLs;      // ray directions (point) / offsets (directional)
layout(location = 5) uniform vec3 wsLight;          // point: the light; directional: ray base
layout(location = 6) uniform vec3 wsLightDirection; // directional: unit direction of travel
layout(location = 7) uniform float lsThird;         // directional: the fixed third coordinate s
layout(location = 8) uniform float depthOffset;     // directional: Depth(0)
layout(location = 9) uniform float depthScale;
layout(location = 10) uniform int pointLight;
layout(location = 11) uniform ivec2 mapSize;
layout(location = 0) out uint shade;
const uint kEmpty = 0u, kLit = 1u, kShadowed = 2u, kFacingAway = 3u;
const float kRelativeBias = 1e-5;

uint ShadeOf(ivec2 pixel) {
    if (texelFetch(triangleImage, pixel, 0).x < 0) return kEmpty;
    vec3 p = texelFetch(positionImage, pixel, 0).xyz;
    vec3 n = texelFetch(normalImage, pixel, 0).xyz;
    vec3 toLight = pointLight != 0 ? normalize(wsLight - p) : -wsLightDirection;
    if (!(dot(n, toLight) > 0.0)) return kFacingAway;
    vec3 X = lsFromWorld * p + lsOffset;
    vec3 h = mapFromLs * X;
    if (!(h.z > 1e-9 * length(X))) return kLit;
    vec2 u = h.xy / h.z;
    if (!(u.x >= 0.0 && u.y >= 0.0 && u.x < float(mapSize.x) && u.y < float(mapSize.y)))
        return kLit;
    ivec2 texel = ivec2(u);
    float stored = texelFetch(shadowDepth, texel, 0).x;
    if (stored >= 1.0) return kLit;  // cleared: nothing drawn there
    stored *= depthScale;
    vec3 lsCentre = lsFromMap * vec3(vec2(texel) + 0.5, 1.0);
    vec3 origin, direction;
    float receiver;
    if (pointLight != 0) {
        origin = wsLight;
        direction = normalize(worldFromLs * lsCentre);
        receiver = length(p - wsLight);
    } else {
        origin = wsLight + (lsThird / lsCentre.z) * (worldFromLs * lsCentre);
        direction = wsLightDirection;
        receiver = dot(wsLightDirection, p) + depthOffset;
    }
    float facing = dot(n, direction);
    if (facing != 0.0) {
        float t = dot(n, p - origin) / facing;
        if (t > 0.0 && !isinf(t)) receiver = t;
    }
    return stored < receiver * (1.0 - kRelativeBias) ? kShadowed : kLit;
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
