// The registry of 3D methods (registry.h, method_info.h).
#include "lexel/spatial/methods/registry.h"

#include <algorithm>
#include <deque>
#include <mutex>
#include <stdexcept>

#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/methods/families.h"

namespace lexel::spatial {

namespace {

// The built-in families, in the order every listing keeps.
const std::vector<MethodDescriptor>& BuiltInMethods() {
    static const std::vector<MethodDescriptor> methods = [] {
        std::vector<MethodDescriptor> all;
        for (auto family : {&OptimizerMethods, &BaselineMethods, &WarpedMethods,
                            &PartitionedMethods, &TrapezoidMethods, &VirtualMethods, &BoundMethods})
            for (MethodDescriptor& m : family()) all.push_back(std::move(m));
        return all;
    }();
    return methods;
}

// The registered methods: a deque, so that a pointer to one stays valid while more are added.
struct Registered {
    std::mutex mutex;
    std::deque<MethodDescriptor> methods;
};

Registered& TheRegistered() {
    static Registered registered;
    return registered;
}

const MethodDescriptor* FindMethod(std::string_view name) {
    for (const MethodDescriptor& m : BuiltInMethods())
        if (m.info.name == name) return &m;
    Registered& registered = TheRegistered();
    const std::lock_guard lock(registered.mutex);
    for (const MethodDescriptor& m : registered.methods)
        if (m.info.name == name) return &m;
    return nullptr;
}

template <typename Predicate>
std::vector<std::string> NamesWhere(Predicate predicate) {
    std::vector<std::string> names;
    for (const MethodInfo& m : MethodInfos())
        if (predicate(m)) names.push_back(m.name);
    return names;
}

bool Contains(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The given matrix's light matrix: the case's own method.
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

std::string_view MethodFamilyName(MethodFamily family) {
    switch (family) {
        case MethodFamily::kOptimizer:
            return "optimizer";
        case MethodFamily::kBaseline:
            return "baseline";
        case MethodFamily::kWarped:
            return "warped";
        case MethodFamily::kPartitioned:
            return "partitioned";
        case MethodFamily::kTrapezoid:
            return "trapezoid";
        case MethodFamily::kVirtual:
            return "virtual";
        case MethodFamily::kBound:
            return "bound";
        case MethodFamily::kRegistered:
            return "registered";
    }
    return "registered";
}

std::string_view StorageModelName(StorageModel model) {
    switch (model) {
        case StorageModel::kBestSingleMap:
            return "best-single-map";
        case StorageModel::kUnwarped:
            return "unwarped";
        case StorageModel::kLispsm:
            return "lispsm";
        case StorageModel::kPsm:
            return "psm";
        case StorageModel::kTrapezoid:
            return "trapezoid";
        case StorageModel::kLogPsm:
            return "logpsm";
        case StorageModel::kAdaptive:
            return "adaptive";
        case StorageModel::kZPartitions:
            return "z-partitions";
        case StorageModel::kZPartitionsWarped:
            return "z-partitions-warped";
        case StorageModel::kFacePartitionsWarped:
            return "face-partitions-warped";
        case StorageModel::kVirtualLevels:
            return "virtual-levels";
    }
    return "best-single-map";
}

std::vector<MethodInfo> MethodInfos() {
    std::vector<MethodInfo> infos;
    for (const MethodDescriptor& m : BuiltInMethods()) infos.push_back(m.info);
    Registered& registered = TheRegistered();
    const std::lock_guard lock(registered.mutex);
    for (const MethodDescriptor& m : registered.methods) infos.push_back(m.info);
    return infos;
}

const MethodInfo* FindMethodInfo(std::string_view name) {
    const MethodDescriptor* m = FindMethod(name);
    return m ? &m->info : nullptr;
}

std::vector<std::string> FairMethodNames() {
    return NamesWhere([](const MethodInfo& m) { return m.traits.fairTable && !m.traits.optIn; });
}

std::vector<std::string> ReportMethodNames() {
    return NamesWhere([](const MethodInfo& m) { return m.traits.reportTable && !m.traits.optIn; });
}

std::vector<std::string> OptInMethodNames() {
    return NamesWhere([](const MethodInfo& m) { return m.traits.optIn; });
}

std::vector<std::string> SpatialMethodNames() {
    std::vector<std::string> names = FairMethodNames();
    for (std::string& m : ReportMethodNames())
        if (!Contains(names, m)) names.push_back(std::move(m));
    for (const MethodInfo& m : MethodInfos())
        if (!m.traits.optIn && !Contains(names, m.name)) names.push_back(m.name);
    return names;
}

std::vector<std::string> MethodNamesOf(MethodFamily family) {
    return NamesWhere(
        [family](const MethodInfo& m) { return m.family == family && !m.traits.optIn; });
}

std::vector<std::string> OptimizerMethodNames() {
    return NamesWhere([](const MethodInfo& m) { return m.traits.optimizer; });
}

bool IsSpatialMethod(std::string_view name) { return FindMethod(name) != nullptr; }

std::string_view SpatialMethodDescription(std::string_view name) {
    const MethodInfo* m = FindMethodInfo(name);
    return m ? std::string_view(m->description) : std::string_view();
}

namespace {

// The trait of a known method; false for an unknown name.
bool HasTrait(std::string_view name, bool MethodTraits::*trait) {
    const MethodInfo* m = FindMethodInfo(name);
    return m && m->traits.*trait;
}

}  // namespace

bool IsOptimizerMethod(std::string_view name) { return HasTrait(name, &MethodTraits::optimizer); }

bool IsPartitionedMethod(std::string_view name) {
    return HasTrait(name, &MethodTraits::partitioned);
}

bool IsVirtualMethod(std::string_view name) { return HasTrait(name, &MethodTraits::virtualMap); }

bool IsWarpedMethod(std::string_view name) { return HasTrait(name, &MethodTraits::warped); }

bool IsFrustumFittedMethod(std::string_view name) {
    return HasTrait(name, &MethodTraits::frustumFitted);
}

bool RendersOnGl(std::string_view name) {
    const MethodInfo* m = FindMethodInfo(name);
    return !m || m->traits.gpuMap;
}

bool IsValidMethodName(std::string_view name) {
    if (name.empty() || name.size() > 64 || name.front() == '-') return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '.' || c == '+' || c == '-';
    });
}

bool RegisterMethod(MethodDescriptor method) {
    const std::string& name = method.info.name;
    if (!IsValidMethodName(name))
        throw std::invalid_argument("RegisterMethod: '" + name +
                                    "' is not a method name (1 to 64 of A-Z a-z 0-9 _ . + -)");
    if (method.info.description.empty() || !method.compute)
        throw std::invalid_argument("RegisterMethod: '" + name +
                                    "' needs a description and a compute function");
    method.info.family = MethodFamily::kRegistered;
    for (const MethodDescriptor& m : BuiltInMethods())
        if (m.info.name == name)
            throw std::invalid_argument("RegisterMethod: '" + name + "' is already a method");
    Registered& registered = TheRegistered();
    const std::lock_guard lock(registered.mutex);
    for (const MethodDescriptor& m : registered.methods)
        if (m.info.name == name)
            throw std::invalid_argument("RegisterMethod: '" + name + "' is already a method");
    registered.methods.push_back(std::move(method));
    return true;
}

MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context) {
    for (const GivenMatrix& g : context.given)
        if (g.name == name) return Given(g, context);
    if (const MethodDescriptor* m = FindMethod(name)) return m->compute(context);
    throw std::invalid_argument("unknown 3D method '" + std::string(name) + "'");
}

}  // namespace lexel::spatial
