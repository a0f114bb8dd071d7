// What lexel knows of a 3D light-matrix method without computing it: its name, one line of
// description, its citation, its family, its traits and its analytic storage model. Every list of
// methods that a report, a flag check, `lexel storage`, the GL backend, the Python module or a
// script needs is a query of the registry below; the records themselves are declared once, in
// one file per family (spatial/methods/*_methods.cpp), or by RegisterMethod (registry.h).
// Reading this header needs none of the methods' inputs: what computes a method is method.h.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lexel::spatial {

// The method names the library itself refers to: Table 1's optimal as published, the fair
// comparison's reference, and the bound the evaluator scores against the truth (oracle.h).
inline constexpr const char* kReportOptimalMethod = "optimal-report";
inline constexpr const char* kOptimalMethod = "optimal";
inline constexpr const char* kOracleMethod = "optimal-oracle";

// The file that declares a built-in method (spatial/methods/<family>_methods.cpp); kRegistered
// for RegisterMethod's.
enum class MethodFamily {
    kOptimizer,    // Algorithm 1 (optimizer.h, multi_start.h)
    kBaseline,     // the published single maps (baselines.h)
    kWarped,       // one map with a nonlinear parameterization (map_warp.h)
    kPartitioned,  // k cascades at the same total texels (partitions.h)
    kTrapezoid,    // trapezoidal shadow maps (tsm.h)
    kVirtual,      // virtual shadow maps: pages at equal physical texels (virtual_shadow_map.h)
    kBound,        // the best single matrix by the measured error (oracle.h)
    kRegistered,   // added by RegisterMethod
};
// "optimizer", "baseline", "warped", "partitioned", "trapezoid", "virtual", "bound", "registered".
std::string_view MethodFamilyName(MethodFamily family);

// Which of Lloyd et al.'s closed forms ("Warping and Partitioning for Low Error Shadow Maps",
// EGSR 2006) `lexel storage` sets beside the method's measured storage factor S̄.
enum class StorageModel {
    kBestSingleMap,         // the least S̄ of any single perspective map (min over n')
    kUnwarped,              // one map, no warp ("no warp")
    kLispsm,                // one LiSPSM map, η = 0
    kPsm,                   // one PSM map, η = 1
    kTrapezoid,             // one map with n' = (f − n) / (3 sin γ): TSM's 80% rule
    kLogPsm,                // LogPSM (S̄_opt with the light overhead)
    kAdaptive,              // warps that follow the scene (RTW): no closed form, no value
    kZPartitions,           // k unwarped z-partitions ("ZP")
    kZPartitionsWarped,     // k warped z-partitions ("ZP + W")
    kFacePartitionsWarped,  // a warped map per frustum face ("FP + W")
    kVirtualLevels,         // unwarped z-partitions, k = ⌈log₂ f/n⌉: a level per halving
};
// "best-single-map", "unwarped", "lispsm", "psm", "trapezoid", "logpsm", "adaptive",
// "z-partitions", "z-partitions-warped", "face-partitions-warped", "virtual-levels".
std::string_view StorageModelName(StorageModel model);

struct MethodTraits {
    bool fairTable = false;      // a row of the fair comparison (optimal the reference)
    bool reportTable = false;    // a row of Table 1 as published (optimal-report the reference)
    bool optIn = false;          // runs only when named: in no default list
    bool frustumFitted = false;  // fits the view frustum ∩ scene bounds, as the report's baselines
    bool optimizer = false;      // runs Algorithm 1 for one map (its trace is reported)
    bool partitioned = false;    // returns k cascades at the same total texels
    bool virtualMap = false;     // returns a virtual map of pages
    bool warped = false;         // its map's parameterization is not a light matrix
    bool gpuMap = true;          // the GL backend renders its map (logpsm's is ray-cast on the CPU)
};

struct MethodInfo {
    std::string name{};         // IsValidMethodName
    std::string description{};  // one line, for `lexel --help`
    std::string citation{};     // authors, title, venue, year; empty for lexel's own variants
    MethodFamily family = MethodFamily::kRegistered;
    MethodTraits traits{};
    StorageModel storage = StorageModel::kBestSingleMap;
};

// Every method, built-in first in their families' order (optimizer, baseline, warped,
// partitioned, trapezoid, virtual, bound), then the registered ones in registration order; the
// opt-in ones included.
std::vector<MethodInfo> MethodInfos();
// The method's record; nullptr for an unknown name (a case's own method, for one).
const MethodInfo* FindMethodInfo(std::string_view name);

// The default list, the order every report keeps: the fair table's methods, then Table 1's
// others, then every other method that is not opt-in, each part in registry order.
std::vector<std::string> SpatialMethodNames();
std::vector<std::string> FairMethodNames();    // traits.fairTable (reference: optimal)
std::vector<std::string> ReportMethodNames();  // traits.reportTable (reference: optimal-report)
std::vector<std::string> OptInMethodNames();   // traits.optIn, run only when named
// The methods of one family that are not opt-in, in registry order.
std::vector<std::string> MethodNamesOf(MethodFamily family);
// The methods that run Algorithm 1 for one map, opt-in ones included: the one list the
// evaluator, the frame pipeline and `lexel timing --optimizer` take them from.
std::vector<std::string> OptimizerMethodNames();
// Whether ComputeLightMatrix knows the name (a default or an opt-in method).
bool IsSpatialMethod(std::string_view name);
// One line saying what the method is; empty for an unknown name.
std::string_view SpatialMethodDescription(std::string_view name);

// A trait of a known method; false for an unknown name.
bool IsOptimizerMethod(std::string_view name);
bool IsPartitionedMethod(std::string_view name);
bool IsVirtualMethod(std::string_view name);
bool IsWarpedMethod(std::string_view name);
bool IsFrustumFittedMethod(std::string_view name);
// Whether the GL backend renders the method's map; true for an unknown name (a given matrix).
bool RendersOnGl(std::string_view name);

// Whether `name` can name a method: 1 to 64 characters of [A-Za-z0-9_.+-], not starting with '-'
// (it appears in CSV columns, image file names and --method values).
bool IsValidMethodName(std::string_view name);

}  // namespace lexel::spatial
