// Embree 3 scene construction and ray queries (see ray_caster.h for the precision and
// determinism contract).
//
// Errors: Embree reports errors through a per-device callback and a per-thread error code, and
// its C API must not be unwound through, so the callback only records the message in a
// thread_local; after each API call the calling thread reads (and clears) its error code with
// rtcGetDeviceError and, if set, throws std::runtime_error with the recorded message. Embree
// raises an error in the thread that made the failing call, so the message read back is the
// one for that call.
#include "lexel/spatial/harness/ray_caster.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "lexel/solvers/errors.h"

namespace lexel::spatial {
namespace {

// Packet width of rtcOccluded16.
constexpr std::size_t kPacketSize = 16;
// Rays per TBB task of OccludedBatch: 256 packets, large enough that task overhead is
// negligible (~100 µs of tracing) and small enough to balance two to sixteen cores on a
// 750² frame (~140 chunks).
constexpr std::size_t kRaysPerChunk = 256 * kPacketSize;

thread_local std::string tlsLastEmbreeMessage;

void RecordEmbreeError(void* /*userPtr*/, RTCError code, const char* message) {
    tlsLastEmbreeMessage = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                           (message != nullptr ? message : "(no message)");
}

// Throws if the calling thread's last Embree call on `device` failed.
void ThrowOnEmbreeError(RTCDevice device, const char* what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code == RTC_ERROR_NONE) return;
    std::string message = tlsLastEmbreeMessage.empty()
                              ? "Embree error " + std::to_string(static_cast<int>(code))
                              : tlsLastEmbreeMessage;
    tlsLastEmbreeMessage.clear();
    throw std::runtime_error(std::string("ray caster: ") + what + ": " + message);
}

// Embree asserts on a ray it cannot trace (Debian's build aborts the process): a non-finite
// origin or direction, or a NaN extent, is refused here instead (a map that was not finite
// upstream); tFar may be +inf (a directional light's shadow ray).
void CheckRay(const ShadowRay& r) {
    const bool finite = std::isfinite(r.unitOrigin.x) && std::isfinite(r.unitOrigin.y) &&
                        std::isfinite(r.unitOrigin.z) && std::isfinite(r.direction.x) &&
                        std::isfinite(r.direction.y) && std::isfinite(r.direction.z) &&
                        std::isfinite(r.tNear) && !std::isnan(r.tFar);
    if (!finite)
        throw std::invalid_argument(
            "ray caster: a ray with a non-finite origin, direction or extent");
}

void InitRay(RTCRay& ray, const ShadowRay& r) {
    CheckRay(r);
    ray.org_x = r.unitOrigin.x;
    ray.org_y = r.unitOrigin.y;
    ray.org_z = r.unitOrigin.z;
    ray.dir_x = r.direction.x;
    ray.dir_y = r.direction.y;
    ray.dir_z = r.direction.z;
    ray.tnear = r.tNear;
    ray.tfar = r.tFar;
    ray.time = 0.0f;
    ray.mask = std::numeric_limits<unsigned>::max();  // every geometry, whatever its mask
    ray.id = 0;
    ray.flags = 0;
}

}  // namespace

struct RayCaster::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::size_t triangleCount = 0;
    UnitFrame frame;

    ~Impl() {
        if (scene != nullptr) rtcReleaseScene(scene);
        if (device != nullptr) rtcReleaseDevice(device);
    }
};

