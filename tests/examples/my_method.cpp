// Two methods added in one file (CONTRIBUTING.md, "Add a method in one file"): each is one
// RegisterMethod call, after which lexel knows it everywhere a built-in method is known
// (ComputeLightMatrix, SpatialMethodNames, `lexel --help`, `lexel run`, `lexel sweep`,
// `lexel methods`, and `lexel storage` with the storage model it declares).
//   - my-focused: focused-tight itself, through the baselines' API (baselines.h);
//   - focused-wide: focused-tight with four times its margin (8% instead of 2% added to each half
//     extent of the rectangle around the visible points), a map that covers more than it needs.
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/methods/registry.h"

namespace {

using lexel::spatial::BaselineContext;
using lexel::spatial::MethodContext;
using lexel::spatial::MethodMatrix;

const bool kMyFocused = lexel::spatial::RegisterMethod({
    .info = {.name = "my-focused",
             .description = "focused-tight, registered from tests/examples/my_method.cpp",
             .citation =
                 "S. Brabec, T. Annen, H.-P. Seidel, \"Practical Shadow Mapping\", JGT 2002",
             .storage = lexel::spatial::StorageModel::kUnwarped},
    .compute =
        [](const MethodContext& context) {
            MethodMatrix m;
            m.matrix = FocusedTightLightMatrix(context.baseline);
            return m;
        },
});

const bool kFocusedWide = lexel::spatial::RegisterMethod({
    .info = {.name = "focused-wide",
             .description = "focused-tight with 4x its margin (tests/examples/my_method.cpp)",
             .storage = lexel::spatial::StorageModel::kUnwarped},
    .compute =
        [](const MethodContext& context) {
            BaselineContext wide = context.baseline;
            wide.margin *= 4.0;
            MethodMatrix m;
            m.matrix = FocusedTightLightMatrix(wide);
            return m;
        },
});

}  // namespace
