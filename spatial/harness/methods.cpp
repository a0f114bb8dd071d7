#include "lexel/spatial/harness/methods.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <stdexcept>

#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/harness/oracle.h"
#include "lexel/spatial/harness/warped_methods.h"
#include "lexel/spatial/multi_start.h"
#include "lexel/spatial/tsm.h"

namespace lexel::spatial {

std::vector<std::string> FairMethodNames() {
    return {kOptimalMethod,  "optimal-refined", "optimal-h",     "focused-tight", "lispsm-tight",
            "lispsm-engine", "psm-tight",       "plane-optimal", "normal"};
}

std::vector<std::string> ReportMethodNames() {
    return {kReportOptimalMethod, "focused", "lispsm", "plane-optimal", "normal", "psm"};
}

namespace {

struct NamedPartition {
    std::string_view name;
    PartitionScheme scheme;
    bool snap = false;
    // sdsm-optimal-h: h as published (eq. 6) instead of the case's energy (e with the prior by
    // default), for its searches and the Lagrange allocation's costs.
    bool onReportEnergy = false;
    bool optIn = false;  // run only when named (OptInMethodNames)
};

constexpr NamedPartition kPartitions[] = {
    {"pssm", PartitionScheme::kPssm},
    {"sdsm", PartitionScheme::kSdsm},
    {"sdsm-snap", PartitionScheme::kSdsm, true},
    {"sdsm-rect", PartitionScheme::kSdsmRect},
    {"zp-lispsm", PartitionScheme::kZpLispsm},
    {"fp-lispsm", PartitionScheme::kFpLispsm},
    {"sdsm-optimal", PartitionScheme::kSdsmOptimal},
    {"sdsm-optimal-h", PartitionScheme::kSdsmOptimal, false, true, true},
};

}  // namespace

std::vector<std::string> PartitionedMethodNames() {
    std::vector<std::string> names;
    for (const NamedPartition& p : kPartitions)
        if (!p.optIn) names.emplace_back(p.name);
    return names;
}

std::vector<std::string> TsmMethodNames() { return {"tsm", "tsm-report"}; }

std::vector<std::string> VirtualMethodNames() { return {"vsm", "vsm-dynamic"}; }

bool IsVirtualMethod(std::string_view name) { return name == "vsm" || name == "vsm-dynamic"; }

std::vector<std::string> OptInMethodNames() {
    return {"optimal-refined-h", "sdsm-optimal-h", kOracleMethod};
}

namespace {

// The registered methods (RegisterMethod): a deque, so that a pointer to one stays valid while
// more are added.
struct Registry {
    std::mutex mutex;
    std::deque<MethodRegistration> methods;
};

Registry& TheRegistry() {
    static Registry registry;
    return registry;
}

const MethodRegistration* FindRegistered(std::string_view name) {
    Registry& registry = TheRegistry();
    const std::lock_guard lock(registry.mutex);
    for (const MethodRegistration& m : registry.methods)
        if (m.name == name) return &m;
    return nullptr;
}

std::vector<std::string> BuiltInMethodNames() {
    std::vector<std::string> names = FairMethodNames();
    for (const std::string& m : ReportMethodNames())
        if (std::find(names.begin(), names.end(), m) == names.end()) names.push_back(m);
    names.push_back("optimal-shear");
    for (const std::string& m : WarpedMethodNames()) names.push_back(m);
    for (const std::string& m : PartitionedMethodNames()) names.push_back(m);
    for (const std::string& m : TsmMethodNames()) names.push_back(m);
    for (const std::string& m : VirtualMethodNames()) names.push_back(m);
    return names;
}

// The names RegisterMethod must not take: the built-in ones and the opt-in ones.
std::vector<std::string> ReservedMethodNames() {
    std::vector<std::string> names = BuiltInMethodNames();
    for (std::string& m : OptInMethodNames()) names.push_back(std::move(m));
    return names;
}

}  // namespace

std::vector<std::string> RegisteredMethodNames() {
    Registry& registry = TheRegistry();
    const std::lock_guard lock(registry.mutex);
    std::vector<std::string> names;
    for (const MethodRegistration& m : registry.methods) names.push_back(m.name);
    return names;
}

std::vector<std::string> SpatialMethodNames() {
    std::vector<std::string> names = BuiltInMethodNames();
    for (std::string& m : RegisteredMethodNames()) names.push_back(std::move(m));
    return names;
}

std::vector<GivenMatrix> GivenMatricesOf(std::span<const CaseMethod> caseMethods,
                                         std::span<const std::string> methods, bool forSweep,
                                         std::size_t light) {
    std::vector<GivenMatrix> given;
    for (const CaseMethod& m : caseMethods)
        if (m.forSweep == forSweep && light < m.clipFromWorld.size() &&
            std::find(methods.begin(), methods.end(), m.name) != methods.end())
            given.push_back({m.name, m.clipFromWorld[light]});
    return given;
}

bool IsValidMethodName(std::string_view name) {
    if (name.empty() || name.size() > 64 || name.front() == '-') return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '.' || c == '+' || c == '-';
    });
}

