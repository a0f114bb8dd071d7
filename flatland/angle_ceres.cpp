// optimal-l2-ceres: the L2 angle as a Ceres least-squares problem (Chong 2003 §3.1 solved with
// a general-purpose optimizer, as a cross-check of the exact quartic and of Newton).
// Kept in its own translation unit: with scene_fit.cpp, the only flatland files that include
// Ceres.
#include <ceres/ceres.h>

#include <cmath>

#include "lexel/flatland/angle_solvers.h"

namespace lexel::flatland {

namespace {

// Residual i is the remapped footprint f_i(x) = f0_i (1 + tan(x) T_i)² / ((1 + tan(x) T_hi)(1 +
// tan(x) T_lo)) (lexel_remap.h, R2), templated so Ceres differentiates it with Jets.
struct FootprintResiduals {
    const LexelSamples* samples;

    template <typename T>
    bool operator()(T const* const* parameters, T* residuals) const {
        const T t = tan(parameters[0][0]);
        const T denom = (1.0 + t * samples->tanHigh) * (1.0 + t * samples->tanLow);
        for (std::size_t i = 0; i < samples->size(); ++i) {
            const T u = 1.0 + t * samples->tanOffset[i];
            residuals[i] = samples->footprint0[i] * u * u / denom;
        }
        return true;
    }

    static ceres::CostFunction* Create(const LexelSamples* samples) {
        auto* cost = new ceres::DynamicAutoDiffCostFunction<FootprintResiduals, 1>(
            new FootprintResiduals{samples});
        cost->AddParameterBlock(1);
        cost->SetNumResiduals(static_cast<int>(samples->size()));
        return cost;
    }
};

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
        problem.AddResidualBlock(FootprintResiduals::Create(&samples), nullptr, &x);
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
    best.iterations = iterations;
    return best;
}

}  // namespace lexel::flatland
