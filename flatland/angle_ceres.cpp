// optimal-l2-ceres: the L2 angle as a Ceres least-squares problem (Chong 2003 §3.1 solved with
// a general-purpose optimizer, as a cross-check of the exact quartic and of Newton).
// Kept in its own translation unit: with scene_fit.cpp, the only flatland files that include
// Ceres.
#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>

#include "lexel/flatland/angle_solvers.h"

namespace lexel::flatland {

namespace {

// Samples per residual. One residual per sample costs Ceres about 60 bytes each (residual and
// Jacobian copies in the evaluator, the minimizer and the dense QR); a chunk costs the same once.
constexpr std::size_t kSamplesPerResidual = 4096;

// Residual k is r_k = sqrt(Σ_{i in chunk k} f_i(x)²), with the remapped footprint
// f_i(x) = f0_i (1 + tan(x) T_i)² / ((1 + tan(x) T_hi)(1 + tan(x) T_lo)) (lexel_remap.h, R2), so
// ½Σ r_k² = ½ Σ f_i² = ½ L2 exactly as with one residual per sample. Templated so Ceres
// differentiates it with Jets.
struct ChunkResidual {
    const LexelSamples* samples;
    std::size_t begin, end;

    template <typename T>
    bool operator()(const T* x, T* residual) const {
        const T t = tan(x[0]);
        const T denom = (1.0 + t * samples->tanHigh) * (1.0 + t * samples->tanLow);
        T sum = T(0.0);
        for (std::size_t i = begin; i < end; ++i) {
            const T u = 1.0 + t * samples->tanOffset[i];
            const T f = samples->footprint0[i] * u * u / denom;
            sum += f * f;
        }
        residual[0] = sqrt(sum);
        return true;
    }
};

// Adds one residual block per chunk that holds a non-zero footprint (u > 0 on the valid
// interval, so a chunk sums to zero only when every f0_i is zero; sqrt has no derivative there
// and the chunk adds nothing to L2).
void AddChunkResiduals(const LexelSamples& samples, double* x, ceres::Problem& problem) {
    for (std::size_t begin = 0; begin < samples.size(); begin += kSamplesPerResidual) {
        const std::size_t end = std::min(begin + kSamplesPerResidual, samples.size());
        bool nonZero = false;
        for (std::size_t i = begin; i < end && !nonZero; ++i) nonZero = samples.footprint0[i] > 0;
        if (!nonZero) continue;
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ChunkResidual, 1, 1>(
                                     new ChunkResidual{&samples, begin, end}),
                                 nullptr, x);
    }
}

}  // namespace

AngleSolution SolveL2Ceres(const LexelSamples& samples) {
    const ValidInterval valid = ValidTInterval(samples);
    // Bounds one part in 1e6 of the interval inside its ends: the objective is infinite there.
    const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
    const double inset = 1e-6 * (xHi - xLo);
    // Q/D² can have two local minima (its derivative's numerator is a quartic), so start from the
    // initial angle and from four more points spread over the valid interval.
    const double starts[] = {0.0, xLo + 0.2 * (xHi - xLo), xLo + 0.4 * (xHi - xLo),
                             xLo + 0.6 * (xHi - xLo), xLo + 0.8 * (xHi - xLo)};
    AngleSolution best;
    best.objective = std::numeric_limits<double>::infinity();
    int iterations = 0;
    for (double start : starts) {
        double x = start;
        ceres::Problem problem;
        AddChunkResiduals(samples, &x, problem);
        if (problem.NumResidualBlocks() == 0) break;  // every footprint is zero: any angle
        problem.SetParameterLowerBound(&x, 0, xLo + inset);
        problem.SetParameterUpperBound(&x, 0, xHi - inset);
        ceres::Solver::Options options;
        options.linear_solver_type = ceres::DENSE_QR;
        options.function_tolerance = 1e-16;
        options.gradient_tolerance = 1e-16;
        options.parameter_tolerance = 1e-16;
        options.max_num_iterations = 200;
        options.num_threads = 1;
        options.logging_type = ceres::SILENT;
        ceres::Solver::Summary summary;
        ceres::Solve(options, &problem, &summary);
        iterations += static_cast<int>(summary.iterations.size());
        const double t = std::tan(x);
        const double value = AngleObjective(samples, Metric::kL2, t);
        if (value < best.objective) best = {t, WsAxisFromT(samples, t), value, 0, {}};
    }
    if (!std::isfinite(best.objective))  // no residual block: every footprint is zero
        best = {0.0, WsAxisFromT(samples, 0.0), AngleObjective(samples, Metric::kL2, 0.0), 0,
                "every footprint is zero; initial angle"};
    best.iterations = iterations;
    return best;
}

}  // namespace lexel::flatland
