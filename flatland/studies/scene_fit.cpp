// Scene fitting (scene_fit.h). Kept apart from the rest of the flatland code because it includes
// Ceres.
//
// Why numeric differences and a multi-start: a table number is a function of the scene through
// which pixel sees which segment. Inside a region where no pixel changes its hit segment the
// numbers are smooth (hit points, light angles and the solvers' optima move smoothly; "worst" is a
// max, with kinks only), so central differences with a step of 1e-6 of a parameter's range give
// the local Jacobian. Across a visibility change (a pixel ray passing a segment's end) the
// averages jump by about f/|Ω|, i.e. 1e-3 relative at 1000 pixels, and the decisions taken on the
// 100-pixel pass (the optimal angles, the split's wedges) jump further: the landscape is a
// smooth trend with steps. Levenberg–Marquardt follows the trend; the random screening supplies
// starts in the different basins (which way the camera looks, whether it sees the sky, ...);
// Lawson's reweighting moves the least-squares optimum toward the smallest worst error; and a
// compass search on the written scene's worst error, which needs no derivative, finishes across
// the steps.
#include "lexel/flatland/studies/scene_fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include "lexel/flatland/methods.h"
#include "lexel/flatland/sampling.h"

namespace lexel::flatland {

const char* QuantityName(Quantity quantity) {
    switch (quantity) {
        case Quantity::kAngle:
            return "angle";
        case Quantity::kWorst:
            return "worst";
        case Quantity::kAverage:
            return "average";
        case Quantity::kMeanPlusSigma:
            return "mean+σ";
        case Quantity::kTwoFrustaMean:
            return "mean (2 frusta)";
    }
    return "?";
}

double NormalizedError(const ComparedNumber& number, const Tolerances& tolerances) {
    const double tolerance =
        number.quantity == Quantity::kAngle ? tolerances.angleDeg : tolerances.footprint;
    return std::abs(number.error) / tolerance;
}

double FitResidual(const ComparedNumber& number, const Tolerances& tolerances) {
    const double tolerance =
        number.quantity == Quantity::kAngle ? tolerances.angleDeg : tolerances.footprint;
    return 0.1 * number.error / tolerance;
}

namespace {

const MethodReport& FindMethod(const CaseReport& report, const std::string& name) {
    for (const auto& m : report.methods)
        if (m.method == name) return m;
    throw std::logic_error("scene_fit: method not run: " + name);
}

void AddFootprint(std::vector<ComparedNumber>& out, int row, Quantity quantity, double published,
                  double value) {
    if (std::isnan(published)) return;
    out.push_back({row, quantity, published, value, value / published - 1.0});
}

}  // namespace

namespace {

// The methods a table's rows need, each once, in the order the rows name them (a row with a
// two-frusta mean adds the split after its own method).
std::vector<std::string> TableMethods(const PublishedTable& table) {
    std::vector<std::string> methods;
    auto addMethod = [&](const std::string& m) {
        if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
    };
    for (const auto& row : table.rows) {
        addMethod(row.method);
        if (!std::isnan(row.twoFrustaMean)) addMethod(table.splitMethod);
    }
    return methods;
}

std::vector<ComparedNumber> NumbersFromReport(const CaseReport& report, const PublishedTable& table,
                                              double footprintScale) {
    std::vector<ComparedNumber> out;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
        const PublishedRow& row = table.rows[r];
        const MethodReport& m = FindMethod(report, row.method);
        const int i = static_cast<int>(r);
        if (!std::isnan(row.angleDeg)) {
            // Lexel plane orientations are equal mod 180°.
            const double error = std::remainder(m.lexelPlaneDeg - row.angleDeg, 180.0);
            out.push_back({i, Quantity::kAngle, row.angleDeg, row.angleDeg + error, error});
        }
        AddFootprint(out, i, Quantity::kWorst, row.worst, footprintScale * m.stats.worst());
        AddFootprint(out, i, Quantity::kAverage, row.average, footprintScale * m.stats.average);
        AddFootprint(out, i, Quantity::kMeanPlusSigma, row.meanPlusSigma,
                     footprintScale * m.stats.meanPlusSigma);
        if (!std::isnan(row.twoFrustaMean))
            AddFootprint(out, i, Quantity::kTwoFrustaMean, row.twoFrustaMean,
                         footprintScale * FindMethod(report, table.splitMethod).stats.average);
    }
    return out;
}

}  // namespace