bool RegisterMethod(MethodRegistration method) {
    if (!IsValidMethodName(method.name))
        throw std::invalid_argument("RegisterMethod: '" + method.name +
                                    "' is not a method name (1 to 64 of A-Z a-z 0-9 _ . + -)");
    if (method.description.empty() || !method.compute)
        throw std::invalid_argument("RegisterMethod: '" + method.name +
                                    "' needs a description and a compute function");
    const std::vector<std::string> builtIn = ReservedMethodNames();
    Registry& registry = TheRegistry();
    const std::lock_guard lock(registry.mutex);
    const bool taken =
        std::find(builtIn.begin(), builtIn.end(), method.name) != builtIn.end() ||
        std::any_of(registry.methods.begin(), registry.methods.end(),
                    [&](const MethodRegistration& m) { return m.name == method.name; });
    if (taken)
        throw std::invalid_argument("RegisterMethod: '" + method.name + "' is already a method");
    registry.methods.push_back(std::move(method));
    return true;
}

namespace {

struct MethodDescription {
    std::string_view name, description;
};

// One line per method of SpatialMethodNames (cases/README.md, "3D methods", says more).
constexpr MethodDescription kDescriptions[] = {
    {kOptimalMethod,
     "Algorithm 1 from every baseline's start on the edge energy e (fair reference)"},
    {"optimal-refined", "optimal, its best start refined on e by Ceres LBFGS, collapses rejected"},
    {"optimal-h", "Algorithm 1 from every baseline's start on the report's h (eq. 6)"},
    {"focused-tight", "focused's axis, minimum-area rectangle around the visible points"},
    {"lispsm-tight", "LiSPSM (Wimmer et al. 2004) fitted to the visible points"},
    {"lispsm-engine", "lispsm-tight with the engines' n (z1 = z0 + d sin γ: Filament, OGRE)"},
    {"psm-tight", "PSM (Stamminger & Drettakis 2002) fitted to the visible points"},
    {"plane-optimal", "Chong & Gortler 2004: the floor plane's optimum, refitted to the view"},
    {"normal", "the light's frustum over the scene bounds"},
    {kReportOptimalMethod,
     "Algorithm 1 as published: from focused's axis only (Table 1's optimal)"},
    {"focused", "the report's focused map: view frustum and scene bounds on the light's plane"},
    {"lispsm", "LiSPSM for the view frustum and scene bounds, as the report ran it"},
    {"psm", "PSM with Kozlov's fixes for the view frustum and scene bounds"},
    {"optimal-shear", "Algorithm 1 with the report's affine shear (Fig. 3), optimized exactly"},
    {"rtw", "Rosen 2012: focused-tight + two 1-D warps from the readback's importance"},
    {"rtw-lagrange", "rtw's warps with Lagrange densities of h's per-sample cost per row/column"},
    {"logpsm", "Lloyd et al. 2008: perspective warp, then the log of its depth (CPU map)"},
    {"pssm", "cascades: Zhang et al. 2006's split depths, a focused-tight map each"},
    {"sdsm", "cascades: Lauritzen et al. 2011, log splits of the visible depth range"},
    {"sdsm-snap", "sdsm with texel snapping for directional lights"},
    {"sdsm-rect", "sdsm's partitions, each fitted with the minimum-area rectangle"},
    {"zp-lispsm", "cascades: Lloyd et al. 2006's log z-partitions, LiSPSM in each"},
    {"fp-lispsm", "Lloyd et al. 2006's face partitioning: a LiSPSM map per face wedge"},
    {"sdsm-optimal", "sdsm's partitions, optimal (multi-start on e) in each"},
    {"tsm", "Martin & Tan 2004: the trapezoid around the visible points, 80% focus rule"},
    {"tsm-report", "tsm as the paper fits it: the view frustum and scene bounds"},
    {"vsm", "virtual shadow map: 16k² pages at the footprint's level, the single map's texels"},
    {"vsm-dynamic", "vsm with the LOD bias raised until its pages fit the pool (UE5)"},
    {"optimal-refined-h", "optimal-h, its best start refined on h by Ceres LBFGS"},
    {"sdsm-optimal-h", "sdsm's partitions, optimal-h (multi-start on h) in each"},
    {kOracleMethod, "bound: the best single matrix by the measured error (scored on the rays)"},
};

}  // namespace

