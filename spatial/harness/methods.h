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
// Trapezoidal shadow maps (tsm.h): `tsm` (fair) and `tsm-report` (the paper's view frustum).
// Virtual shadow maps (virtual_shadow_map.h): `vsm` and `vsm-dynamic`, pages at equal texels.
// The warped methods (warped_methods.h) return one map with a nonlinear parameterization: `rtw`,
// `rtw-lagrange`, `logpsm`.
//
// Two more kinds extend the list without editing this file: methods registered in C++
// (RegisterMethod, CONTRIBUTING.md "Add a method in one file"), after the built-in ones in
// SpatialMethodNames, and a case's own methods, one clip matrix per light (GivenMatrix: the case
// loader reads them, cases/README.md "Methods of a case"), which only their case knows.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/map_warp.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/virtual_shadow_map.h"

namespace lexel::spatial {

// The two method names the library itself refers to (every other name lives in methods.cpp's
// list only): Table 1's optimal as published, and the fair comparison's reference.
inline constexpr const char* kReportOptimalMethod = "optimal-report";
inline constexpr const char* kOptimalMethod = "optimal";

// The baselines' context for a scene: its camera, shadow-map resolution and floor plane, the
// visible points and their hull, and Algorithm 1's margin.
BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant,
                                    std::span<const glm::dvec3> wsRelevantHull = {});

// A case's own method for the light being evaluated: its name and the light's clip matrix
// (OpenGL clip space, the form ClipFromWorld returns; its depth row is ignored).
struct GivenMatrix {
    std::string name;
    glm::dmat4 clipFromWorld{1.0};
};

struct MethodContext {
    BaselineContext baseline;               // its samples are set: plane-optimal uses them
    const LightSamples* samples = nullptr;  // boundary samples and relevant points (light space)
    PartitionOptions partitions;            // k, λ and the allocation of the partitioned methods
    const Readback* readback =
        nullptr;       // the readback (vsm*'s page requests, rtw's importance map)
    Resolution frame;  // the final frame's size (rtw's sampling rates)
    // The case's own methods for this light (looked up by name before the registry); may be empty.
    std::span<const GivenMatrix> given;
    // The optimal* methods' sample budget (OptimizerOptions::maxSamples; 0: every sample).
    std::size_t maxSamples = 0;
};

// The matrices for light `light` (an index into the fixed lights, or into the sweep's lights when
// forSweep) of the scene's own methods (Scene::methods) that are among `methods` and for those
// lights; none when forSweep differs from theirs.
std::vector<GivenMatrix> GivenMatricesOf(std::span<const CaseMethod> caseMethods,
                                         std::span<const std::string> methods, bool forSweep,
                                         std::size_t light);