std::vector<ComparedNumber> CompareWithTable(const FlatScene& scene, const PublishedTable& table,
                                             double footprintScale) {
    const CaseReport report = RunFlatlandCase(scene, TableMethods(table), Metric::kL1);
    return NumbersFromReport(report, table, footprintScale);
}

std::optional<std::vector<ComparedNumber>> TryCompareWithTable(const FlatScene& scene,
                                                               const PublishedTable& table,
                                                               double footprintScale,
                                                               std::optional<DomainError>* defect) {
    const auto fail = [&](DomainError error) -> std::optional<std::vector<ComparedNumber>> {
        if (defect) defect->emplace(std::move(error));
        return std::nullopt;
    };
    // RunFlatlandCase's refusals, checked in its order with the non-throwing variants.
    if (std::optional<DomainError> geometry = FindSceneGeometryDefect(scene))
        return fail(std::move(*geometry));
    std::optional<SamplingPass> full = TrySamplingPass(scene, scene.camera.pixels, defect);
    if (!full) return std::nullopt;
    std::optional<SamplingPass> decision;
    if (scene.DecisionPixels() != scene.camera.pixels) {
        decision = TrySamplingPass(scene, scene.DecisionPixels(), defect);
        if (!decision) return std::nullopt;
    }
    const std::vector<std::string> methods = TableMethods(table);
    const int budget = scene.frusta.value_or(FrustaOptions{}).budget;
    // A split keeps at most `budget` frusta, so with at least that many lexels SplitLightFrustum
    // never finds more frusta holding samples than lexels.
    if (std::find(methods.begin(), methods.end(), table.splitMethod) != methods.end() &&
        scene.lexels < budget)
        return fail(DomainError(
            Subject::kLexels, std::to_string(scene.lexels) + " lexels cannot serve a split into " +
                                  "up to " + std::to_string(budget) + " frusta"));
    const CaseReport report = RunFlatlandCase(
        scene, methods, Metric::kL1, std::make_shared<const SamplingPass>(std::move(*full)),
        decision ? &*decision : nullptr);
    return NumbersFromReport(report, table, footprintScale);
}

TableAgreement Agreement(const std::vector<ComparedNumber>& numbers, const Tolerances& tolerances) {
    TableAgreement a;
    double sum = 0.0;
    for (const auto& n : numbers) {
        if (n.quantity == Quantity::kAngle)
            a.worstAngleDeg = std::max(a.worstAngleDeg, std::abs(n.error));
        else
            a.worstFootprint = std::max(a.worstFootprint, std::abs(n.error));
        a.worstNormalized = std::max(a.worstNormalized, NormalizedError(n, tolerances));
        sum += FitResidual(n, tolerances) * FitResidual(n, tolerances);
    }
    a.rms = numbers.empty() ? 0.0 : std::sqrt(sum / numbers.size());
    a.accepted = a.worstNormalized <= 1.0;
    return a;
}

std::vector<double> FamilyResiduals(const SceneFamily& family, const PublishedTable& table,
                                    std::span<const double> parameters,
                                    const Tolerances& tolerances, std::span<const double> weights) {
    const auto numbers =
        TryCompareWithTable(family.Build(parameters), table, family.FootprintScale(parameters));
    if (!numbers) return {};
    std::vector<double> residuals;
    for (std::size_t i = 0; i < numbers->size(); ++i)
        residuals.push_back(FitResidual((*numbers)[i], tolerances) *
                            (weights.empty() ? 1.0 : weights[i]));
    for (double r : residuals)
        if (!std::isfinite(r)) return {};
    return residuals;
}