namespace {

// DomainError kGeometry for a mesh without triangles, a triangle naming a vertex it lacks or a
// referenced vertex that is not finite.
void CheckMesh(const TriangleMesh& wsMesh) {
    if (wsMesh.triangles.empty())
        throw DomainError(Subject::kGeometry, "the scene has no triangles");
    const std::size_t vertexCount = wsMesh.positions.size();
    for (std::size_t t = 0; t < wsMesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const unsigned v = wsMesh.triangles[t][k];
            if (v >= vertexCount)
                throw DomainError(Subject::kGeometry,
                                  "triangle " + std::to_string(t) + " references vertex " +
                                      std::to_string(v) + " of " + std::to_string(vertexCount));
            if (const glm::dvec3& p = wsMesh.positions[v];
                !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw DomainError(Subject::kGeometry, "vertex " + std::to_string(v) +
                                                          " of triangle " + std::to_string(t) +
                                                          " is not finite");
        }
    }
}

// Copies the mesh in `frame`'s unit coordinates into Embree-owned buffers of `geometry`, which
// Embree pads for its vector loads; shared buffers would oblige the mesh to outlive the caster
// and to carry that padding itself.
void FillGeometry(RTCDevice device, RTCGeometry geometry, const TriangleMesh& wsMesh,
                  const UnitFrame& frame) {
    const std::size_t vertexCount = wsMesh.positions.size();
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), wsMesh.triangles.size()));
    ThrowOnEmbreeError(device, "allocating the geometry buffers");
    if (vertices == nullptr || indices == nullptr)
        throw std::runtime_error("ray caster: Embree returned no geometry buffer");
    for (std::size_t v = 0; v < vertexCount; ++v) {
        // Unreferenced vertices may lie anywhere (even be non-finite): Embree never reads them.
        const glm::vec3 unitPoint(frame.ToUnit(wsMesh.positions[v]));
        for (int k = 0; k < 3; ++k) vertices[3 * v + k] = unitPoint[k];
    }
    for (std::size_t t = 0; t < wsMesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) indices[3 * t + k] = wsMesh.triangles[t][k];
}

}  // namespace

RayCaster::RayCaster(const TriangleMesh& wsMesh) : impl_(std::make_unique<Impl>()) {
    CheckMesh(wsMesh);
    impl_->device = rtcNewDevice(nullptr);
    if (impl_->device == nullptr)
        throw std::runtime_error("ray caster: Embree could not create a device (error " +
                                 std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) +
                                 ")");
    RTCDevice device = impl_->device;
    rtcSetDeviceErrorFunction(device, RecordEmbreeError, nullptr);

    impl_->scene = rtcNewScene(device);
    ThrowOnEmbreeError(device, "creating the scene");
    rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
    ThrowOnEmbreeError(device, "configuring the scene");

    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    ThrowOnEmbreeError(device, "creating the triangle geometry");
    // Released at the end of this scope; the scene keeps its own reference once attached.
    struct GeometryRef {
        RTCGeometry g;
        ~GeometryRef() {
            if (g != nullptr) rtcReleaseGeometry(g);
        }
    } geometryRef{geometry};
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    impl_->frame = UnitFrameOf(wsMesh.ComputeBounds());
    FillGeometry(device, geometry, wsMesh, impl_->frame);

    rtcCommitGeometry(geometry);
    ThrowOnEmbreeError(device, "committing the geometry");
    rtcAttachGeometryByID(impl_->scene, geometry, 0);
    ThrowOnEmbreeError(device, "attaching the geometry");
    rtcCommitScene(impl_->scene);
    ThrowOnEmbreeError(device, "building the BVH");
    impl_->triangleCount = wsMesh.triangles.size();
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

std::size_t RayCaster::TriangleCount() const { return impl_->triangleCount; }

const UnitFrame& RayCaster::Frame() const { return impl_->frame; }

ShadowRay RayCaster::ToShadowRay(const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection,
                                 double tNear, double tFar) const {
    const UnitFrame& frame = impl_->frame;
    return {glm::vec3(frame.ToUnit(wsOrigin)), glm::vec3(wsDirection),
            static_cast<float>(tNear / frame.wsScale), static_cast<float>(tFar / frame.wsScale)};
}

bool RayCaster::Occluded(const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection, double tNear,
                         double tFar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray;
    InitRay(ray, ToShadowRay(wsOrigin, wsDirection, tNear, tFar));
    rtcOccluded1(impl_->scene, &context, &ray);
    ThrowOnEmbreeError(impl_->device, "tracing a shadow ray");
    // rtcOccluded1 sets tfar to -inf when it finds a hit.
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

std::optional<RayCaster::Hit> RayCaster::Intersect(const glm::dvec3& wsOrigin,
                                                   const glm::dvec3& wsDirection, double tNear,
                                                   double tFar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit;
    InitRay(rayHit.ray, ToShadowRay(wsOrigin, wsDirection, tNear, tFar));
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->scene, &context, &rayHit);
    ThrowOnEmbreeError(impl_->device, "tracing a ray");
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{static_cast<double>(rayHit.ray.tfar) * impl_->frame.wsScale, rayHit.hit.primID};
}

