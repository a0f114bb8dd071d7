// The passes of report Algorithm 1 and §3 on OpenGL 4.5 (render_backend.h names them), with the
// buffers kept on the GPU between passes, as a renderer would run them:
//   - camera pass into a slot's G-buffer: triangle id (R32I), point in the mesh's unit frame
//     (scene.h) and facing normal (RGBA32F), depth reversed (D32F, 1 at the near plane, 0 at the
//     far plane: float precision is relative, not absolute);
//   - shadow map into a map slot: any light matrix P through ClipFromWorld (clip_matrix.h) with
//     depth clamping, storing the linear light depth LightSpace::Depth / 2^k (D32F) — along the
//     texel centre's ray to the triangle's plane, in double — so that the stored value times 2^k
//     is the depth the shader computed;
//   - shading of a camera slot against a map slot (a full-screen fragment pass): ShadePoint's
//     decision per pixel in double, as Shade codes in an R8UI image;
//   - the boundary pixels of a shaded slot (a compute pass appending into a buffer): only they
//     come back to the CPU (report §2.4: the readback is the cost to keep small).
// Each pass can be timed (PassTimer).
// The shaders and their precision: shaders.h. Every float the GPU holds (vertices, G-buffer points)
// is in the mesh's UnitFrame, centred on its bounds and scaled to unit size, and every uniform that
// maps them is composed with that frame in double: the passes' results do not depend on the
// scene's size or distance from the origin.
//
// Every member function needs the shared context current on the calling thread (CurrentContext);
// the constructor and destructor take care of it themselves. Throws GlUnavailable when the GPU
// cannot serve a request (a map larger than GL_MAX_TEXTURE_SIZE, a framebuffer the driver refuses).
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "lexel/solvers/stopwatch.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/gl/context.h"
#include "lexel/spatial/harness/render_backend.h"

namespace lexel::spatial::gl {

// Where a camera pass goes: the final frame, or the low-resolution readback of Algorithm 1.
enum class CameraSlot { kFrame = 0, kReadback = 1 };

// How passes are timed:
//   kQueries  GL_TIME_ELAPSED queries: GPU time, without stalling the pipeline (hardware GPUs);
//   kFinish   glFinish before and after each pass, wall clock: right on any driver, but it drains
//             the pipeline. Mesa's llvmpipe needs it: it rasterizes in worker threads when a
//             frame is flushed, outside the query (measured: 2 ms reported for a 38 ms camera
//             pass, 0 ms for a 40 ms compute pass).
enum class PassTimer { kOff, kQueries, kFinish };

// Milliseconds per kind of pass since the last TakeTimes.
struct GpuTimes {
    double cameraPass = 0.0;  // camera passes (both slots)
    double shadowMap = 0.0;   // shadow-map passes
    double shading = 0.0;     // shading of the frame slot
    double extraction = 0.0;  // shading of the readback slot and boundary extraction
};

class GlRenderer {
  public:
    // Uploads the mesh (float unit-frame positions, indices, face normals) into the shared
    // context. Throws GlUnavailable when there is no context or a program does not build.
    explicit GlRenderer(const TriangleMesh& geometry);
    ~GlRenderer();
    GlRenderer(const GlRenderer&) = delete;
    GlRenderer& operator=(const GlRenderer&) = delete;

    const Context& context() const { return context_; }

    // The camera pass of `camera` at `resolution` into `slot` (Q = camera.ScreenFromWorld).
    void RenderCamera(CameraSlot slot, const Camera& camera, Resolution resolution);
    // A CPU camera buffer into `slot` in place of a camera pass (covered where triangle ≥ 0).
    void UploadCamera(CameraSlot slot, const CameraBuffer& buffer);
    // The slot's triangle ids, row-major from the top row (-1 where nothing is visible).
    std::vector<std::int32_t> ReadTriangles(CameraSlot slot) const;
    // The slot's world points and normals as stored on the GPU (float), for agreement tests.
    std::vector<glm::vec4> ReadPositions(CameraSlot slot) const;  // taken back to world units
    std::vector<glm::vec4> ReadNormals(CameraSlot slot) const;

    // The shadow map of `matrix` at `resolution` into map slot `map` ≥ 0 (slots are created on
    // first use and keep their map until overwritten).
    void RenderShadowMap(int map, const LightSpace& lightSpace, const LightMatrix& matrix,
                         Resolution resolution);
    // The map of a nonlinear `warp` (map_warp.h) at `resolution` into map slot `map`, by the
    // vertex warp of tessellated geometry (warp_shaders.h: Rosen 2012's way), patch edges cut
    // into segments of at most kWarpSegmentTexels warped texels (up to GL_MAX_TESS_GEN_LEVEL
    // segments). Its axis warps must be the identity, affine or piecewise linear (RTW's);
    // std::invalid_argument for a logarithmic one (LogPSM's map is ray-cast: ray_cast_map.h).
    // ReadShadowMap then returns the map with the warp attached.
    void RenderWarpedShadowMap(int map, const LightSpace& lightSpace, const MapWarp& warp,
                               Resolution resolution);
    // A CPU shadow map into slot `map` in place of a shadow pass.
    void UploadShadowMap(int map, const ShadowMap& shadowMap);
    // Map slot `map` as a ShadowMap (+inf where empty).
    ShadowMap ReadShadowMap(int map) const;

