#include "lexel/solvers/newton.h"

#include <cmath>

namespace lexel {

NewtonResult NewtonRoot(const std::function<std::pair<double, double>(double)>& valueAndDerivative,
                        double x0, const NewtonOptions& options) {
    NewtonResult result{x0, 0, false};
    double x = x0;
    for (int it = 1; it <= options.maxIterations; ++it) {
        const auto [g, dg] = valueAndDerivative(x);
        result.iterations = it;
        if (!std::isfinite(g) || !std::isfinite(dg) || dg == 0.0) break;
        const double step = g / dg;
        x -= step;
        result.x = x;
        if (!(x > options.lower && x < options.upper)) break;
        if (std::abs(step) <= options.stepTolerance * std::max(1.0, std::abs(x))) {
            result.converged = true;
            break;
        }
    }
    return result;
}

}  // namespace lexel
