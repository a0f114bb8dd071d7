// The receiver-plane depth test exists once in C++ (spatial/harness/receiver_plane.h) and once
// in GLSL (LEXEL_RECEIVER_PLANE_TEST, spatial/gl/shaders.h). A compute shader evaluates the GLSL
// text with the uniforms every shading pass sets (light_uniforms.h) on seeded random receivers
// for a point and a directional light behind a projective map; the C++ evaluates the same
// receivers. They must give the same receiver depth (relative 1e-12: two fp64 evaluations of one
// formula) and the same decision for a stored depth 1e-8 (relative) on either side of the
// threshold receiverDepth · (1 − kRelativeBias), so a different bias, plane or ray in either
// language fails. Receivers whose plane the ray meets behind its start take the fallback, the
// receiver's own depth, in both.
#include "lexel/spatial/harness/receiver_plane.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "lexel/spatial/gl/context.h"
#include "lexel/spatial/gl/light_uniforms.h"
#include "lexel/spatial/gl/program.h"
#include "lexel/spatial/gl/shaders.h"
#include "spatial/gl/gl_test_support.h"

namespace lexel::spatial {
namespace {

using testing::GlTest;

// Per receiver, 9 doubles in: p (3), n (3), texel centre c (2, map coordinates), stored depth;
// out: the GLSL receiver depth and decision.
constexpr const char* kKernel = R"(
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Receivers { double receiver[]; };
layout(std430, binding = 1) writeonly buffer Depths { double depthOut[]; };
layout(std430, binding = 2) writeonly buffer Shades { uint shadeOut[]; };
layout(location = 0) uniform uint count;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count) return;
    uint b = 9u * i;
    dvec3 p = dvec3(receiver[b], receiver[b + 1u], receiver[b + 2u]);
    dvec3 n = dvec3(receiver[b + 3u], receiver[b + 4u], receiver[b + 5u]);
    dvec2 c = dvec2(receiver[b + 6u], receiver[b + 7u]);
    double depth = ReceiverPlaneDepth(c, p, n);
    depthOut[i] = depth;
    shadeOut[i] = CompareWithTexel(receiver[b + 8u], depth);
}
)";

struct Receiver {
    glm::dvec3 wsPoint, wsNormal;
    glm::dvec2 texelCentre;
    double stored = 0.0;
};

// Receivers near the ray through a random texel centre of a 400² map, at depths 1–20 along it,
// with random normals; every fifth one's plane behind the ray's start (the fallback). Stored
// depths 1e-8 (relative) either side of the C++ threshold, alternately.
std::vector<Receiver> RandomReceivers(const LightSpace& lightSpace, const LightMatrix& matrix,
                                      std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), texel(0.0, 400.0), depth(1.0, 20.0);
    const glm::dmat3 lsFromMap = glm::inverse(matrix.Rows());
    std::vector<Receiver> receivers;
    for (int k = 0; k < 500; ++k) {
        Receiver r;
        r.texelCentre = glm::floor(glm::dvec2(texel(rng), texel(rng))) + 0.5;
        const glm::dvec3 lsX = lsFromMap * glm::dvec3(r.texelCentre, 1.0);
        glm::dvec3 wsOrigin, wsDirection;
        lightSpace.Ray(lsX, &wsOrigin, &wsDirection);
        const glm::dvec3 jitter = 0.01 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        r.wsNormal = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        r.wsPoint = wsOrigin + depth(rng) * wsDirection + jitter;
        if (k % 5 == 4) {  // the plane meets the ray before its start
            r.wsNormal = wsDirection;
            r.wsPoint = wsOrigin - 0.5 * wsDirection + jitter;
        }
        const double receiverDepth = ReceiverPlaneDepth(lightSpace, lsX, r.wsPoint, r.wsNormal);
        r.stored = receiverDepth * (1.0 - kRelativeBias) * (k % 2 == 0 ? 1.0 - 1e-8 : 1.0 + 1e-8);
        receivers.push_back(r);
    }
    return receivers;
}

struct GlResult {
    std::vector<double> depth;
    std::vector<std::uint32_t> shade;
};

GLuint Buffer(const void* data, std::size_t bytes, GLuint binding) {
    GLuint b = 0;
    glCreateBuffers(1, &b);
    glNamedBufferStorage(b, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_STORAGE_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, b);
    return b;
}

