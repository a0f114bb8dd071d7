// Exact shadow rays for the ground truth of the 3D harness (report §3: a pixel is lit when the
// segment from its world point to the light is unobstructed). A RayCaster owns an Embree 3
// device and a BVH over one TriangleMesh and answers occlusion and closest-hit queries against
// it (Wald et al., "Embree: A Kernel Framework for Efficient CPU Ray Tracing", SIGGRAPH 2014;
// Embree 3 API manual: rtcOccluded1, rtcIntersect1, rtcOccluded16).
//
// Why Embree and not our own BVH: the passes shoot one shadow ray per camera pixel per light
// (562,500 for a 750² frame, times 500 lights of a sweep), so throughput decides how many
// configurations the harness can evaluate; Embree's packet kernels are the fastest CPU option
// available as a Debian package.
//
// Precision. Embree works in single precision, so the caster works in the mesh's UnitFrame
// (scene.h): the BVH holds the vertices centred on the mesh's bounds and scaled to unit size,
// rounded to float there, and each ray's origin is taken into that frame in double before it is
// rounded (its direction is kept; t is divided by the frame's power-of-two scale). Every float
// then carries ~1e-7 of the scene's radius, so the answers do not depend on the scene's size or
// its distance from the origin (tests/spatial/harness/scale_invariance_test.cpp). In world
// coordinates they did: 700 radii from the origin a 1e-5-radius ray offset is a few float steps,
// and the truth rays of tests/cases/data/spatial_small.json found 98.6% of its pixels shadowed;
// at scale 1e-20 Embree's products underflowed and they found none. Ray parameters t are in
// units of |wsDirection| (world units when the direction is unit). The scene is built with
// RTC_SCENE_FLAG_ROBUST, which makes the traversal conservative and the triangle test watertight
// (Plücker edge tests that evaluate a shared edge identically for both of its triangles), so a
// ray through a shared edge or vertex of a closed mesh cannot leak between its triangles. It does
// not make hits near the ray's own origin reliable: a shadow ray started on a surface can hit
// that surface again ("shadow acne").
//
// Recommended policy for ground-truth shadow rays from a surface point p with unit geometric
// normal n (TriangleMesh::FaceNormal) towards a light, with every length relative to the scene
// radius (Bounds::Radius() of the mesh's bounds) so that it is scale-free:
//   - flip n to the light's side (n·wsDirection > 0) and start at p + εo·n, with the origin
//     offset εo = 1e-5 × scene radius (~100 float ulps of a unit-frame coordinate, so the
//     offset origin is strictly off the plane of the triangle p lies on, in float);
//   - use tNear = 1e-4 × scene radius (ten times εo, so that neighbours of p's triangle meeting
//     it at a concave angle are skipped too) and tFar = distance to the light minus the same
//     tNear (the light is not geometry, but a light placed on a surface must not be shadowed by
//     it);
//   - points closer than tNear to an occluder are misclassified as lit; at the report's scene
//     scales (radius ~30, tNear ~3 mm) this is far below one readback pixel.
//
// Determinism. Every query is a pure function of the committed scene and the float ray:
// Occluded reports whether any triangle is hit with t in [tNear, tFar], which does not depend
// on traversal order; Intersect reports the smallest such t. Repeated queries, concurrent
// queries, and the single-ray and batch forms give identical answers on one machine (the
// tests check the last). Only the triangle index of an exact tie in t (a ray through a shared
// edge) depends on the BVH layout. Bitwise agreement across machines is not promised: Embree
// picks SSE/AVX/AVX-512 kernels at run time and their float rounding can differ in the last
// ulp.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// One ray of a batch, already in Embree's precision and in the caster's UnitFrame (the batch form
// is for throughput, and 32 bytes a ray where a frame holds one per pixel): make it with
// RayCaster::ToShadowRay. t is in units of |direction| in that frame.
struct ShadowRay {
    glm::vec3 unitOrigin;
    glm::vec3 direction;
    float tNear, tFar;
};

class RayCaster {
  public:
    struct Hit {
        double t;           // ray parameter of the hit, in units of |wsDirection|
        unsigned triangle;  // index into TriangleMesh::triangles
    };

    // Copies the mesh into Embree-owned buffers and builds a high-quality, robust BVH.
    // Throws DomainError (Subject::kGeometry) when the mesh has no triangles, a triangle indexes a
    // missing vertex, or a referenced position is not finite; std::runtime_error with Embree's
    // message when Embree fails (device creation, out of memory, build errors).
    explicit RayCaster(const TriangleMesh& wsMesh);
    ~RayCaster();
    RayCaster(RayCaster&&) noexcept;
    RayCaster& operator=(RayCaster&&) noexcept;
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // All queries below are const and safe to call concurrently (e.g. from TBB tasks); a
    // moved-from RayCaster must not be queried. Rays with tNear > tFar hit nothing. An Embree
    // error during a query throws std::runtime_error with Embree's message.

    // Whether any triangle is hit with t in [tNear, tFar] (rtcOccluded1).
    bool Occluded(const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection, double tNear,
                  double tFar) const;
    // The closest hit with t in [tNear, tFar], if any (rtcIntersect1).
    std::optional<Hit> Intersect(const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection,
                                 double tNear, double tFar) const;
    // How the rays of a batch are ordered, which selects Embree's traversal for the packets
    // (RTC_INTERSECT_CONTEXT_FLAG_COHERENT or _INCOHERENT). Measured on 562,500 shadow rays
    // towards one light over a 20k-triangle scene, 2 shared cores (bench/spatial_bench.cpp): in
    // frame order, coherent ~71-78 M rays/s vs incoherent ~57 M; shuffled, coherent ~13 M vs
    // incoherent ~25 M. A wrong hint costs up to 2× but never changes the answers.
    enum class RayOrder {
        kCoherent,   // consecutive rays are neighbours (frame order towards one light)
        kIncoherent  // no useful order
    };

    // The world ray wsOrigin + t·wsDirection, t ∈ [tNear, tFar], as a ShadowRay of this caster.
    ShadowRay ToShadowRay(const glm::dvec3& wsOrigin, const glm::dvec3& wsDirection, double tNear,
                          double tFar) const;
    // occluded[i] = Occluded of the world ray rays[i] stands for, as 0 or 1, for every i. Rays go
    // to Embree in packets of 16 (rtcOccluded16), in chunks spread over TBB worker threads. Throws
    // std::invalid_argument when the spans differ in size.
    void OccludedBatch(std::span<const ShadowRay> rays, std::span<std::uint8_t> occluded,
                       RayOrder order = RayOrder::kCoherent) const;

    std::size_t TriangleCount() const;
    const UnitFrame& Frame() const;  // the frame of the mesh's bounds (scene.h)

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace lexel::spatial