std::string_view SpatialMethodDescription(std::string_view name) {
    for (const MethodDescription& d : kDescriptions)
        if (d.name == name) return d.description;
    if (const MethodRegistration* m = FindRegistered(name)) return m->description;
    return {};
}

bool IsSpatialMethod(std::string_view name) {
    const std::vector<std::string> names = SpatialMethodNames();
    const std::vector<std::string> optIn = OptInMethodNames();
    return std::find(names.begin(), names.end(), name) != names.end() ||
           std::find(optIn.begin(), optIn.end(), name) != optIn.end();
}

bool IsFrustumFittedMethod(std::string_view name) {
    return name == "focused" || name == "lispsm" || name == "psm" || name == "tsm-report";
}

namespace {

constexpr std::string_view kOptimizerMethods[] = {kReportOptimalMethod, kOptimalMethod,
                                                  "optimal-refined",    "optimal-h",
                                                  "optimal-refined-h",  "optimal-shear"};

}  // namespace

std::vector<std::string> OptimizerMethodNames() {
    return {std::begin(kOptimizerMethods), std::end(kOptimizerMethods)};
}

bool IsOptimizerMethod(std::string_view name) {
    return std::find(std::begin(kOptimizerMethods), std::end(kOptimizerMethods), name) !=
           std::end(kOptimizerMethods);
}

bool IsPartitionedMethod(std::string_view name) {
    for (const NamedPartition& p : kPartitions)
        if (p.name == name) return true;
    return false;
}

BaselineContext MakeBaselineContext(const Scene& scene, const LightSpace& lightSpace,
                                    const Bounds& wsBounds, std::span<const glm::dvec3> wsRelevant,
                                    std::span<const glm::dvec3> wsRelevantHull) {
    BaselineContext context;
    context.lightSpace = &lightSpace;
    context.camera = scene.camera;
    context.map = scene.shadowMap;
    context.wsBounds = wsBounds;
    context.wsRelevant = wsRelevant;
    context.wsRelevantHull = wsRelevantHull;
    context.floorPlane = scene.floorPlane;
    return context;
}