GlResult EvaluateInGlsl(const LightSpace& lightSpace, const LightMatrix& matrix,
                        const std::vector<Receiver>& receivers) {
    const gl::CurrentContext current(gl::Context::Shared());
    const std::string source = std::string("#version 450 core\n") + LEXEL_LIGHT_UNIFORMS +
                               LEXEL_RECEIVER_PLANE_TEST + kKernel;
    const GLuint program = gl::BuildProgram({{GL_COMPUTE_SHADER, source}});
    gl::SetLightUniforms(program, lightSpace, matrix, UnitFrame{});
    const auto n = static_cast<GLuint>(receivers.size());
    glProgramUniform1ui(program, 0, n);
    std::vector<double> in;
    for (const Receiver& r : receivers)
        in.insert(in.end(), {r.wsPoint.x, r.wsPoint.y, r.wsPoint.z, r.wsNormal.x, r.wsNormal.y,
                             r.wsNormal.z, r.texelCentre.x, r.texelCentre.y, r.stored});
    GlResult out{std::vector<double>(n), std::vector<std::uint32_t>(n)};
    const GLuint buffers[] = {Buffer(in.data(), in.size() * sizeof(double), 0),
                              Buffer(nullptr, n * sizeof(double), 1),
                              Buffer(nullptr, n * sizeof(std::uint32_t), 2)};
    glUseProgram(program);
    glDispatchCompute((n + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers[1], 0, n * sizeof(double), out.depth.data());
    glGetNamedBufferSubData(buffers[2], 0, n * sizeof(std::uint32_t), out.shade.data());
    gl::CheckGlError("the receiver-plane kernel");
    glDeleteBuffers(3, buffers);
    glDeleteProgram(program);
    return out;
}

void ExpectSameTest(const Light& light, std::uint32_t seed) {
    Bounds wsBounds;
    wsBounds.Add(glm::dvec3(-4.0, -1.0, -4.0));
    wsBounds.Add(glm::dvec3(4.0, 3.0, 4.0));
    const LightSpace lightSpace(light, wsBounds);
    // A projective map (p4 ≠ (0, 0, 1)) of 400² texels, so texel centres spread over the rays.
    const LightMatrix matrix{{300.0, 20.0, 200.0}, {-15.0, 280.0, 210.0}, {0.08, -0.05, 1.0}};
    const std::vector<Receiver> receivers = RandomReceivers(lightSpace, matrix, seed);
    const GlResult glsl = EvaluateInGlsl(lightSpace, matrix, receivers);
    const glm::dmat3 lsFromMap = glm::inverse(matrix.Rows());
    int fallbacks = 0, shadowed = 0;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
        const Receiver& r = receivers[i];
        const glm::dvec3 lsX = lsFromMap * glm::dvec3(r.texelCentre, 1.0);
        const double depth = ReceiverPlaneDepth(lightSpace, lsX, r.wsPoint, r.wsNormal);
        const Shade shade = CompareWithTexel(r.stored, depth);
        fallbacks += depth == lightSpace.Depth(r.wsPoint);
        shadowed += shade == Shade::kShadowed;
        SCOPED_TRACE("seed " + std::to_string(seed) + ", receiver " + std::to_string(i));
        EXPECT_NEAR(glsl.depth[i], depth, 1e-12 * std::abs(depth));
        EXPECT_EQ(glsl.shade[i], static_cast<std::uint32_t>(shade));
    }
    EXPECT_GE(fallbacks, 100);  // every fifth receiver
    EXPECT_EQ(shadowed, 250);   // just below the threshold: every other one
}

class ReceiverPlaneTest : public GlTest {};

TEST_F(ReceiverPlaneTest, GlslAndCppAgreeForAPointLight) {
    ExpectSameTest({Light::Type::kPoint, glm::dvec3(1.0, 30.0, -2.0), {}}, 7);
}

TEST_F(ReceiverPlaneTest, GlslAndCppAgreeForADirectionalLight) {
    ExpectSameTest({Light::Type::kDirectional, {}, glm::dvec3(0.3, -1.0, 0.2)}, 8);
}

}  // namespace
}  // namespace lexel::spatial
