#include "lexel/solvers/lagrange_allocation.h"

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "lexel/solvers/errors.h"

namespace lexel {

double AllocationTerm(double error, double exponent) {
    return std::pow(error, 1.0 / (exponent + 1));
}

double AllocatedTotal(double termSum, double exponent, double lexels) {
    return std::pow(termSum, exponent + 1) / std::pow(lexels, exponent);
}

std::vector<double> AllocateLexelsReal(std::span<const double> errors, double exponent,
                                       double lexels) {
    double termSum = 0.0;
    for (double e : errors) termSum += AllocationTerm(e, exponent);
    std::vector<double> out(errors.size(), 0.0);
    if (termSum <= 0.0) return out;
    for (std::size_t j = 0; j < errors.size(); ++j)
        out[j] = lexels * AllocationTerm(errors[j], exponent) / termSum;
    return out;
}

namespace {
// Error of frustum j with n lexels; n == 0 is allowed only for an empty frustum.
double Cost(double e, int n, double exponent) {
    if (e == 0.0) return 0.0;
    if (n <= 0) return std::numeric_limits<double>::infinity();
    return e / std::pow(static_cast<double>(n), exponent);
}
}  // namespace

std::vector<int> AllocateLexelsInteger(std::span<const double> errors, double exponent,
                                       int lexels) {
    if (!(exponent > 0.0) || !std::isfinite(exponent))
        throw std::invalid_argument("lexels: the exponent k must be finite and > 0, got " +
                                    std::to_string(exponent));
    const std::size_t n = errors.size();
    std::size_t occupied = 0;
    for (double e : errors) occupied += e > 0.0;
    if (static_cast<long>(occupied) > lexels)
        throw std::invalid_argument("lexels: " + std::to_string(lexels) + " lexels cannot serve " +
                                    std::to_string(occupied) + " frusta that hold samples");
    const std::vector<double> real = AllocateLexelsReal(errors, exponent, lexels);
    std::vector<int> alloc(n, 0);
    long used = 0;
    for (std::size_t j = 0; j < n; ++j) {
        if (errors[j] > 0.0) alloc[j] = std::max(1, static_cast<int>(std::floor(real[j])));
        used += alloc[j];
    }
    // The min-one rule can overshoot; take lexels back where removing one costs least.
    while (used > lexels) {
        std::size_t best = n;
        double bestLoss = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < n; ++j) {
            if (alloc[j] <= 1) continue;
            const double loss =
                Cost(errors[j], alloc[j] - 1, exponent) - Cost(errors[j], alloc[j], exponent);
            if (loss < bestLoss) bestLoss = loss, best = j;
        }
        --alloc[best];
        --used;
    }
    // Hand out the rest where one more lexel gains most (water-filling).
    while (used < lexels) {
        std::size_t best = n;
        double bestGain = -1.0;
        for (std::size_t j = 0; j < n; ++j) {
            if (errors[j] == 0.0) continue;
            const double gain =
                Cost(errors[j], alloc[j], exponent) - Cost(errors[j], alloc[j] + 1, exponent);
            if (gain > bestGain) bestGain = gain, best = j;
        }
        if (best == n) {  // no frustum holds samples: park the lexels on the first one
            alloc[0] += lexels - used;
            break;
        }
        ++alloc[best];
        ++used;
    }
    // Exchange until no single-lexel move between two frusta lowers the total.
    for (int guard = 0; guard < 1000000; ++guard) {
        std::size_t giver = n, taker = n;
        double bestLoss = std::numeric_limits<double>::infinity(), bestGain = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            if (errors[j] == 0.0) continue;
            const double gain =
                Cost(errors[j], alloc[j], exponent) - Cost(errors[j], alloc[j] + 1, exponent);
            if (gain > bestGain) bestGain = gain, taker = j;
            if (alloc[j] > 1) {
                const double loss =
                    Cost(errors[j], alloc[j] - 1, exponent) - Cost(errors[j], alloc[j], exponent);
                if (loss < bestLoss) bestLoss = loss, giver = j;
            }
        }
        if (giver == n || taker == n || giver == taker || !(bestGain > bestLoss)) break;
        --alloc[giver];
        ++alloc[taker];
    }
    return alloc;
}

double AllocationError(std::span<const double> errors, std::span<const int> lexels,
                       double exponent) {
    double total = 0.0;
    for (std::size_t j = 0; j < errors.size(); ++j) total += Cost(errors[j], lexels[j], exponent);
    return total;
}

}  // namespace lexel
