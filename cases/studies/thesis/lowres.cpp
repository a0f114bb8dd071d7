#include "lexel/cases/studies/thesis/lowres.h"

#include <string>

#include "lexel/flatland/methods.h"

namespace lexel::cases {

std::vector<int> LowresResolutions(int fullPixels) {
    std::vector<int> out;
    for (int k : {5, 10, 20, 50, 100, 200})
        if (k < fullPixels) out.push_back(k);
    out.push_back(fullPixels);
    return out;
}

// Memory: the reference run's at most 64 bytes per camera pixel (flatland/memory.h), the K = P row
// reusing its pass, plus passes of at most 200 pixels: within the budget for every pixel count the
// schema allows (64 · kMaxPixels ≈ 6 GiB).
std::vector<LowresRow> RunLowresStudy(const flatland::FlatScene& scene) {
    static const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "optimal-linf"};
    auto errorOf = [](const FootprintStats& s, int metric) {
        return metric == 0 ? s.average : metric == 1 ? s.meanPlusSigma : s.worst();
    };
    flatland::FlatScene full = scene;
    full.decisionPixels = 0;
    const flatland::CaseReport reference = flatland::RunFlatlandCase(full, methods, Metric::kL1);
    // Every K is measured on the same full-resolution pass: compute it once.
    const auto fullPass = reference.fullPass;
    std::vector<LowresRow> rows;
    for (int k : LowresResolutions(scene.camera.pixels)) {
        LowresRow row;
        row.decisionPixels = k;
        flatland::FlatScene low = scene;
        low.decisionPixels = k;
        // K pixels may see no geometry, or too little to span a frustum: no decision possible.
        // K = P is the full pass itself (not a second copy of it: flatland/memory.h).
        std::optional<flatland::SamplingPass> coarse;
        if (k != scene.camera.pixels) coarse = flatland::TrySamplingPass(low, k);
        const flatland::SamplingPass* decision = k == scene.camera.pixels ? fullPass.get()
                                                 : coarse                 ? &*coarse
                                                                          : nullptr;
        if (decision) {
            const flatland::CaseReport report =
                flatland::RunFlatlandCase(low, methods, Metric::kL1, fullPass, decision);
            for (int m = 0; m < 3; ++m)
                row.extraPercent[m] = 100.0 * (errorOf(report.methods[m].stats, m) /
                                                   errorOf(reference.methods[m].stats, m) -
                                               1.0);
        }
        rows.push_back(row);
    }
    return rows;
}

}  // namespace lexel::cases
