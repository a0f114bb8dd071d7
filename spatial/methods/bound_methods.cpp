// The bound family: optimal-oracle, the best single light matrix per light by the measured
// error (oracle.h) — the limit of the single-matrix family, not a method a renderer can use. It is
// scored against the exact shadow rays, so the Evaluator computes it; ComputeLightMatrix refuses.
#include <stdexcept>
#include <string>

#include "lexel/spatial/methods/families.h"

namespace lexel::spatial {

std::vector<MethodDescriptor> BoundMethods() {
    return {{{kOracleMethod,
              "bound: the best single matrix by the measured error (scored on the rays)",
              "",
              MethodFamily::kBound,
              {.optIn = true},
              StorageModel::kBestSingleMap},
             [](const MethodContext&) -> MethodMatrix {
                 throw std::invalid_argument(std::string(kOracleMethod) +
                                             " is scored against the truth: Evaluator::Evaluate "
                                             "computes it");
             }}};
}

}  // namespace lexel::spatial