namespace {

using Baseline = LightMatrix (*)(const BaselineContext&, BaselineDiagnostics*);

struct NamedBaseline {
    std::string_view name;
    Baseline compute;
};

constexpr NamedBaseline kBaselines[] = {
    {"normal", &NormalLightMatrix},
    {"focused", &FocusedLightMatrix},
    {"lispsm", &LispsmLightMatrix},
    {"psm", &PsmLightMatrix},
    {"plane-optimal", &PlaneOptimalLightMatrix},
    {"focused-tight", &FocusedTightLightMatrix},
    {"lispsm-tight", &LispsmTightLightMatrix},
    {"lispsm-engine", &LispsmEngineLightMatrix},
    {"psm-tight", &PsmTightLightMatrix},
    {"tsm", &TsmLightMatrix},
    {"tsm-report", &TsmReportLightMatrix},
};

MethodMatrix Optimal(std::string_view name, const MethodContext& context) {
    if (!context.samples) throw std::invalid_argument(std::string(name) + " needs the samples");
    const Resolution map = context.baseline.map;
    OptimizerOptions options;
    if (name == kOptimalMethod || name == "optimal-refined") {
        options = EdgeOptimizerOptions();
        options.energy.exponent = context.edgeExponent;
    }
    options.maxSamples = context.maxSamples;
    if (name == kOptimalMethod || name == "optimal-refined" || name == "optimal-h" ||
        name == "optimal-refined-h") {
        options.refine = name == "optimal-refined" || name == "optimal-refined-h";
        const std::vector<OptimizerStart> starts = StandardStarts(context.baseline);
        MultiStartResult r = OptimizeFromStarts(*context.samples, starts, map, options);
        return {r.result.matrix,
                std::move(r.result),
                std::move(r.winner),
                {},
                std::nullopt,
                std::nullopt,
                {}};
    }
    // The report's single start (optimal-report), or with the shear (optimal-shear).
    options.shear = name == "optimal-shear";
    const BaselineContext& b = context.baseline;
    const glm::dvec3 initialP4 = InitialLightAxis(*b.lightSpace, b.wsBounds, b.wsRelevant);
    // The report's own samples: no thin-shadow contacts (samples.h).
    OptimizerResult r =
        OptimizeLightMatrix(PublishedSamples(*context.samples), initialP4, map, options);
    return {r.matrix, std::move(r), {}, {}, std::nullopt, std::nullopt, {}};
}

MethodMatrix Partitioned(const NamedPartition& partition, const MethodContext& context) {
    if (!context.samples)
        throw std::invalid_argument(std::string(partition.name) + " needs the samples");
    PartitionOptions options = context.partitions;
    options.snap = partition.snap;
    if (partition.onReportEnergy) options.energy = EnergyOptions{};
    MethodMatrix m;
    m.cascades =
        PartitionedLightMatrices(partition.scheme, context.baseline, *context.samples, options);
    m.matrix = m.cascades.front().matrix;
    return m;
}

MethodMatrix Virtual(std::string_view name, const MethodContext& context) {
    if (!context.readback) throw std::invalid_argument(std::string(name) + " needs the readback");
    VirtualMapOptions options;
    options.fitPool = name == "vsm-dynamic";
    MethodMatrix m;
    m.virtualMap = BuildVirtualShadowMap(context.baseline, *context.readback, options);
    const VirtualMapLayout& layout = m.virtualMap->layout;
    m.matrix = layout.PageMatrix({layout.maxLevel, 0, 0});
    return m;
}

MethodMatrix Given(const GivenMatrix& given, const MethodContext& context) {
    const BaselineContext& b = context.baseline;
    std::string failure;
    const std::optional<LightMatrix> matrix = LightMatrixFromClip(
        *b.lightSpace, given.clipFromWorld, b.map, b.wsBounds.Center(), &failure);
    if (!matrix)
        throw std::invalid_argument("method '" + given.name + "': its clip_from_world " + failure);
    MethodMatrix m;
    m.matrix = *matrix;
    return m;
}

}  // namespace

MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context) {
    for (const GivenMatrix& g : context.given)
        if (g.name == name) return Given(g, context);
    for (const NamedBaseline& b : kBaselines)
        if (b.name == name)
            return {b.compute(context.baseline, nullptr),
                    std::nullopt,
                    {},
                    {},
                    std::nullopt,
                    std::nullopt,
                    {}};
    if (IsOptimizerMethod(name)) return Optimal(name, context);
    for (const NamedPartition& p : kPartitions)
        if (p.name == name) return Partitioned(p, context);
    if (IsVirtualMethod(name)) return Virtual(name, context);
    if (IsWarpedMethod(name)) return WarpedLightMatrix(name, context);
    if (const MethodRegistration* m = FindRegistered(name)) return m->compute(context);
    if (name == kOracleMethod)
        throw std::invalid_argument(
            std::string(name) + " is scored against the truth: Evaluator::Evaluate computes it");
    throw std::invalid_argument("unknown 3D method '" + std::string(name) + "'");
}

}  // namespace lexel::spatial
