// Lexel allocation across light frusta by Lagrange multipliers (Chong 2003, §3.2).
//
// Frustum j's error, measured with a unit-length lexel range, is e_j; with N_j lexels its metric
// is e_j / N_j^k (k = 1 for L1: footprints scale as 1/N; k = 2 for L2: squared footprints scale as
// 1/N²). Minimize Σ e_j / N_j^k subject to Σ N_j = L:
//     ∂/∂N_j [Σ e_j N_j^-k + λ(Σ N_j - L)] = 0   ⇒   k e_j N_j^-(k+1) = λ
//     ⇒ N_j = L e_j^(1/(k+1)) / Σ_i e_i^(1/(k+1)),
//     total = (Σ_j e_j^(1/(k+1)))^(k+1) / L^k.
// So the optimal total depends on the partition only through Σ_j e_j^(1/(k+1)), a sum of
// per-frustum terms; that is what makes the dynamic program of flatland/frustum_split exact.
//
// Integer allocation: the objective is separable and convex in each N_j, so an integer allocation
// from which no single lexel moved between two frusta lowers the total is globally optimal.
// AllocateLexelsInteger starts from the rounded-down real solution (every frustum with e_j > 0
// gets at least one lexel, frusta with e_j == 0 get none) and hands out or exchanges single
// lexels greedily by marginal gain until that exchange condition holds.
#pragma once

#include <span>
#include <vector>

namespace lexel {

// k = 1 (L1) or 2 (L2) in flatland; any k > 0 holds the same derivation (3D: k = 1 for h, whose
// squared footprints fall as 1/N with a map's N texels; k = p/2 for the edge energy e_p, a length
// to the power p).
double AllocationTerm(double error, double exponent);                   // e^(1/(k+1))
double AllocatedTotal(double termSum, double exponent, double lexels);  // (Σ terms)^(k+1) / L^k

std::vector<double> AllocateLexelsReal(std::span<const double> errors, double exponent,
                                       double lexels);

// Throws std::invalid_argument when there are fewer lexels than frusta holding samples.
std::vector<int> AllocateLexelsInteger(std::span<const double> errors, double exponent, int lexels);

double AllocationError(std::span<const double> errors, std::span<const int> lexels,
                       double exponent);

}  // namespace lexel