namespace {

// Normalized coordinates: z = 1 + u with u ∈ [0, 1] across the parameter's range (linear, or
// linear in log for logScale). The offset keeps |z| ≥ 1, so Ceres's relative difference step is
// a fixed fraction of the range.
double FromNormalized(const FamilyParameter& p, double z) {
    const double u = z - 1.0;
    if (p.logScale) return std::exp(std::log(p.lo) + u * (std::log(p.hi) - std::log(p.lo)));
    return p.lo + u * (p.hi - p.lo);
}

double ToNormalized(const FamilyParameter& p, double x) {
    if (p.logScale) return 1.0 + (std::log(x) - std::log(p.lo)) / (std::log(p.hi) - std::log(p.lo));
    return 1.0 + (x - p.lo) / (p.hi - p.lo);
}

std::vector<double> Denormalize(const SceneFamily& family, const double* z) {
    std::vector<double> x(family.parameters.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = FromNormalized(family.parameters[i], z[i]);
    return x;
}

struct TableResiduals {
    const SceneFamily* family;
    const PublishedTable* table;
    Tolerances tolerances;
    std::vector<double> weights;
    int numResiduals;
    int* evaluations;

    bool operator()(double const* const* z, double* residuals) const {
        ++*evaluations;
        const auto r =
            FamilyResiduals(*family, *table, Denormalize(*family, z[0]), tolerances, weights);
        // A refused scene (TryCompareWithTable) costs a residual of 10 per number, a
        // normalized error of 100: Levenberg–Marquardt rejects the step. (Returning false would
        // end the solve with an error log when a difference step crosses into such a scene.)
        if (r.empty())
            std::fill(residuals, residuals + numResiduals, 10.0);
        else
            std::copy(r.begin(), r.end(), residuals);
        return true;
    }
};

double Cost(const std::vector<double>& residuals) {
    double c = 0.0;
    for (double r : residuals) c += 0.5 * r * r;
    return c;
}

// Levenberg–Marquardt from z (normalized), in place; returns the final cost.
double RunLevenbergMarquardt(const SceneFamily& family, const PublishedTable& table,
                             std::vector<double>& z, int numResiduals, const FitOptions& options,
                             std::span<const double> weights, int& evaluations) {
    ceres::NumericDiffOptions diff;
    diff.relative_step_size = 1e-6;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<TableResiduals, ceres::CENTRAL>(
        new TableResiduals{&family,
                           &table,
                           options.tolerances,
                           {weights.begin(), weights.end()},
                           numResiduals,
                           &evaluations},
        ceres::TAKE_OWNERSHIP, diff);
    cost->AddParameterBlock(static_cast<int>(z.size()));
    cost->SetNumResiduals(numResiduals);
    ceres::Problem problem;
    problem.AddResidualBlock(cost, nullptr, z.data());
    for (std::size_t i = 0; i < z.size(); ++i) {
        problem.SetParameterLowerBound(z.data(), static_cast<int>(i), 1.0);
        problem.SetParameterUpperBound(z.data(), static_cast<int>(i), 2.0);
    }
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.max_num_iterations = options.maxIterations;
    solver.function_tolerance = 1e-14;
    solver.gradient_tolerance = 1e-14;
    solver.parameter_tolerance = 1e-12;
    solver.num_threads = 1;
    solver.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    return summary.final_cost;
}

FitResult Finish(const SceneFamily& family, const PublishedTable& table,
                 std::vector<double> parameters, double cost, int evaluations,
                 const Tolerances& tolerances) {
    FitResult result;
    // Difference steps and exp/log round-off can leave a parameter 1 ulp outside its range.
    for (std::size_t i = 0; i < parameters.size(); ++i)
        parameters[i] = std::clamp(parameters[i], family.parameters[i].lo, family.parameters[i].hi);
    result.parameters = std::move(parameters);
    result.scene = family.Build(result.parameters);
    result.numbers = CompareWithTable(result.scene, table, 1.0);
    result.agreement = Agreement(result.numbers, tolerances);
    result.cost = cost;
    result.evaluations = evaluations;
    return result;
}

// Throws why the scene of `parameters` is refused (FamilyResiduals returned nothing for it).
[[noreturn]] void ThrowRefused(const SceneFamily& family, const PublishedTable& table,
                               std::span<const double> parameters) {
    std::optional<DomainError> defect;
    TryCompareWithTable(family.Build(parameters), table, 1.0, &defect);
    if (defect) throw *defect;
    throw DomainError(Subject::kGeometry,
                      "the " + family.name + " scene's numbers are not finite at these parameters");
}

}  // namespace

FitResult EvaluateFamily(const SceneFamily& family, const PublishedTable& table,
                         std::span<const double> parameters, const Tolerances& tolerances) {
    const auto r = FamilyResiduals(family, table, parameters, tolerances);
    if (r.empty()) ThrowRefused(family, table, parameters);
    return Finish(family, table, {parameters.begin(), parameters.end()}, Cost(r), 1, tolerances);
}

namespace {

// The worst weighted residual of a normalized parameter vector (+inf when refused).
double WorstResidual(const SceneFamily& family, const PublishedTable& table,
                     const std::vector<double>& z, const Tolerances& tolerances,
                     std::span<const double> weights, std::vector<double>& r) {
    r = FamilyResiduals(family, table, Denormalize(family, z.data()), tolerances, weights);
    double worst = 0.0;
    for (double v : r) worst = std::max(worst, std::abs(v));
    return r.empty() ? INFINITY : worst;
}

// Levenberg–Marquardt from z, then Lawson's rounds toward the minimax (factors λ_i ← λ_i |r_i| on
// top of the given weights). Returns the iterate, the start included, with the smallest worst
// weighted residual.
std::vector<double> LeastSquaresStage(const SceneFamily& family, const PublishedTable& table,
                                      std::vector<double> z, std::span<const double> base,
                                      const FitOptions& options, int& evaluations) {
    const int numResiduals = static_cast<int>(base.size());
    std::vector<double> r;
    std::vector<double> bestZ = z;
    double bestWorst = WorstResidual(family, table, z, options.tolerances, base, r);
    RunLevenbergMarquardt(family, table, z, numResiduals, options, base, evaluations);
    double worst = WorstResidual(family, table, z, options.tolerances, base, r);
    if (worst < bestWorst) bestWorst = worst, bestZ = z;
    std::vector<double> lawson(base.size(), 1.0), weights(base.size());
    for (int round = 0; round < options.minimaxRounds && !r.empty(); ++round) {
        double sum = 0.0;
        for (std::size_t i = 0; i < lawson.size(); ++i) sum += lawson[i] *= std::abs(r[i]);
        // A floor of 1e-3 of the mean factor keeps every weighted number in the problem.
        for (std::size_t i = 0; i < lawson.size(); ++i) {
            lawson[i] = std::max(lawson[i] * lawson.size() / std::max(sum, 1e-300), 1e-3);
            weights[i] = base[i] * lawson[i];
        }
        RunLevenbergMarquardt(family, table, z, numResiduals, options, weights, evaluations);
        worst = WorstResidual(family, table, z, options.tolerances, base, r);
        if (worst < bestWorst) bestWorst = worst, bestZ = z;
    }
    return bestZ;
}

// Score of the scene as written: (worst weighted normalized error, RMS), compared in that order.
std::pair<double, double> WrittenScore(const SceneFamily& family, const PublishedTable& table,
                                       const std::vector<double>& z, std::span<const double> base,
                                       const Tolerances& tolerances) {
    const auto numbers = TryCompareWithTable(family.Build(Denormalize(family, z.data())), table);
    if (!numbers) return {INFINITY, INFINITY};
    double worst = 0.0, sum = 0.0;
    for (std::size_t i = 0; i < numbers->size(); ++i) {
        const double e = base[i] * NormalizedError((*numbers)[i], tolerances);
        worst = std::max(worst, e);
        sum += e * e;
    }
    return {worst, std::sqrt(sum / numbers->size())};
}

// Compass search: ± step along each normalized coordinate, moving on any improvement of the
// written score, halving the step after a sweep without one.
std::vector<double> PatternSearch(const SceneFamily& family, const PublishedTable& table,
                                  std::vector<double> z, std::span<const double> base,
                                  const FitOptions& options, int& evaluations) {
    auto best = WrittenScore(family, table, z, base, options.tolerances);
    int budget = options.patternEvaluations;
    for (double step = options.patternStep; step >= 1e-6 && budget > 0;) {
        bool moved = false;
        for (std::size_t i = 0; i < z.size() && budget > 0; ++i)
            for (double sign : {1.0, -1.0}) {
                std::vector<double> trial = z;
                trial[i] = std::clamp(trial[i] + sign * step, 1.0, 2.0);
                if (trial[i] == z[i]) continue;
                --budget, ++evaluations;
                const auto score = WrittenScore(family, table, trial, base, options.tolerances);
                if (score < best) {
                    best = score, z = std::move(trial), moved = true;
                    break;
                }
            }
        if (!moved) step *= 0.5;
    }
    return z;
}

}  // namespace

FitResult RefineFamily(const SceneFamily& family, const PublishedTable& table,
                       std::span<const double> start, const FitOptions& options) {
    const auto r0 = FamilyResiduals(family, table, start, options.tolerances, options.weights);
    if (r0.empty()) ThrowRefused(family, table, start);
    std::vector<double> z(start.size());
    for (std::size_t i = 0; i < z.size(); ++i)
        z[i] = std::clamp(ToNormalized(family.parameters[i], start[i]), 1.0, 2.0);
    const std::vector<double> base =
        options.weights.empty() ? std::vector<double>(r0.size(), 1.0) : options.weights;
    int evaluations = 1;
    const std::vector<double> zStart = z;
    z = LeastSquaresStage(family, table, z, base, options, evaluations);
    if (options.patternEvaluations > 0)
        z = PatternSearch(family, table, z, base, options, evaluations);
    if (WrittenScore(family, table, zStart, base, options.tolerances) <
        WrittenScore(family, table, z, base, options.tolerances))
        z = zStart;
    const auto r =
        FamilyResiduals(family, table, Denormalize(family, z.data()), options.tolerances, base);
    return Finish(family, table, Denormalize(family, z.data()), Cost(r), evaluations,
                  options.tolerances);
}

std::optional<FitResult> FitFamily(const SceneFamily& family, const PublishedTable& table,
                                   const FitOptions& options) {
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<double, std::vector<double>>> screened;
    int evaluations = 0;
    for (int s = 0; s < options.screenSamples; ++s) {
        std::vector<double> z(family.parameters.size());
        for (double& v : z) v = 1.0 + unit(rng);
        const std::vector<double> x = Denormalize(family, z.data());
        ++evaluations;
        const auto r = FamilyResiduals(family, table, x, options.tolerances, options.weights);
        if (!r.empty()) screened.emplace_back(Cost(r), x);
    }
    if (screened.empty() || options.starts <= 0) return std::nullopt;
    std::sort(screened.begin(), screened.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    FitResult best;
    best.cost = INFINITY;
    const int starts = std::min<int>(options.starts, static_cast<int>(screened.size()));
    for (int s = 0; s < starts; ++s) {
        FitResult r = RefineFamily(family, table, screened[s].second, options);
        evaluations += r.evaluations;
        if (r.cost < best.cost) best = std::move(r);
    }
    best.evaluations = evaluations;
    best.validStarts = static_cast<int>(screened.size());
    return best;
}

std::vector<DroppedNumber> DropOneAnalysis(const SceneFamily& family, const PublishedTable& table,
                                           std::span<const double> start,
                                           const FitOptions& options) {
    const auto r0 = FamilyResiduals(family, table, start, options.tolerances);
    if (r0.empty()) ThrowRefused(family, table, start);
    std::vector<DroppedNumber> out;
    for (std::size_t k = 0; k < r0.size(); ++k) {
        FitOptions dropped = options;
        dropped.weights.assign(r0.size(), 1.0);
        dropped.weights[k] = 0.0;
        const FitResult fit = RefineFamily(family, table, start, dropped);
        DroppedNumber d;
        d.number = static_cast<int>(k);
        for (std::size_t i = 0; i < fit.numbers.size(); ++i) {
            const double e = NormalizedError(fit.numbers[i], options.tolerances);
            if (i == k)
                d.droppedNormalized = e;
            else
                d.restWorstNormalized = std::max(d.restWorstNormalized, e);
        }
        out.push_back(d);
    }
    return out;
}

}  // namespace lexel::flatland
