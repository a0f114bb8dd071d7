// The names of the 3D harness's methods and their families, without what computes them
// (methods.h): what a report, a flag check or the frame pipeline needs to know of a method, so
// that they need not include the methods' inputs (baselines, optimizer, partitions). The lists are
// kept in methods.cpp, the registry's one place.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lexel::spatial {

// The two method names the library itself refers to (every other name lives in methods.cpp's
// list only): Table 1's optimal as published, and the fair comparison's reference.
inline constexpr const char* kReportOptimalMethod = "optimal-report";
inline constexpr const char* kOptimalMethod = "optimal";

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
// optimal-refined before it moved to e); `sdsm-optimal-h`: sdsm-optimal's searches and
// its Lagrange costs on h (eq. 6) whatever the case's cascade energy;
// `optimal-oracle` (oracle.h): the bound, which the Evaluator computes against the truth
// (ComputeLightMatrix refuses it). `optimal`, `optimal-refined` and `sdsm-optimal` are on e with
// the footprint prior (kEdgeEnergy, energy.h; the refinement under the collapse guard).
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

// Whether `name` can name a method: 1 to 64 characters of [A-Za-z0-9_.+-], not starting with '-'
// (it appears in CSV columns, image file names and --method values).
bool IsValidMethodName(std::string_view name);

// The registered methods' names (RegisterMethod, methods.h), in registration order.
std::vector<std::string> RegisteredMethodNames();

}  // namespace lexel::spatial
