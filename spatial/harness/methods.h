// The named light-matrix methods of the 3D harness (report §3): one registry so that `lexel run`,
// `lexel sweep` and the tests agree on names, order and inputs. Two families:
//   - the report's Table 1 as published: `optimal-report` (Algorithm 1 from focused's axis alone),
//     `focused`, `lispsm`, `psm` fitted to the view frustum ∩ scene bounds, `plane-optimal`,
//     `normal`;
//   - the fair comparison, every method on the optimizer's own information (the visible points,
//     the same margin): `optimal` (Algorithm 1 from every baseline's start, multi_start.h),
//     `optimal-refined` (its best start refined by Ceres), `focused-tight`, `lispsm-tight`,
//     `lispsm-engine` (LiSPSM with the n rule Filament and OGRE ship), `psm-tight`,
//     `plane-optimal`, `normal`;
// and `optimal-shear` (Algorithm 1 with the report's Fig. 3 shear, optimized exactly). The
// partitioned methods (partitions.h) return k cascades at the same total texels: `pssm`, `sdsm`,
// `sdsm-snap` (SDSM with texel snapping), `sdsm-rect`, `zp-lispsm`, `fp-lispsm`, `sdsm-optimal`.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// The baselines' context for a scene: its camera, shadow-map resolution and floor plane, the
// visible points and their hull, and Algorithm 1's margin.
BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant,
                                    std::span<const glm::dvec3> wsRelevantHull = {});

struct MethodContext {
    BaselineContext baseline;               // its samples are set: plane-optimal uses them
    const LightSamples* samples = nullptr;  // boundary samples and relevant points (light space)
    PartitionOptions partitions;            // k, λ and the allocation of the partitioned methods
};

// Every method: the fair comparison's first (optimal its reference), then the report's, then
// optimal-shear, then the partitioned ones.
std::vector<std::string> SpatialMethodNames();
// The report's Table 1 as published (reference: optimal-report).
std::vector<std::string> ReportMethodNames();
// The fair comparison (reference: optimal).
std::vector<std::string> FairMethodNames();
// The partitioned methods, each compared with optimal at the same total texels.
std::vector<std::string> PartitionedMethodNames();
bool IsSpatialMethod(std::string_view name);
// One line saying what the method is (for `lexel --help`); empty for an unknown name.
std::string_view SpatialMethodDescription(std::string_view name);
bool IsPartitionedMethod(std::string_view name);

// The matrix; for the optimal* methods the optimizer's trace (h per iteration, time profile)
// and, for the multi-start ones, which start won; for a partitioned method its cascades (and
// `matrix` the first cascade's).
struct MethodMatrix {
    LightMatrix matrix;
    std::optional<OptimizerResult> optimizer;
    std::string winner;  // optimal, optimal-refined: the start whose map or search won; else empty
    std::vector<Cascade> cascades;  // partitioned methods only
};
// std::invalid_argument for an unknown name, or an optimal* or partitioned method without samples.
MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context);

}  // namespace lexel::spatial
