// The OpenGL passes (gl_renderer.h). GL objects are created with direct state access (4.5);
// uniform locations and bindings are those of shaders.h.
#include "lexel/spatial/gl/gl_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/gl/light_uniforms.h"
#include "lexel/spatial/gl/program.h"
#include "lexel/spatial/gl/shaders.h"
#include "lexel/spatial/gl/warp_refinement.h"
#include "lexel/spatial/gl/warp_shaders.h"

namespace lexel::spatial::gl {

glm::dmat4 CameraClipFromWorld(const Camera& camera, Resolution resolution) {
    const glm::dmat4 q = camera.ScreenFromWorld(resolution);
    const glm::dvec4 q1 = glm::row(q, 0), q2 = glm::row(q, 1), qw = glm::row(q, 3);
    const double n = camera.nearPlane, f = camera.farPlane;
    const glm::dvec4 rowX = (2.0 / resolution.width) * q1 - qw;
    const glm::dvec4 rowY = (2.0 / resolution.height) * q2 - qw;
    const glm::dvec4 rowZ = (-n / (f - n)) * qw + glm::dvec4(0.0, 0.0, 0.0, n * f / (f - n));
    return glm::transpose(glm::dmat4(rowX, rowY, rowZ, qw));
}

double DepthScale(double maxDepth) {
    if (!(maxDepth > 0.0) || !std::isfinite(maxDepth)) return 1.0;
    int exponent = 0;
    std::frexp(maxDepth * (1.0 + 1.0 / 1024.0), &exponent);  // value = m · 2^e, m ∈ [½, 1)
    return std::ldexp(1.0, exponent);
}

namespace {

constexpr GLenum kCameraFormats[3] = {GL_R32I, GL_RGBA32F, GL_RGBA32F};

glm::mat4 ToFloat(const glm::dmat4& m) { return glm::mat4(m); }

void CheckSize(const Context& context, Resolution r, const char* what) {
    const int limit = context.Info().maxTextureSize;
    if (r.width < 1 || r.height < 1 || r.width > limit || r.height > limit)
        throw GlUnavailable(std::string(what) + " of " + std::to_string(r.width) + "×" +
                            std::to_string(r.height) + " exceeds GL_MAX_TEXTURE_SIZE (" +
                            std::to_string(limit) + ")");
}

// The largest linear light depth over the mesh: Depth is convex (point) or affine
// (directional) in the world point, so its maximum over the bounds is at a corner.
double MaxDepth(const LightSpace& lightSpace, const Bounds& wsBounds) {
    double m = 0.0;
    for (const glm::dvec3& corner : wsBounds.Corners()) m = std::max(m, lightSpace.Depth(corner));
    return m;
}

}  // namespace

GlRenderer::GlRenderer(const TriangleMesh& geometry) : context_(Context::Shared()) {
    const CurrentContext current(context_);
    bounds_ = geometry.ComputeBounds();
    frame_ = UnitFrameOf(bounds_);
    indexCount_ = static_cast<GLsizei>(3 * geometry.triangles.size());
    std::vector<glm::vec3> unitPositions(geometry.positions.size());
    for (std::size_t v = 0; v < unitPositions.size(); ++v)
        unitPositions[v] = glm::vec3(frame_.ToUnit(geometry.positions[v]));
    glCreateBuffers(1, &vertexBuffer_);
    glNamedBufferStorage(vertexBuffer_, unitPositions.size() * sizeof(glm::vec3),
                         unitPositions.data(), 0);
    glCreateBuffers(1, &indexBuffer_);
    glNamedBufferStorage(indexBuffer_, geometry.triangles.size() * sizeof(glm::uvec3),
                         geometry.triangles.data(), 0);
    glCreateVertexArrays(1, &vertexArray_);
    glVertexArrayVertexBuffer(vertexArray_, 0, vertexBuffer_, 0, sizeof(glm::vec3));
    glVertexArrayElementBuffer(vertexArray_, indexBuffer_);
    glEnableVertexArrayAttrib(vertexArray_, 0);
    glVertexArrayAttribFormat(vertexArray_, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_, 0, 0);

    std::vector<glm::vec4> normals(std::max<std::size_t>(geometry.triangles.size(), 1));
    for (std::size_t t = 0; t < geometry.triangles.size(); ++t)
        normals[t] = glm::vec4(glm::vec3(geometry.FaceNormal(t)), 0.0f);
    glCreateBuffers(1, &normalBuffer_);
    glNamedBufferStorage(normalBuffer_, normals.size() * sizeof(glm::vec4), normals.data(), 0);
    // Face planes n·x = d in double for the shadow pass's depth.
    std::vector<glm::dvec4> planes(normals.size(), glm::dvec4(0.0));
    for (std::size_t t = 0; t < geometry.triangles.size(); ++t) {
        const glm::dvec3 n = geometry.FaceNormal(t);
        planes[t] = glm::dvec4(n, glm::dot(n, geometry.positions[geometry.triangles[t][0]]));
    }
    glCreateBuffers(1, &planeBuffer_);
    glNamedBufferStorage(planeBuffer_, planes.size() * sizeof(glm::dvec4), planes.data(), 0);

    cameraProgram_ = BuildProgram({{GL_VERTEX_SHADER, shaders::kGeometryVertex},
                                   {GL_FRAGMENT_SHADER, shaders::kCameraFragment}});
    shadowProgram_ = BuildProgram({{GL_VERTEX_SHADER, shaders::kGeometryVertex},
                                   {GL_FRAGMENT_SHADER, shaders::kShadowFragment}});
    shadeProgram_ = BuildProgram({{GL_VERTEX_SHADER, shaders::kFullScreenVertex},
                                  {GL_FRAGMENT_SHADER, shaders::kShadeFragment}});
    glCreateVertexArrays(1, &emptyVertexArray_);
    boundaryProgram_ = BuildProgram({{GL_COMPUTE_SHADER, shaders::kBoundaryCompute}});
    CheckGlError("uploading the mesh");
}

GlRenderer::~GlRenderer() {
    const CurrentContext current(context_);
    CollectTimes(true);
    for (CameraTarget& t : cameras_) Release(t);
    for (MapTarget& t : maps_) Release(t);
    glDeleteQueries(static_cast<GLsizei>(freeQueries_.size()), freeQueries_.data());
    for (GLuint p : {cameraProgram_, shadowProgram_, shadeProgram_, boundaryProgram_, warpProgram_})
        glDeleteProgram(p);
    const GLuint buffers[] = {vertexBuffer_,   indexBuffer_,      normalBuffer_,
                              planeBuffer_,    boundaryBuffer_,   warpKnotBuffer_,
                              warpBaseBuffer_, warpVertexBuffer_, warpTriangleBuffer_};
    glDeleteBuffers(9, buffers);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteVertexArrays(1, &warpVertexArray_);
    glDeleteVertexArrays(1, &emptyVertexArray_);
}

void GlRenderer::Release(CameraTarget& t) {
    glDeleteFramebuffers(1, &t.framebuffer);
    glDeleteFramebuffers(1, &t.shadeFramebuffer);
    glDeleteTextures(3, t.color.data());
    glDeleteTextures(1, &t.depth);
    glDeleteTextures(1, &t.shade);
    t = CameraTarget{};
}

void GlRenderer::Release(MapTarget& t) {
    glDeleteFramebuffers(1, &t.framebuffer);
    glDeleteTextures(1, &t.depth);
    t = MapTarget{};
}

GlRenderer::CameraTarget& GlRenderer::EnsureCamera(CameraSlot slot, Resolution r) {
    CameraTarget& t = cameras_[static_cast<int>(slot)];
    if (t.framebuffer != 0 && t.resolution.width == r.width && t.resolution.height == r.height)
        return t;
    CheckSize(context_, r, "a camera pass");
    Release(t);
    t.resolution = r;
    glCreateTextures(GL_TEXTURE_2D, 3, t.color.data());
    for (int i = 0; i < 3; ++i) {
        glTextureStorage2D(t.color[i], 1, kCameraFormats[i], r.width, r.height);
        // Integer textures are incomplete under linear filtering; texelFetch reads them anyway.
        glTextureParameteri(t.color[i], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t.color[i], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glCreateTextures(GL_TEXTURE_2D, 1, &t.depth);
    glTextureStorage2D(t.depth, 1, GL_DEPTH_COMPONENT32F, r.width, r.height);
    glCreateTextures(GL_TEXTURE_2D, 1, &t.shade);
    glTextureStorage2D(t.shade, 1, GL_R8UI, r.width, r.height);
    glCreateFramebuffers(1, &t.framebuffer);
    for (int i = 0; i < 3; ++i)
        glNamedFramebufferTexture(t.framebuffer, GL_COLOR_ATTACHMENT0 + i, t.color[i], 0);
    glNamedFramebufferTexture(t.framebuffer, GL_DEPTH_ATTACHMENT, t.depth, 0);
    const GLenum drawBuffers[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                   GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(t.framebuffer, 3, drawBuffers);
    glCreateFramebuffers(1, &t.shadeFramebuffer);
    glNamedFramebufferTexture(t.shadeFramebuffer, GL_COLOR_ATTACHMENT0, t.shade, 0);
    glNamedFramebufferDrawBuffer(t.shadeFramebuffer, GL_COLOR_ATTACHMENT0);
    if (glCheckNamedFramebufferStatus(t.framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
        glCheckNamedFramebufferStatus(t.shadeFramebuffer, GL_FRAMEBUFFER) !=
            GL_FRAMEBUFFER_COMPLETE)
        throw GlUnavailable("the camera framebuffer is incomplete");
    return t;
}

GlRenderer::MapTarget& GlRenderer::EnsureMap(int map, Resolution r) {
    if (map < 0) throw std::invalid_argument("GlRenderer: no such map slot");
    if (static_cast<std::size_t>(map) >= maps_.size())
        maps_.resize(static_cast<std::size_t>(map) + 1);
    MapTarget& t = maps_[static_cast<std::size_t>(map)];
    if (t.framebuffer != 0 && t.resolution.width == r.width && t.resolution.height == r.height)
        return t;
    CheckSize(context_, r, "a shadow map");
    Release(t);
    t.resolution = r;
    glCreateTextures(GL_TEXTURE_2D, 1, &t.depth);
    glTextureStorage2D(t.depth, 1, GL_DEPTH_COMPONENT32F, r.width, r.height);
    glTextureParameteri(t.depth, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.depth, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t.depth, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glCreateFramebuffers(1, &t.framebuffer);
    glNamedFramebufferTexture(t.framebuffer, GL_DEPTH_ATTACHMENT, t.depth, 0);
    glNamedFramebufferDrawBuffer(t.framebuffer, GL_NONE);
    glNamedFramebufferReadBuffer(t.framebuffer, GL_NONE);
    if (glCheckNamedFramebufferStatus(t.framebuffer, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlUnavailable("the shadow-map framebuffer is incomplete");
    return t;
}

void GlRenderer::RenderCamera(CameraSlot slot, const Camera& camera, Resolution resolution) {
    CameraTarget& t = EnsureCamera(slot, resolution);
    const GLint noTriangle = -1;
    const GLfloat zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, farDepth = 0.0f;
    glClearNamedFramebufferiv(t.framebuffer, GL_COLOR, 0, &noTriangle);
    glClearNamedFramebufferfv(t.framebuffer, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(t.framebuffer, GL_COLOR, 2, zero);
    glClearNamedFramebufferfv(t.framebuffer, GL_DEPTH, 0, &farDepth);
    BeginPass(PassKind::kCamera);
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
    glViewport(0, 0, resolution.width, resolution.height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reversed depth: nearer is larger
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_CULL_FACE);
    glUseProgram(cameraProgram_);
    const glm::mat4 clip =
        ToFloat(CameraClipFromWorld(camera, resolution) * frame_.WorldFromUnit());
    glProgramUniformMatrix4fv(cameraProgram_, 0, 1, GL_FALSE, glm::value_ptr(clip));
    const glm::vec3 eye(frame_.ToUnit(camera.position));
    glProgramUniform3fv(cameraProgram_, 1, 1, glm::value_ptr(eye));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, normalBuffer_);
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EndPass();
}

void GlRenderer::UploadCamera(CameraSlot slot, const CameraBuffer& buffer) {
    const Resolution r = buffer.resolution;
    CameraTarget& t = EnsureCamera(slot, r);
    const std::size_t n = r.Count();
    std::vector<glm::vec4> position(n), normal(n);
    for (std::size_t i = 0; i < n; ++i) {
        position[i] = glm::vec4(glm::vec3(frame_.ToUnit(buffer.wsPosition[i])), 1.0f);
        normal[i] = glm::vec4(glm::vec3(buffer.wsNormal[i]), 0.0f);
    }
    glTextureSubImage2D(t.color[0], 0, 0, 0, r.width, r.height, GL_RED_INTEGER, GL_INT,
                        buffer.triangle.data());
    glTextureSubImage2D(t.color[1], 0, 0, 0, r.width, r.height, GL_RGBA, GL_FLOAT, position.data());
    glTextureSubImage2D(t.color[2], 0, 0, 0, r.width, r.height, GL_RGBA, GL_FLOAT, normal.data());
}

std::vector<std::int32_t> GlRenderer::ReadTriangles(CameraSlot slot) const {
    const CameraTarget& t = cameras_[static_cast<int>(slot)];
    std::vector<std::int32_t> out(t.resolution.Count());
    glGetTextureImage(t.color[0], 0, GL_RED_INTEGER, GL_INT,
                      static_cast<GLsizei>(out.size() * sizeof(std::int32_t)), out.data());
    return out;
}

std::vector<glm::vec4> GlRenderer::ReadPositions(CameraSlot slot) const {
    const CameraTarget& t = cameras_[static_cast<int>(slot)];
    std::vector<glm::vec4> out(t.resolution.Count());
    glGetTextureImage(t.color[1], 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(out.size() * sizeof(glm::vec4)), out.data());
    for (glm::vec4& p : out)
        if (p.w != 0.0f) p = glm::vec4(glm::vec3(frame_.ToWorld(glm::dvec3(p))), 1.0f);
    return out;
}

std::vector<glm::vec4> GlRenderer::ReadNormals(CameraSlot slot) const {
    const CameraTarget& t = cameras_[static_cast<int>(slot)];
    std::vector<glm::vec4> out(t.resolution.Count());
    glGetTextureImage(t.color[2], 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(out.size() * sizeof(glm::vec4)), out.data());
    return out;
}

// The state both shadow passes share: the map's cleared depth as the target, depth in [0, 1]
// with clamping (every point in front of the light is kept), no culling (casters of either
// winding).
void GlRenderer::BeginShadowPass(const MapTarget& t) {
    BeginPass(PassKind::kShadow);
    const GLfloat empty = 1.0f;
    glClearNamedFramebufferfv(t.framebuffer, GL_DEPTH, 0, &empty);
    glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
    glViewport(0, 0, t.resolution.width, t.resolution.height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_CLAMP);
    glDisable(GL_CULL_FACE);
}

void GlRenderer::RenderShadowMap(int map, const LightSpace& lightSpace, const LightMatrix& matrix,
                                 Resolution resolution) {
    MapTarget& t = EnsureMap(map, resolution);
    t.matrix = matrix;
    t.warp.reset();
    const double maxDepth = MaxDepth(lightSpace, bounds_);
    t.depthScale = static_cast<float>(DepthScale(maxDepth));
    // Any valid range: depth clamping keeps every point in front of the light, and the fragment
    // shader writes the linear depth.
    const DepthRange range =
        lightSpace.IsPoint() ? DepthRange{1e-3 * maxDepth, maxDepth} : DepthRange{0.0, maxDepth};
    const glm::mat4 clip =
        ToFloat(ClipFromWorld(lightSpace, matrix, resolution, range, ClipDepth::kZeroToOne) *
                frame_.WorldFromUnit());

    BeginShadowPass(t);
    glUseProgram(shadowProgram_);
    glProgramUniformMatrix4fv(shadowProgram_, 0, 1, GL_FALSE, glm::value_ptr(clip));
    glProgramUniform1d(shadowProgram_, 4, 1.0 / t.depthScale);
    SetLightUniforms(shadowProgram_, lightSpace, matrix, frame_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, planeBuffer_);
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_CLAMP);
    EndPass();
}

namespace {

// An axis warp as the warped pass's knots: (lo, hi) and the values at equally spaced knots.
void AppendKnots(const AxisWarp& w, double extent, std::vector<float>* knots, float* lo,
                 float* hi) {
    if (w.kind() == AxisWarp::Kind::kLogarithmic)
        throw std::invalid_argument("GlRenderer: a logarithmic axis warp is not a vertex warp");
    if (w.kind() == AxisWarp::Kind::kPiecewise) {
        *lo = static_cast<float>(w.lo()), *hi = static_cast<float>(w.hi());
        for (double v : w.values()) knots->push_back(static_cast<float>(v));
        return;
    }
    // Identity and affine: one segment, extended linearly beyond it.
    *lo = 0.0f, *hi = static_cast<float>(extent);
    knots->push_back(static_cast<float>(w.Apply(0.0)));
    knots->push_back(static_cast<float>(w.Apply(extent)));
}

// Replaces *buffer by one holding `bytes` bytes of `data`.
void Upload(GLuint* buffer, const void* data, std::size_t bytes) {
    glDeleteBuffers(1, buffer);
    glCreateBuffers(1, buffer);
    glNamedBufferStorage(*buffer, static_cast<GLsizeiptr>(bytes), data, 0);
}

}  // namespace

void GlRenderer::RenderWarpedShadowMap(int map, const LightSpace& lightSpace, const MapWarp& warp,
                                       Resolution resolution) {
    std::vector<float> knots;
    float range[4];
    AppendKnots(warp.x, resolution.width, &knots, &range[0], &range[1]);
    const int knotsX = static_cast<int>(knots.size());
    AppendKnots(warp.y, resolution.height, &knots, &range[2], &range[3]);
    const int knotsY = static_cast<int>(knots.size()) - knotsX;
    // The base coordinates of every column's and row's texel centre: warp.Inverse, axis by axis.
    std::vector<double> texelBase;
    for (int x = 0; x < resolution.width; ++x)
        texelBase.push_back(warp.x.Invert(x + 0.5 - warp.phase.x));
    for (int y = 0; y < resolution.height; ++y)
        texelBase.push_back(warp.y.Invert(y + 0.5 - warp.phase.y));
    if (warpProgram_ == 0) {
        warpProgram_ = BuildProgram({{GL_VERTEX_SHADER, shaders::kWarpVertex},
                                     {GL_TESS_CONTROL_SHADER, shaders::kWarpControl},
                                     {GL_TESS_EVALUATION_SHADER, shaders::kWarpEvaluation},
                                     {GL_FRAGMENT_SHADER, shaders::kWarpFragment}});
        GLint level = 0;
        glGetIntegerv(GL_MAX_TESS_GEN_LEVEL, &level);
        maxTessLevel_ = static_cast<float>(std::max(level, 1));
        // The mesh on the CPU once, from the GPU's own buffers, for the pieces.
        GLint64 bytes = 0;
        glGetNamedBufferParameteri64v(vertexBuffer_, GL_BUFFER_SIZE, &bytes);
        unitPositions_.resize(static_cast<std::size_t>(bytes) / sizeof(glm::vec3));
        glGetNamedBufferSubData(vertexBuffer_, 0, bytes, unitPositions_.data());
        triangles_.resize(static_cast<std::size_t>(indexCount_) / 3);
        glGetNamedBufferSubData(indexBuffer_, 0, indexCount_ * sizeof(GLuint), triangles_.data());
        glCreateVertexArrays(1, &warpVertexArray_);
        glEnableVertexArrayAttrib(warpVertexArray_, 0);
        glVertexArrayAttribFormat(warpVertexArray_, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(warpVertexArray_, 0, 0);
    }
    Upload(&warpKnotBuffer_, knots.data(), knots.size() * sizeof(float));
    Upload(&warpBaseBuffer_, texelBase.data(), texelBase.size() * sizeof(double));

    MapTarget& t = EnsureMap(map, resolution);
    t.matrix = warp.base;
    t.warp = warp;
    const double maxDepth = MaxDepth(lightSpace, bounds_);
    t.depthScale = static_cast<float>(DepthScale(maxDepth));
    const DepthRange depthRange =
        lightSpace.IsPoint() ? DepthRange{1e-3 * maxDepth, maxDepth} : DepthRange{0.0, maxDepth};
    const glm::dmat4 clipFromUnit =
        ClipFromWorld(lightSpace, warp.base, resolution, depthRange, ClipDepth::kZeroToOne) *
        frame_.WorldFromUnit();
    const glm::mat4 clip = ToFloat(clipFromUnit);
    const WarpPieces pieces =
        RefineForWarp(unitPositions_, triangles_, clipFromUnit, warp, resolution,
                      static_cast<double>(maxTessLevel_ * kWarpSegmentTexels));
    Upload(&warpVertexBuffer_, pieces.unitVertices.data(),
           pieces.unitVertices.size() * sizeof(glm::vec3));
    Upload(&warpTriangleBuffer_, pieces.triangle.data(),
           pieces.triangle.size() * sizeof(std::int32_t));
    glVertexArrayVertexBuffer(warpVertexArray_, 0, warpVertexBuffer_, 0, sizeof(glm::vec3));
    BeginShadowPass(t);
    const GLuint p = warpProgram_;
    glUseProgram(p);
    glProgramUniformMatrix4fv(p, 0, 1, GL_FALSE, glm::value_ptr(clip));
    glProgramUniform2f(p, 1, static_cast<float>(resolution.width),
                       static_cast<float>(resolution.height));
    glProgramUniform2i(p, 2, knotsX, knotsY);
    glProgramUniform4fv(p, 3, 1, range);
    glProgramUniform2f(p, 4, static_cast<float>(warp.phase.x), static_cast<float>(warp.phase.y));
    glProgramUniform1f(p, 5, kWarpSegmentTexels);
    glProgramUniform1f(p, 6, maxTessLevel_);
    glProgramUniform1d(p, 7, 1.0 / t.depthScale);
    glProgramUniform1i(p, 8, resolution.width);
    SetLightUniforms(p, lightSpace, warp.base, frame_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, planeBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, warpKnotBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, warpBaseBuffer_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, warpTriangleBuffer_);
    glBindVertexArray(warpVertexArray_);
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    const std::vector<std::size_t> batches =
        WarpDrawBatches(pieces.longestEdge, kWarpSegmentTexels, maxTessLevel_);
    for (std::size_t b = 0; b + 1 < batches.size(); ++b)  // gl_VertexID counts from `first`
        glDrawArrays(GL_PATCHES, static_cast<GLint>(3 * batches[b]),
                     static_cast<GLsizei>(3 * (batches[b + 1] - batches[b])));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_CLAMP);
    EndPass();
    CheckGlError("rendering a warped shadow map");
}

void GlRenderer::UploadShadowMap(int map, const ShadowMap& shadowMap) {
    MapTarget& t = EnsureMap(map, shadowMap.resolution);
    t.matrix = shadowMap.matrix;
    t.warp = shadowMap.warp;
    double maxDepth = 0.0;
    for (float d : shadowMap.depth)
        if (std::isfinite(d)) maxDepth = std::max(maxDepth, static_cast<double>(d));
    t.depthScale = static_cast<float>(DepthScale(maxDepth));
    std::vector<float> stored(shadowMap.depth.size());
    for (std::size_t i = 0; i < stored.size(); ++i)
        stored[i] = std::isfinite(shadowMap.depth[i]) ? shadowMap.depth[i] / t.depthScale : 1.0f;
    glTextureSubImage2D(t.depth, 0, 0, 0, t.resolution.width, t.resolution.height,
                        GL_DEPTH_COMPONENT, GL_FLOAT, stored.data());
}

ShadowMap GlRenderer::ReadShadowMap(int map) const {
    const MapTarget& t = maps_.at(map);
    ShadowMap out;
    out.resolution = t.resolution;
    out.matrix = t.matrix;
    out.warp = t.warp;
    out.depth.resize(t.resolution.Count());
    glGetTextureImage(t.depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(out.depth.size() * sizeof(float)), out.depth.data());
    for (float& d : out.depth)
        d = d >= 1.0f ? std::numeric_limits<float>::infinity() : d * t.depthScale;
    return out;
}

void GlRenderer::ShadePass(CameraSlot slot, int map, const LightSpace& lightSpace) {
    CameraTarget& c = cameras_[static_cast<int>(slot)];
    const MapTarget& m = maps_.at(map);
    if (c.framebuffer == 0 || m.framebuffer == 0)
        throw std::invalid_argument("GlRenderer::ShadePass: render or upload the buffers first");
    BeginPass(slot == CameraSlot::kFrame ? PassKind::kShading : PassKind::kExtraction);
    const GLuint p = shadeProgram_;
    glProgramUniform1d(p, 0, m.depthScale);
    glProgramUniform2i(p, 1, m.resolution.width, m.resolution.height);
    SetLightUniforms(p, lightSpace, m.matrix, frame_);
    glBindTextureUnit(0, m.depth);
    for (int i = 0; i < 3; ++i) glBindTextureUnit(1 + i, c.color[i]);
    glBindFramebuffer(GL_FRAMEBUFFER, c.shadeFramebuffer);
    glViewport(0, 0, c.resolution.width, c.resolution.height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(p);
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EndPass();
}

std::vector<Shade> GlRenderer::ReadShades(CameraSlot slot) const {
    const CameraTarget& t = cameras_[static_cast<int>(slot)];
    std::vector<Shade> out(t.resolution.Count());
    static_assert(sizeof(Shade) == 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(t.shade, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                      static_cast<GLsizei>(out.size()), out.data());
    return out;
}

std::vector<std::uint32_t> GlRenderer::BoundaryPixels(CameraSlot slot) {
    FindBoundary(slot);
    return ReadBoundary();
}

void GlRenderer::FindBoundary(CameraSlot slot) {
    const CameraTarget& c = cameras_[static_cast<int>(slot)];
    const auto pixels = static_cast<GLsizeiptr>(c.resolution.Count());
    if (boundaryCapacity_ < pixels) {
        glDeleteBuffers(1, &boundaryBuffer_);
        glCreateBuffers(1, &boundaryBuffer_);
        glNamedBufferStorage(boundaryBuffer_, (1 + pixels) * sizeof(GLuint), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        boundaryCapacity_ = pixels;
    }
    boundaryPixels_ = pixels;
    BeginPass(PassKind::kExtraction);
    const GLuint zero = 0;
    glNamedBufferSubData(boundaryBuffer_, 0, sizeof(GLuint), &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, boundaryBuffer_);
    glBindImageTexture(3, c.shade, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8UI);
    glUseProgram(boundaryProgram_);
    glDispatchCompute((c.resolution.width + 7) / 8, (c.resolution.height + 7) / 8, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    EndPass();
}

std::vector<std::uint32_t> GlRenderer::ReadBoundary() {
    if (boundaryBuffer_ == 0) throw std::invalid_argument("GlRenderer::ReadBoundary: none found");
    GLuint count = 0;
    glGetNamedBufferSubData(boundaryBuffer_, 0, sizeof(GLuint), &count);
    std::vector<std::uint32_t> out(std::min<GLsizeiptr>(count, boundaryPixels_));
    if (!out.empty())
        glGetNamedBufferSubData(boundaryBuffer_, sizeof(GLuint),
                                static_cast<GLsizeiptr>(out.size() * sizeof(GLuint)), out.data());
    std::sort(out.begin(), out.end());  // appended in any order; samples keep pixel order
    return out;
}

void GlRenderer::BeginPass(PassKind kind) {
    if (timer_ == PassTimer::kOff) return;
    passKind_ = kind;
    inPass_ = true;
    if (timer_ == PassTimer::kFinish) {
        glFinish();
        passClock_.Restart();
        return;
    }
    GLuint query = 0;
    if (freeQueries_.empty()) {
        glCreateQueries(GL_TIME_ELAPSED, 1, &query);
    } else {
        query = freeQueries_.back();
        freeQueries_.pop_back();
    }
    glBeginQuery(GL_TIME_ELAPSED, query);
    pending_.push_back({query, kind});
}

void GlRenderer::EndPass() {
    if (!inPass_) return;
    inPass_ = false;
    if (timer_ == PassTimer::kFinish) {
        glFinish();
        Add(passKind_, passClock_.Ms());
        return;
    }
    glEndQuery(GL_TIME_ELAPSED);
}

void GlRenderer::Add(PassKind kind, double ms) {
    switch (kind) {
        case PassKind::kCamera:
            times_.cameraPass += ms;
            break;
        case PassKind::kShadow:
            times_.shadowMap += ms;
            break;
        case PassKind::kShading:
            times_.shading += ms;
            break;
        case PassKind::kExtraction:
            times_.extraction += ms;
            break;
    }
}

void GlRenderer::CollectTimes(bool wait) {
    for (const PendingQuery& q : pending_) {
        GLuint64 ns = 0;
        if (wait) glGetQueryObjectui64v(q.query, GL_QUERY_RESULT, &ns);
        Add(q.kind, static_cast<double>(ns) * 1e-6);
        freeQueries_.push_back(q.query);
    }
    pending_.clear();
}

GpuTimes GlRenderer::TakeTimes() {
    CollectTimes(true);
    const GpuTimes out = times_;
    times_ = GpuTimes{};
    return out;
}

}  // namespace lexel::spatial::gl
