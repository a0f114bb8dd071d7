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
#include "lexel/spatial/harness/method_names.h"
#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/map_warp.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/virtual_shadow_map.h"

namespace lexel::spatial {

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
    PartitionOptions partitions;  // k, λ, the allocation and the energy of the partitioned methods
    const Readback* readback =
        nullptr;       // the readback (vsm*'s page requests, rtw's importance map)
    Resolution frame;  // the final frame's size (rtw's sampling rates)
    // The case's own methods for this light (looked up by name before the registry); may be empty.
    std::span<const GivenMatrix> given;
    // The optimal* methods' sample budget (OptimizerOptions::maxSamples; 0: every sample).
    std::size_t maxSamples = 0;
    // The exponent of optimal's and optimal-refined's edge energy (EnergyOptions::exponent).
    double edgeExponent = kDefaultEdgeExponent;
};

// The matrices for light `light` (an index into the fixed lights, or into the sweep's lights when
// forSweep) of the scene's own methods (Scene::methods) that are among `methods` and for those
// lights; none when forSweep differs from theirs.
std::vector<GivenMatrix> GivenMatricesOf(std::span<const CaseMethod> caseMethods,
                                         std::span<const std::string> methods, bool forSweep,
                                         std::size_t light);

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

}  // namespace lexel::spatial
