// The partitioned family (partitions.h): k cascades whose texels add up to the single map's,
// each compared with optimal at the same total texels; k, λ, the allocation and the energy come
// from MethodContext::partitions.
#include <stdexcept>
#include <string>

#include "lexel/spatial/methods/families.h"

namespace lexel::spatial {

namespace {

constexpr const char* kZhang =
    "F. Zhang, H. Sun, L. Xu, L. K. Lun, \"Parallel-Split Shadow Maps for Large-scale Virtual "
    "Environments\", VRCIA 2006";
constexpr const char* kLauritzen =
    "A. Lauritzen, M. Salvi, A. Lefohn, \"Sample Distribution Shadow Maps\", I3D 2011";
constexpr const char* kLloyd2006 =
    "D. B. Lloyd, D. Tuft, S. Yoon, D. Manocha, \"Warping and Partitioning for Low Error Shadow "
    "Maps\", EGSR 2006";

struct Partition {
    PartitionScheme scheme;
    bool snap = false;  // SDSM's texel snapping (directional lights)
    // sdsm-optimal-h: h as published (eq. 6) instead of the case's energy (e with the prior by
    // default), for its searches and the Lagrange allocation's costs.
    bool onReportEnergy = false;
};

MethodMatrix Partitioned(const std::string& name, Partition partition,
                         const MethodContext& context) {
    if (!context.samples) throw std::invalid_argument(name + " needs the samples");
    PartitionOptions options = context.partitions;
    options.snap = options.snap || partition.snap;
    if (partition.onReportEnergy) options.energy = EnergyOptions{};
    MethodMatrix m;
    m.cascades =
        PartitionedLightMatrices(partition.scheme, context.baseline, *context.samples, options);
    m.matrix = m.cascades.front().matrix;
    return m;
}

MethodDescriptor Cascades(std::string name, std::string description, std::string citation,
                          StorageModel storage, Partition partition, bool optIn = false) {
    MethodInfo info{name,
                    std::move(description),
                    std::move(citation),
                    MethodFamily::kPartitioned,
                    {.optIn = optIn, .partitioned = true},
                    storage};
    return {std::move(info), [name, partition](const MethodContext& context) {
                return Partitioned(name, partition, context);
            }};
}

}  // namespace

std::vector<MethodDescriptor> PartitionedMethods() {
    using enum PartitionScheme;
    constexpr StorageModel kZp = StorageModel::kZPartitions;
    constexpr StorageModel kZpWarp = StorageModel::kZPartitionsWarped;
    return {
        Cascades("pssm", "cascades: Zhang et al. 2006's split depths, a focused-tight map each",
                 kZhang, kZp, {kPssm}),
        Cascades("sdsm", "cascades: Lauritzen et al. 2011, log splits of the visible depth range",
                 kLauritzen, kZp, {kSdsm}),
        Cascades("sdsm-snap", "sdsm with texel snapping for directional lights", kLauritzen, kZp,
                 {kSdsm, true}),
        Cascades("sdsm-rect", "sdsm's partitions, each fitted with the minimum-area rectangle",
                 kLauritzen, kZp, {kSdsmRect}),
        Cascades("zp-lispsm", "cascades: Lloyd et al. 2006's log z-partitions, LiSPSM in each",
                 kLloyd2006, kZpWarp, {kZpLispsm}),
        Cascades("fp-lispsm", "Lloyd et al. 2006's face partitioning: a LiSPSM map per face wedge",
                 kLloyd2006, StorageModel::kFacePartitionsWarped, {kFpLispsm}),
        Cascades("sdsm-optimal", "sdsm's partitions, optimal (multi-start on e) in each",
                 kLauritzen, kZpWarp, {kSdsmOptimal}),
        Cascades("sdsm-optimal-h", "sdsm's partitions, optimal-h (multi-start on h) in each",
                 kLauritzen, kZpWarp, {kSdsmOptimal, false, true}, true),
    };
}

}  // namespace lexel::spatial
