// The optimizer family: Algorithm 1 of H. Chong and S. J. Gortler, "Scene Optimized Shadow
// Mapping", Harvard TR-07-07 (2007), for one map (optimizer.h), from the report's single start or
// from every baseline's (multi_start.h), on the report's h (eq. 6) or the edge energy e
// (energy.h), optionally refined by Ceres.
//   optimal            every baseline's start on e (the fair comparison's reference)
//   optimal-refined    optimal, its best start refined on e by Ceres LBFGS
//   optimal-h          every baseline's start on h
//   optimal-report     Table 1's optimal: focused's axis only, on h
//   optimal-shear      optimal-report with the report's affine shear (Fig. 3)
//   optimal-refined-h  optimal-h refined on h (opt-in)
#include <stdexcept>
#include <string>

#include "lexel/spatial/methods/families.h"
#include "lexel/spatial/multi_start.h"

namespace lexel::spatial {

namespace {

constexpr const char* kCitation =
    "H. Chong, S. J. Gortler, \"Scene Optimized Shadow Mapping\", Harvard TR-07-07, 2007";

// Algorithm 1 from every baseline's start (StandardStarts), on e when `edge`, else on h;
// `name` for the message when the samples are missing.
MethodMatrix FromEveryStart(const char* name, const MethodContext& context, bool edge,
                            bool refine) {
    if (!context.samples) throw std::invalid_argument(std::string(name) + " needs the samples");
    OptimizerOptions options;
    if (edge) {
        options = EdgeOptimizerOptions();
        options.energy.exponent = context.edgeExponent;
    }
    options.maxSamples = context.maxSamples;
    options.refine = refine;
    const std::vector<OptimizerStart> starts = StandardStarts(context.baseline);
    MultiStartResult r =
        OptimizeFromStarts(*context.samples, starts, context.baseline.map, options);
    MethodMatrix m;
    m.matrix = r.result.matrix;
    m.optimizer = std::move(r.result);
    m.winner = std::move(r.winner);
    return m;
}

// The report's single start, focused's axis (InitialLightAxis), on h; with the shear or not.
MethodMatrix FromReportStart(const char* name, const MethodContext& context, bool shear) {
    if (!context.samples) throw std::invalid_argument(std::string(name) + " needs the samples");
    OptimizerOptions options;
    options.maxSamples = context.maxSamples;
    options.shear = shear;
    const BaselineContext& b = context.baseline;
    const glm::dvec3 initialP4 = InitialLightAxis(*b.lightSpace, b.wsBounds, b.wsRelevant);
    // The report's own samples: no thin-shadow contacts (samples.h).
    OptimizerResult r =
        OptimizeLightMatrix(PublishedSamples(*context.samples), initialP4, b.map, options);
    MethodMatrix m;
    m.matrix = r.matrix;
    m.optimizer = std::move(r);
    return m;
}

MethodInfo OptimizerInfo(const char* name, std::string description, MethodTraits traits) {
    traits.optimizer = true;
    return {name,   std::move(description),      kCitation, MethodFamily::kOptimizer,
            traits, StorageModel::kBestSingleMap};
}

// A method that runs Algorithm 1 from every baseline's start (FromEveryStart).
MethodDescriptor EveryStart(const char* name, std::string description, MethodTraits traits,
                            bool edge, bool refine) {
    return {OptimizerInfo(name, std::move(description), traits),
            [name, edge, refine](const MethodContext& c) {
                return FromEveryStart(name, c, edge, refine);
            }};
}

// A method that runs Algorithm 1 from the report's start (FromReportStart).
MethodDescriptor ReportStart(const char* name, std::string description, MethodTraits traits,
                             bool shear) {
    return {OptimizerInfo(name, std::move(description), traits),
            [name, shear](const MethodContext& c) { return FromReportStart(name, c, shear); }};
}

}  // namespace

std::vector<MethodDescriptor> OptimizerMethods() {
    constexpr bool kEdge = true, kRefine = true, kShear = true;
    return {
        EveryStart(kOptimalMethod,
                   "Algorithm 1 from every baseline's start on the edge energy e (fair reference)",
                   {.fairTable = true}, kEdge, !kRefine),
        EveryStart("optimal-refined",
                   "optimal, its best start refined on e by Ceres LBFGS, collapses rejected",
                   {.fairTable = true}, kEdge, kRefine),
        EveryStart("optimal-h", "Algorithm 1 from every baseline's start on the report's h (eq. 6)",
                   {.fairTable = true}, !kEdge, !kRefine),
        ReportStart(kReportOptimalMethod,
                    "Algorithm 1 as published: from focused's axis only (Table 1's optimal)",
                    {.reportTable = true}, !kShear),
        ReportStart("optimal-shear",
                    "Algorithm 1 with the report's affine shear (Fig. 3), optimized exactly", {},
                    kShear),
        EveryStart("optimal-refined-h", "optimal-h, its best start refined on h by Ceres LBFGS",
                   {.optIn = true}, !kEdge, kRefine),
    };
}

}  // namespace lexel::spatial
