// One-dimensional Newton iteration x ← x - g(x)/g'(x), as used by the thesis's Algorithm 1
// (Chong 2003, §3.1) on the derivative of the L2 objective.
#pragma once

#include <functional>
#include <limits>
#include <utility>

namespace lexel {

struct NewtonOptions {
    int maxIterations = 60;
    // Converged once a step is below this (absolute, in the units of x).
    double stepTolerance = 1e-14;
    // An iterate outside [lower, upper] ends the iteration as not converged: Algorithm 1 treats
    // such a run as "converged to an invalid angle" and restarts.
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
};

struct NewtonResult {
    double x = 0.0;
    int iterations = 0;
    bool converged = false;
};

// valueAndDerivative(x) returns {g(x), g'(x)}.
NewtonResult NewtonRoot(const std::function<std::pair<double, double>(double)>& valueAndDerivative,
                        double x0, const NewtonOptions& options = {});

}  // namespace lexel
