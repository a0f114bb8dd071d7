#include "lexel/cases/run/sweep_share.h"

#include <algorithm>
#include <cstdio>
#include <mutex>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/sub_texel_phase.h"

namespace lexel::cases {

using spatial::Light;

std::string ShardText(SweepShard shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

std::vector<std::size_t> ShardLights(std::size_t lights, SweepShard shard) {
    std::vector<std::size_t> indices;
    for (std::size_t i = shard.index; i < lights; i += shard.count) indices.push_back(i);
    return indices;
}

SweepResult RunSweepShare(const spatial::Scene& scene, const std::vector<std::string>& methods,
                          const std::vector<Light>& allLights,
                          const std::vector<std::size_t>& indices, const SweepDone& done,
                          const std::function<void(const SweepLightRecord&)>& onLightDone,
                          BackendKind backend, int shimmerPoses) {
    std::vector<std::size_t> pending;
    std::vector<Light> pendingLights;
    for (std::size_t i : indices)
        if (!done.lights.count(i)) {
            pending.push_back(i);
            pendingLights.push_back(allLights.at(i));
        }
    SweepResult fresh = RunSweep(
        scene, methods, pendingLights,
        [&](std::size_t l, const std::vector<SweepCell>& cells, std::int64_t receiverPixels) {
            if (onLightDone) onLightDone({pending[l], pendingLights[l], receiverPixels, cells});
        },
        backend, pending, shimmerPoses);
    SweepResult r;
    r.caseName = scene.name;
    r.methods = methods;
    r.phases = scene.phases;
    r.maxPhases = spatial::MostPhases(scene.phases, scene.maxPhases);
    r.shimmerPoses = shimmerPoses;
    r.seconds = fresh.seconds;
    std::size_t next = 0;  // the next of `fresh`
    for (std::size_t i : indices) {
        r.indices.push_back(i);
        r.lights.push_back(allLights.at(i));
        if (const auto it = done.lights.find(i); it != done.lights.end()) {
            r.cells.push_back(it->second.cells);
            r.receiverPixels.push_back(it->second.receiverPixels);
        } else {
            r.cells.push_back(fresh.cells[next]);
            r.receiverPixels.push_back(fresh.receiverPixels[next]);
            ++next;
        }
    }
    return r;
}

StudyMisclassified RunStudyShare(const spatial::Scene& scene, const SweepResult& share,
                                 const SweepDone& done,
                                 const std::function<void(const StudyLightRecord&)>& onLightDone,
                                 BackendKind backend) {
    const std::vector<std::string> methods = CascadeStudyMethods(share.methods);
    StudyMisclassified study;
    for (int k : CascadeStudyExtraCounts(scene.partitions.count)) {
        std::vector<std::size_t> pending, pendingIndices;  // positions in the share, in the sweep
        std::vector<Light> pendingLights;
        for (std::size_t l = 0; l < share.lights.size(); ++l)
            if (!done.study.count({k, share.indices[l]})) {
                pending.push_back(l);
                pendingIndices.push_back(share.indices[l]);
                pendingLights.push_back(share.lights[l]);
            }
        spatial::Scene atK = scene;
        atK.partitions.count = k;
        auto& perLight = study.emplace_back(share.lights.size());
        RunSweep(
            atK, methods, pendingLights,
            [&](std::size_t l, const std::vector<SweepCell>& cells, std::int64_t) {
                std::vector<double>& counts = perLight[pending[l]];
                for (const SweepCell& c : cells) counts.push_back(c.misclassifiedMean);
                if (onLightDone) onLightDone({k, share.indices[pending[l]], counts});
            },
            backend, pendingIndices);
        for (std::size_t l = 0; l < share.lights.size(); ++l)
            if (const auto it = done.study.find({k, share.indices[l]}); it != done.study.end())
                perLight[l] = it->second.misclassified;
    }
    return study;
}

}  // namespace lexel::cases
