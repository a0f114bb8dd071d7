// The trapezoid family (tsm.h): T. Martin and T.-S. Tan's trapezoidal shadow maps with the 80%
// focus rule, fitted to the visible points (tsm) or, as the paper fits them, to the view
// frustum ∩ scene bounds (tsm-report).
#include "lexel/spatial/methods/families.h"
#include "lexel/spatial/tsm.h"

namespace lexel::spatial {

namespace {

constexpr const char* kMartinTan =
    "T. Martin, T.-S. Tan, \"Anti-aliasing and Continuity with Trapezoidal Shadow Maps\", EGSR "
    "2004";

}  // namespace

std::vector<MethodDescriptor> TrapezoidMethods() {
    const auto trapezoid = [](std::string name, std::string description, MethodTraits traits,
                              LightMatrix (*tsm)(const BaselineContext&, BaselineDiagnostics*)) {
        return MethodDescriptor{{std::move(name), std::move(description), kMartinTan,
                                 MethodFamily::kTrapezoid, traits, StorageModel::kTrapezoid},
                                [tsm](const MethodContext& context) {
                                    MethodMatrix m;
                                    m.matrix = tsm(context.baseline, &m.diagnostics);
                                    return m;
                                }};
    };
    return {
        trapezoid("tsm",
                  "Martin & Tan 2004: the trapezoid around the visible points, 80% focus rule", {},
                  &TsmLightMatrix),
        trapezoid("tsm-report", "tsm as the paper fits it: the view frustum and scene bounds",
                  {.frustumFitted = true}, &TsmReportLightMatrix),
    };
}

}  // namespace lexel::spatial
