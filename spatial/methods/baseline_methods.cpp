// The baseline family: the published single maps (baselines.h), each fitted the report's way
// (the view frustum ∩ scene bounds, Table 1 as published) or the fair way (the visible points and
// Algorithm 1's margin: `-tight`), in the order the fair table and Table 1 list them.
#include "lexel/spatial/methods/families.h"

namespace lexel::spatial {

namespace {

using Baseline = LightMatrix (*)(const BaselineContext&, BaselineDiagnostics*);

constexpr const char* kBrabec =
    "S. Brabec, T. Annen, H.-P. Seidel, \"Practical Shadow Mapping\", JGT 2002";
constexpr const char* kLispsm =
    "M. Wimmer, D. Scherzer, W. Purgathofer, \"Light Space Perspective Shadow Maps\", EGSR 2004";
constexpr const char* kPsm =
    "M. Stamminger, G. Drettakis, \"Perspective Shadow Maps\", SIGGRAPH 2002; S. Kozlov, "
    "\"Perspective Shadow Maps: Care and Feeding\", GPU Gems 2004";
constexpr const char* kPlaneOptimal =
    "H. Chong, S. J. Gortler, \"A Lixel for Every Pixel\", EGSR 2004";
constexpr const char* kReport =
    "H. Chong, S. J. Gortler, \"Scene Optimized Shadow Mapping\", Harvard TR-07-07, 2007";

MethodDescriptor Single(std::string name, std::string description, std::string citation,
                        MethodTraits traits, StorageModel storage, Baseline baseline) {
    return {{std::move(name), std::move(description), std::move(citation), MethodFamily::kBaseline,
             traits, storage},
            [baseline](const MethodContext& context) {
                MethodMatrix m;
                m.matrix = baseline(context.baseline, &m.diagnostics);
                return m;
            }};
}

}  // namespace

std::vector<MethodDescriptor> BaselineMethods() {
    constexpr MethodTraits kFair{.fairTable = true};
    constexpr MethodTraits kReported{.reportTable = true, .frustumFitted = true};
    constexpr MethodTraits kBoth{.fairTable = true, .reportTable = true};
    return {
        Single("focused-tight", "focused's axis, minimum-area rectangle around the visible points",
               kBrabec, kFair, StorageModel::kUnwarped, &FocusedTightLightMatrix),
        Single("lispsm-tight", "LiSPSM (Wimmer et al. 2004) fitted to the visible points", kLispsm,
               kFair, StorageModel::kLispsm, &LispsmTightLightMatrix),
        Single("lispsm-engine",
               "lispsm-tight with the engines' n (z1 = z0 + d sin γ: Filament, OGRE)", kLispsm,
               kFair, StorageModel::kLispsm, &LispsmEngineLightMatrix),
        Single("psm-tight", "PSM (Stamminger & Drettakis 2002) fitted to the visible points", kPsm,
               kFair, StorageModel::kPsm, &PsmTightLightMatrix),
        Single("focused",
               "the report's focused map: view frustum and scene bounds on the light's plane",
               kReport, kReported, StorageModel::kUnwarped, &FocusedLightMatrix),
        Single("lispsm", "LiSPSM for the view frustum and scene bounds, as the report ran it",
               kLispsm, kReported, StorageModel::kLispsm, &LispsmLightMatrix),
        Single("plane-optimal",
               "Chong & Gortler 2004: the floor plane's optimum, refitted to the view",
               kPlaneOptimal, kBoth, StorageModel::kBestSingleMap, &PlaneOptimalLightMatrix),
        Single("normal", "the light's frustum over the scene bounds", kReport, kBoth,
               StorageModel::kBestSingleMap, &NormalLightMatrix),
        Single("psm", "PSM with Kozlov's fixes for the view frustum and scene bounds", kPsm,
               kReported, StorageModel::kPsm, &PsmLightMatrix),
    };
}

}  // namespace lexel::spatial
