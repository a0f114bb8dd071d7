// Partitioned light matrices (cascades.h) built from the same information as every other method
// (the readback's visible points and the light's boundary samples, baselines.h's context), at a
// total texel budget equal to the single map's (context.map):
//   pssm          Zhang et al. 2006: splits C_i = λ n (f/n)^(i/k) + (1 - λ)(n + (f - n) i/k) over
//                 the camera's near and far planes, each partition a focused-tight map of its
//                 visible points;
//   sdsm          Lauritzen et al. 2011 §3–4: logarithmic splits over the visible depth range of
//                 the readback (the first partition from the camera's near plane, the last to its
//                 far plane, for frame pixels beyond the readback's samples), each partition the
//                 light-space bounding box of its points with the camera's view direction along the
//                 map's first axis, no warp (texel snapping, §5.3, with options.snap for
//                 directional lights);
//   sdsm-rect     SDSM's partitions with the minimum-area rectangle instead of the box;
//   zp-lispsm     Lloyd et al. 2006 §5: z-partitioning with logarithmic splits over the camera's
//                 near and far (eq. 15), LiSPSM per partition (n'_i from the partition's own
//                 depths) built as lispsm-tight on its visible points;
//   fp-lispsm     Lloyd et al. 2006 §5.1: face partitioning — the view frustum cut by the planes
//                 through its four side edges parallel to the light direction, one LiSPSM per face
//                 wedge whose view direction is the wedge's bisector (for directional lights; a
//                 point light uses the direction from the light to the scene's centre);
//   sdsm-optimal  SDSM's partitions with Algorithm 1 on each (multi-start, multi_start.h, with
//                 SDSM's box among the starts) minimizing PartitionOptions::energy, on the
//                 partition's own visible points and samples.
// Points and samples are assigned to partitions exactly as pixels are shaded (CascadeFor).
#pragma once

#include <string_view>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/cascades.h"
#include "lexel/spatial/energy.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

enum class PartitionScheme { kPssm, kSdsm, kSdsmRect, kZpLispsm, kFpLispsm, kSdsmOptimal };

// The most partitions a method may have (bounds the maps' memory: their texels add up to the
// single map's, but each costs a render and a shading pass).
inline constexpr int kMaxCascades = 16;

struct PartitionOptions {
    int count = 4;        // k ∈ [1, kMaxCascades] (fp-lispsm: its face wedges, at most 4)
    double lambda = 0.5;  // pssm's blend of the logarithmic and the uniform split
    CascadeAllocation allocation = CascadeAllocation::kEqual;
    bool snap = false;  // sdsm: snap its boxes to whole texels (directional lights)
    // The energy sdsm-optimal's multi-start minimizes per partition (energy.h) and, for every
    // scheme, the Lagrange allocation's cost: e with the prior by default (c_i = e_i N_i^(p/2),
    // N_i ∝ c_i^(1/(1+p/2))), as `optimal`: at the 720² readback its searches beat h's per
    // partition, and on the walkthrough its Lagrange allocation beats the equal split by 2–4%
    // (sdsm) to 23% (pssm) where h's doubles SDSM's errors (RESULTS.md, "The Lagrange allocation");
    // EnergyOptions{} (`sdsm-optimal-h`) is h as published (c_i = h_i N_i, N_i ∝ √c_i).
    EnergyOptions energy = kEdgeEnergy;
    // sdsm-optimal's sample budget per partition (OptimizerOptions::maxSamples; 0: all).
    std::size_t maxSamples = 0;
};

// The cascades of `scheme` for the context's light. Their texels add up to context.map's (equal
// allocation: k maps of (W/√k) × (H/√k), rounded down); kLagrange moves texels toward the
// partitions with the larger cost (c_i = e_i N_i^(p/2), or h_i N_i on h: PartitionOptions::energy).
// An empty partition (no visible point) is kept,
// with visiblePoints = 0 and the whole view's focused-tight map at its resolution. Throws
// DomainError as the baselines do; std::invalid_argument for count outside [1, kMaxCascades].
std::vector<Cascade> PartitionedLightMatrices(PartitionScheme scheme,
                                              const BaselineContext& context,
                                              const LightSamples& samples,
                                              const PartitionOptions& options);

// The samples a cascade serves (by their world points), with their edge normals, the relevant
// points and the prior's points it serves; the relevant points must be context.wsRelevant's, in
// order (MakeLightSamples keeps that order).
LightSamples SamplesOfCascade(const LightSamples& samples, std::span<const glm::dvec3> wsRelevant,
                              const Camera& camera, std::span<const Cascade> cascades,
                              std::size_t cascade);

// h (eq. 6) of a partitioned method: Σ over cascades of h of its matrix over the samples it serves.
double PartitionedEnergy(std::span<const Cascade> cascades, const LightSamples& samples,
                         std::span<const glm::dvec3> wsRelevant, const Camera& camera);
// The same sum of any energy of the family (energy.h), each cascade's prior over the prior points
// it serves: the 4-argument form exactly when energy.IsReport().
double PartitionedEnergy(std::span<const Cascade> cascades, const LightSamples& samples,
                         std::span<const glm::dvec3> wsRelevant, const Camera& camera,
                         const EnergyOptions& energy);

}  // namespace lexel::spatial