    // ShadePoint for every pixel of camera `slot` against map slot `map`, which must hold a map
    // made for `lightSpace`'s light.
    void ShadePass(CameraSlot slot, int map, const LightSpace& lightSpace);
    std::vector<spatial::Shade> ReadShades(CameraSlot slot) const;
    // The boundary pixels of the slot's last shading (BoundaryPixels, samples.h), ascending:
    // FindBoundary (the compute pass) then ReadBoundary (waits for it, reads the list back).
    std::vector<std::uint32_t> BoundaryPixels(CameraSlot slot);
    void FindBoundary(CameraSlot slot);
    std::vector<std::uint32_t> ReadBoundary();

    // How passes are timed from now on (kOff by default).
    void SetPassTimer(PassTimer timer) { timer_ = timer; }
    // Waits for the pending queries and returns the sums by kind of pass, then resets them.
    GpuTimes TakeTimes();

  private:
    struct CameraTarget {
        Resolution resolution;
        GLuint framebuffer = 0;
        std::array<GLuint, 3> color{};  // triangle, position, normal
        GLuint depth = 0;
        GLuint shade = 0;  // R8UI
        GLuint shadeFramebuffer = 0;
    };
    struct MapTarget {
        Resolution resolution;
        GLuint framebuffer = 0, depth = 0;
        LightMatrix matrix;
        float depthScale = 1.0f;      // stored × depthScale = linear depth
        std::optional<MapWarp> warp;  // a warped map's parameterization (RenderWarpedShadowMap)
    };
    enum class PassKind { kCamera, kShadow, kShading, kExtraction };

    CameraTarget& EnsureCamera(CameraSlot slot, Resolution resolution);
    MapTarget& EnsureMap(int map, Resolution resolution);
    void BeginPass(PassKind kind);
    void BeginShadowPass(const MapTarget& target);
    void EndPass();
    void CollectTimes(bool wait);
    static void Release(CameraTarget& target);
    static void Release(MapTarget& target);

    const Context& context_;
    Bounds bounds_;    // of the mesh: the largest light depth for the depth scale
    UnitFrame frame_;  // of bounds_: the frame of every float on the GPU
    GLsizei indexCount_ = 0;
    GLuint emptyVertexArray_ = 0;  // the full-screen triangle needs no attributes
    GLuint vertexArray_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0, normalBuffer_ = 0;
    GLuint planeBuffer_ = 0;  // dvec4 (n, d) per triangle: n·x = d
    GLuint boundaryBuffer_ = 0;
    GLsizeiptr boundaryCapacity_ = 0;  // pixels
    GLsizeiptr boundaryPixels_ = 0;    // pixels of the last FindBoundary's image
    GLuint cameraProgram_ = 0, shadowProgram_ = 0, shadeProgram_ = 0, boundaryProgram_ = 0;
    GLuint warpProgram_ = 0;                             // built on the first warped map
    GLuint warpKnotBuffer_ = 0, warpBaseBuffer_ = 0;     // its axis knots and texel centres
    GLuint warpVertexBuffer_ = 0, warpVertexArray_ = 0;  // the pieces (warp_refinement.h)
    GLuint warpTriangleBuffer_ = 0;                      // ... and their mesh triangles
    std::vector<glm::vec3> unitPositions_;               // the mesh on the CPU, for the pieces
    std::vector<glm::uvec3> triangles_;
    float maxTessLevel_ = 0.0f;
    std::array<CameraTarget, 2> cameras_{};
    std::vector<MapTarget> maps_;

    void Add(PassKind kind, double ms);

    PassTimer timer_ = PassTimer::kOff;
    PassKind passKind_ = PassKind::kCamera;
    Stopwatch passClock_;
    struct PendingQuery {
        GLuint query;
        PassKind kind;
    };
    std::vector<PendingQuery> pending_;
    std::vector<GLuint> freeQueries_;
    GpuTimes times_;
    bool inPass_ = false;
};

// The longest patch edge segment of the warped pass, in warped texels: the axis warps (RTW's,
// blurred over about two texels) are close to linear over it.
inline constexpr float kWarpSegmentTexels = 2.0f;

// The camera pass's clip-from-world for a framebuffer whose row 0 is the screen's top row:
// x_ndc = 2x¹/W - 1, y_ndc = 2x²/H - 1 from Q = camera.ScreenFromWorld(resolution), and reversed
// depth with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE): z_ndc = n (f - w) / ((f - n) w), 1 at
// the near plane (w = n) and 0 at the far plane (w = f, w the distance along the view axis), so
// the GPU keeps what the CPU renderer keeps: n ≤ w ≤ f.
glm::dmat4 CameraClipFromWorld(const Camera& camera, Resolution resolution);

// The power of two 2^k > maxDepth · (1 + 2⁻¹⁰) by which the shadow pass divides linear depth
// (stored values stay below 1, the cleared value meaning "nothing").
double DepthScale(double maxDepth);

}  // namespace lexel::spatial::gl