// Every method: the fair comparison's first (optimal its reference), then the report's, then
// optimal-shear, then the warped ones, then the partitioned ones, then tsm and the virtual ones,
// then the registered ones (RegisterMethod) in the order they were registered.
std::vector<std::string> SpatialMethodNames();
// The report's Table 1 as published (reference: optimal-report).
std::vector<std::string> ReportMethodNames();
// The fair comparison (reference: optimal).
std::vector<std::string> FairMethodNames();
// The partitioned methods, each compared with optimal at the same total texels.
std::vector<std::string> PartitionedMethodNames();
// Trapezoidal shadow maps (tsm.h): tsm on the fair comparison's information, tsm-report fitted
// as the paper does (view frustum ∩ scene bounds).
std::vector<std::string> TsmMethodNames();
// Virtual shadow maps (virtual_shadow_map.h) at the single map's physical texels: `vsm` requests
// pages at the level each pixel's footprint asks for and drops the least requested when the pool
// is full; `vsm-dynamic` raises the LOD bias until the requests fit (UE5's dynamic resolution).
std::vector<std::string> VirtualMethodNames();
bool IsVirtualMethod(std::string_view name);
// Methods that run only when asked for by name: not in SpatialMethodNames (so every default list
// and its outputs stay as they are), yet computed by ComputeLightMatrix and described by
// SpatialMethodDescription. `optimal-refined-h`: optimal-h's best start refined on h (today's
// optimal-refined before issue 25 moved it to e); `sdsm-optimal-e`: sdsm-optimal on e (measured
// worse than on h at equal texels, RESULTS.md, so not the default);
// `optimal-oracle` (oracle.h): the bound, which the Evaluator computes against the truth
// (ComputeLightMatrix refuses it). `optimal` and `optimal-refined` are on e with the footprint
// prior (kEdgeEnergy, energy.h; the refinement under the collapse guard).
std::vector<std::string> OptInMethodNames();
// Whether ComputeLightMatrix knows the name: SpatialMethodNames or OptInMethodNames.
bool IsSpatialMethod(std::string_view name);
// One line saying what the method is (for `lexel --help`); empty for an unknown name.
std::string_view SpatialMethodDescription(std::string_view name);
bool IsPartitionedMethod(std::string_view name);
// The methods that run Algorithm 1 for one map (optimizer.h, multi_start.h): optimal-report,
// optimal, optimal-refined, optimal-h, optimal-refined-h, optimal-shear. The one list the
// evaluator, the frame pipeline and `lexel timing --optimizer` take them from.
std::vector<std::string> OptimizerMethodNames();
bool IsOptimizerMethod(std::string_view name);
// Whether the method fits the view frustum ∩ scene bounds as the report's baselines do (focused,
// lispsm, psm, tsm-report) rather than the visible points: such a method belongs beside Table 1
// as published, not in the fair comparison.
bool IsFrustumFittedMethod(std::string_view name);

// The matrix; for the optimal* methods the optimizer's trace (h per iteration, time profile)
// and, for the multi-start ones, which start won; for a partitioned method its cascades (and
// `matrix` the first cascade's).
struct MethodMatrix {
    LightMatrix matrix;
    std::optional<OptimizerResult> optimizer;
    std::string winner;  // optimal, optimal-refined: the start whose map or search won; else empty
    std::vector<Cascade> cascades;  // partitioned methods only
    // vsm*: the virtual map and its resident pages (`matrix` is then its coarsest page's).
    std::optional<VirtualShadowMap> virtualMap;
    // Warped methods (rtw, rtw-lagrange, logpsm: warped_methods.h): the map's parameterization,
    // whose base is `matrix`, and its resolution when it is not the scene's (0 × 0: the scene's).
    std::optional<MapWarp> warp;
    Resolution resolution;
};
// std::invalid_argument for an unknown name, an optimal* or partitioned method without samples,
// a vsm* method without the readback, or a given matrix (context.given) that does not project
// from the light (LightMatrixFromClip, clip_matrix.h).
MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context);

// Whether `name` can name a method: 1 to 64 characters of [A-Za-z0-9_.+-], not starting with '-'
// (it appears in CSV columns, image file names and --method values).
bool IsValidMethodName(std::string_view name);

// A method added from outside the built-in list (CONTRIBUTING.md, "Add a method in one file"):
// `compute` returns its light matrix (MethodMatrix::matrix) or its cascades (::cascades, with
// `matrix` the first one's) from the context of one light, as the built-in methods do.
struct MethodRegistration {
    std::string name;         // IsValidMethodName, not yet known to IsSpatialMethod
    std::string description;  // one line for `lexel --help`
    std::function<MethodMatrix(const MethodContext&)> compute;
};
// Adds the method to SpatialMethodNames (after every earlier one), IsSpatialMethod,
// SpatialMethodDescription and ComputeLightMatrix; the built-in methods and their order are
// unchanged. Thread-safe; a method cannot be removed. Returns true (for `static const bool r =
// RegisterMethod(...)` at namespace scope). Throws std::invalid_argument for an invalid or taken
// name, an empty description or no compute function.
bool RegisterMethod(MethodRegistration method);
// The registered methods' names, in registration order.
std::vector<std::string> RegisteredMethodNames();

}  // namespace lexel::spatial