namespace {

// Lanes [0, count) of `packet` from rays[first, first + count); lanes past the end repeat the last
// ray but are masked off in `valid`.
void FillPacket(RTCRay16& packet, int* valid, std::span<const ShadowRay> rays, std::size_t first,
                std::size_t count) {
    for (std::size_t i = 0; i < kPacketSize; ++i) {
        const ShadowRay& r = rays[first + std::min(i, count - 1)];
        if (i < count) CheckRay(r);
        valid[i] = i < count ? -1 : 0;
        packet.org_x[i] = r.unitOrigin.x;
        packet.org_y[i] = r.unitOrigin.y;
        packet.org_z[i] = r.unitOrigin.z;
        packet.dir_x[i] = r.direction.x;
        packet.dir_y[i] = r.direction.y;
        packet.dir_z[i] = r.direction.z;
        packet.tnear[i] = r.tNear;
        packet.tfar[i] = r.tFar;
        packet.time[i] = 0.0f;
        packet.mask[i] = std::numeric_limits<unsigned>::max();
        packet.id[i] = static_cast<unsigned>(i);
        packet.flags[i] = 0;
    }
}

// Calls trace(context, first, count) for every packet of `rays` (at most kPacketSize rays from
// `first`), in parallel over chunks of kRaysPerChunk rays, each chunk's packets in order on one
// thread with one intersect context flagged for `order`.
template <class Trace>
void TracePackets(std::size_t rayCount, RayCaster::RayOrder order, const Trace& trace) {
    const std::size_t chunkCount = (rayCount + kRaysPerChunk - 1) / kRaysPerChunk;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, chunkCount),
        [&](const tbb::blocked_range<std::size_t>& chunks) {
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            context.flags = order == RayCaster::RayOrder::kCoherent
                                ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
            for (std::size_t chunk = chunks.begin(); chunk != chunks.end(); ++chunk) {
                const std::size_t chunkBegin = chunk * kRaysPerChunk;
                const std::size_t chunkEnd = std::min(rayCount, chunkBegin + kRaysPerChunk);
                for (std::size_t first = chunkBegin; first < chunkEnd; first += kPacketSize)
                    trace(context, first, std::min(kPacketSize, chunkEnd - first));
            }
        });
}

void CheckResultSlots(std::size_t rays, std::size_t slots) {
    if (rays != slots)
        throw std::invalid_argument("ray caster: " + std::to_string(rays) + " rays but " +
                                    std::to_string(slots) + " result slots");
}

}  // namespace

void RayCaster::IntersectBatch(std::span<const ShadowRay> rays, std::span<std::int32_t> triangle,
                               RayOrder order) const {
    CheckResultSlots(rays.size(), triangle.size());
    const RTCScene scene = impl_->scene;
    const RTCDevice device = impl_->device;
    TracePackets(rays.size(), order,
                 [&](RTCIntersectContext& context, std::size_t first, std::size_t count) {
                     RTCRayHit16 packet;
                     alignas(64) int valid[kPacketSize];
                     FillPacket(packet.ray, valid, rays, first, count);
                     for (std::size_t i = 0; i < kPacketSize; ++i) {
                         packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
                         packet.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
                         packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
                     }
                     rtcIntersect16(valid, scene, &context, &packet);
                     ThrowOnEmbreeError(device, "tracing a packet of rays");
                     for (std::size_t i = 0; i < count; ++i)
                         triangle[first + i] =
                             packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID
                                 ? -1
                                 : static_cast<std::int32_t>(packet.hit.primID[i]);
                 });
}

void RayCaster::OccludedBatch(std::span<const ShadowRay> rays, std::span<std::uint8_t> occluded,
                              RayOrder order) const {
    CheckResultSlots(rays.size(), occluded.size());
    const RTCScene scene = impl_->scene;
    const RTCDevice device = impl_->device;
    TracePackets(rays.size(), order,
                 [&](RTCIntersectContext& context, std::size_t first, std::size_t count) {
                     RTCRay16 packet;
                     alignas(64) int valid[kPacketSize];
                     FillPacket(packet, valid, rays, first, count);
                     rtcOccluded16(valid, scene, &context, &packet);
                     ThrowOnEmbreeError(device, "tracing a packet of shadow rays");
                     for (std::size_t i = 0; i < count; ++i)
                         occluded[first + i] =
                             packet.tfar[i] == -std::numeric_limits<float>::infinity() ? 1 : 0;
                 });
}

}  // namespace lexel::spatial
