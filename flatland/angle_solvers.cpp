#include "lexel/flatland/angle_solvers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "lexel/solvers/geometry.h"
#include "lexel/solvers/newton.h"
#include "lexel/solvers/polynomial.h"

namespace lexel::flatland {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

AngleSolution MakeSolution(const LexelSamples& samples, double t, double objective, int iterations,
                           std::string note = {}) {
    return {t, WsAxisFromT(samples, t), objective, iterations, std::move(note)};
}

// D(t) = 1 + p t + q t² as ascending coefficients.
Polynomial Denominator(const LexelSamples& s) {
    return {1.0, s.tanHigh + s.tanLow, s.tanHigh * s.tanLow};
}

// When rounding leaves no interior critical point (it cannot happen in exact arithmetic: the
// objective is +∞ at both ends of the valid interval), take the better of two points one part in
// 1e9 of the interval inside its ends: the thesis's "fall back to the boundary".
AngleSolution BoundaryFallback(const LexelSamples& samples, Metric metric) {
    const ValidInterval valid = ValidTInterval(samples);
    const double inset = 1e-9 * (valid.hi - valid.lo);
    const double a = valid.lo + inset, b = valid.hi - inset;
    const double fa = AngleObjective(samples, metric, a), fb = AngleObjective(samples, metric, b);
    return fa <= fb ? MakeSolution(samples, a, fa, 2, "no interior critical point; boundary")
                    : MakeSolution(samples, b, fb, 2, "no interior critical point; boundary");
}

// The least objective over candidate t inside the valid interval, taken one at a time (nothing
// stored per candidate; the first of equal values wins).
class CandidateSearch {
  public:
    CandidateSearch(const LexelSamples& samples, Metric metric)
        : samples_(samples), metric_(metric), valid_(ValidTInterval(samples)) {
        best_.objective = kInf;
    }
    void Consider(double t) {
        if (!valid_.Contains(t)) return;
        const double value = AngleObjective(samples_, metric_, t);
        ++evaluated_;
        if (value < best_.objective) best_ = MakeSolution(samples_, t, value, evaluated_);
    }
    AngleSolution Result() const {
        if (!std::isfinite(best_.objective)) return BoundaryFallback(samples_, metric_);
        AngleSolution best = best_;
        best.iterations = evaluated_;
        return best;
    }

  private:
    const LexelSamples& samples_;
    Metric metric_;
    ValidInterval valid_;
    AngleSolution best_;
    int evaluated_ = 0;
};

// Least objective over candidate roots inside the valid interval.
AngleSolution BestCandidate(const LexelSamples& samples, Metric metric,
                            const std::vector<double>& candidates) {
    CandidateSearch search(samples, metric);
    for (double t : candidates) search.Consider(t);
    return search.Result();
}

}  // namespace

double AngleObjective(const LexelSamples& samples, Metric metric, double t) {
    const double denom = (1.0 + t * samples.tanHigh) * (1.0 + t * samples.tanLow);
    if (!(denom > 0.0)) return kInf;
    double sum = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double n = 1.0 + t * samples.tanOffset[i];
        const double f = samples.footprint0[i] * n * n / denom;
        switch (metric) {
            case Metric::kL1:
                sum += f;
                break;
            case Metric::kL2:
                sum += f * f;
                break;
            case Metric::kLinf:
                worst = std::max(worst, f);
                break;
        }
    }
    return metric == Metric::kLinf ? worst : sum;
}

L1Moments ComputeL1Moments(const LexelSamples& samples) {
    // Four independent accumulators per moment let the compiler keep several FMAs in flight.
    const double* T = samples.tanOffset.data();
    const double* f = samples.footprint0.data();
    const std::size_t n = samples.size();
    double s0[4] = {0, 0, 0, 0}, s1[4] = {0, 0, 0, 0}, s2[4] = {0, 0, 0, 0};
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int k = 0; k < 4; ++k) {
            const double w = f[i + k], wt = w * T[i + k];
            s0[k] += w;
            s1[k] += wt;
            s2[k] += wt * T[i + k];
        }
    for (; i < n; ++i) s0[0] += f[i], s1[0] += f[i] * T[i], s2[0] += f[i] * T[i] * T[i];
    return {s0[0] + s0[1] + s0[2] + s0[3], s1[0] + s1[1] + s1[2] + s1[3],
            s2[0] + s2[1] + s2[2] + s2[3]};
}

L2Moments ComputeL2Moments(const LexelSamples& samples) {
    const double* T = samples.tanOffset.data();
    const double* f = samples.footprint0.data();
    const std::size_t n = samples.size();
    double m[5][2] = {};
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2)
        for (int k = 0; k < 2; ++k) {
            double w = f[i + k] * f[i + k];
            const double tt = T[i + k];
            for (int j = 0; j < 5; ++j, w *= tt) m[j][k] += w;
        }
    for (; i < n; ++i) {
        double w = f[i] * f[i];
        for (int j = 0; j < 5; ++j, w *= T[i]) m[j][0] += w;
    }
    L2Moments out;
    for (int j = 0; j < 5; ++j) out.m[j] = m[j][0] + m[j][1];
    return out;
}

AngleSolution SolveL1Exact(const LexelSamples& samples) {
    const L1Moments mo = ComputeL1Moments(samples);
    const Polynomial numerator = {mo.s0, 2.0 * mo.s1, mo.s2};  // N1(t)
    const Polynomial denominator = Denominator(samples);
    // N1'D − N1 D' (the cubic terms cancel exactly; PolynomialRealRoots trims their residue).
    const Polynomial critical =
        PolyAdd(PolyMultiply(PolyDerivative(numerator), denominator),
                PolyScale(PolyMultiply(numerator, PolyDerivative(denominator)), -1.0));
    return BestCandidate(samples, Metric::kL1, PolynomialRealRoots(critical));
}

AngleSolution SolveL2Exact(const LexelSamples& samples) {
    const L2Moments mo = ComputeL2Moments(samples);
    const Polynomial q = {mo.m[0], 4.0 * mo.m[1], 6.0 * mo.m[2], 4.0 * mo.m[3], mo.m[4]};  // Q(t)
    const Polynomial d = Denominator(samples);
    // Q'D − 2QD' (the t⁵ terms cancel).
    const Polynomial critical = PolyAdd(PolyMultiply(PolyDerivative(q), d),
                                        PolyScale(PolyMultiply(q, PolyDerivative(d)), -2.0));
    return BestCandidate(samples, Metric::kL2, PolynomialRealRoots(critical));
}

AngleSolution SolveLinfExact(const LexelSamples& samples) {
    // Lines y_i(t) = a_i + b_i t with a_i = sqrt(f0_i), b_i = a_i T_i.
    struct Line {
        double a, b;
    };
    std::vector<Line> lines(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double a = std::sqrt(samples.footprint0[i]);
        lines[i] = {a, a * samples.tanOffset[i]};
    }
    // Upper envelope (convex hull trick): sort by slope; among equal slopes keep the highest.
    std::sort(lines.begin(), lines.end(),
              [](const Line& x, const Line& y) { return x.b < y.b || (x.b == y.b && x.a > y.a); });
    // The hull is a stack kept in place as the prefix lines[0, h): h never passes the read index,
    // so no second array per sample (flatland/memory.h).
    auto crossAt = [](const Line& x, const Line& y) { return (x.a - y.a) / (y.b - x.b); };
    std::size_t h = 0;
    for (std::size_t r = 0; r < lines.size(); ++r) {
        const Line line = lines[r];
        if (h > 0 && lines[h - 1].b == line.b) continue;  // lower duplicate slope
        // The top of the stack is hidden once the new line overtakes the one beneath it no later
        // than the top does.
        while (h >= 2 && crossAt(lines[h - 2], line) <= crossAt(lines[h - 2], lines[h - 1])) --h;
        lines[h++] = line;
    }
    lines.resize(h);
    const std::vector<Line>& hull = lines;
    const ValidInterval valid = ValidTInterval(samples);
    const double p = samples.tanHigh + samples.tanLow, q = samples.tanHigh * samples.tanLow;
    CandidateSearch search(samples, Metric::kLinf);
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const double from = k == 0 ? -kInf : crossAt(hull[k - 1], hull[k]);
        const double to = k + 1 == hull.size() ? kInf : crossAt(hull[k], hull[k + 1]);
        const double lo = std::max(from, valid.lo), hi = std::min(to, valid.hi);
        if (!(lo < hi)) continue;
        if (lo > valid.lo) search.Consider(lo);  // interior breakpoints
        if (hi < valid.hi) search.Consider(hi);
        const double denom = hull[k].b * p - 2.0 * hull[k].a * q;
        if (denom != 0.0) {
            const double t = (hull[k].a * p - 2.0 * hull[k].b) / denom;
            if (t > lo && t < hi) search.Consider(t);
        }
    }
    return search.Result();
}

AngleSolution SolveL2Newton(const LexelSamples& samples, const NewtonRestartOptions& options) {
    const ValidInterval valid = ValidTInterval(samples);
    const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
    // g(x) = dE/dx and g'(x) for E = Σ f_i², summed over the samples. With u = 1 + tT,
    // a = d(log f)/dt = 2T/u − T_hi/d_hi − T_lo/d_lo and b = da/dt:
    //     d(f²)/dt = 2f²a,  d²(f²)/dt² = 2f²(2a² + b),
    //     dE/dx = E_t (1+t²),  d²E/dx² = E_tt (1+t²)² + 2t(1+t²) E_t.
    auto gradient = [&](double x) -> std::pair<double, double> {
        const double t = std::tan(x);
        const double dHi = 1.0 + t * samples.tanHigh, dLo = 1.0 + t * samples.tanLow;
        const double cHi = samples.tanHigh / dHi, cLo = samples.tanLow / dLo;
        const double denom = dHi * dLo;
        double et = 0.0, ett = 0.0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            const double T = samples.tanOffset[i];
            const double u = 1.0 + t * T;
            const double f = samples.footprint0[i] * u * u / denom;
            const double a = 2.0 * T / u - cHi - cLo;
            const double b = -2.0 * T * T / (u * u) + cHi * cHi + cLo * cLo;
            et += 2.0 * f * f * a;
            ett += 2.0 * f * f * (2.0 * a * a + b);
        }
        const double s = 1.0 + t * t;
        return {et * s, ett * s * s + 2.0 * t * s * et};
    };
    std::mt19937_64 rng(options.seed);
    const double maxOffset = Radians(options.maxOffsetDeg);
    std::uniform_real_distribution<double> randomOffset(-maxOffset, maxOffset);
    NewtonOptions newtonOptions;
    newtonOptions.lower = xLo;
    newtonOptions.upper = xHi;
    newtonOptions.stepTolerance = 1e-15;
    AngleSolution best;
    best.objective = kInf;
    int totalIterations = 0;
    for (int i = 0; i <= options.restarts; ++i) {
        double guess = i * randomOffset(rng);
        for (int attempt = 0; attempt < options.maxTriesPerRestart; ++attempt) {
            const NewtonResult r = NewtonRoot(gradient, std::clamp(guess, xLo, xHi), newtonOptions);
            totalIterations += r.iterations;
            if (r.converged && r.x > xLo && r.x < xHi) {
                const double t = std::tan(r.x);
                const double value = AngleObjective(samples, Metric::kL2, t);
                if (value < best.objective) best = MakeSolution(samples, t, value, 0);
                break;
            }
            guess += randomOffset(rng);
        }
    }
    if (!std::isfinite(best.objective)) {
        AngleSolution fallback =
            MakeSolution(samples, 0.0, AngleObjective(samples, Metric::kL2, 0.0), totalIterations,
                         "Newton never converged; initial angle");
        return fallback;
    }
    best.iterations = totalIterations;
    return best;
}

AngleSolution SolveSweep(const LexelSamples& samples, Metric metric, const SweepOptions& options) {
    const ValidInterval valid = ValidTInterval(samples);
    const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
    const double cell = (xHi - xLo) / options.cells;
    auto objectiveAt = [&](double x) { return AngleObjective(samples, metric, std::tan(x)); };
    int bestCell = 0;
    double bestValue = kInf;
    for (int k = 0; k < options.cells; ++k) {
        const double value = objectiveAt(xLo + (k + 0.5) * cell);
        if (value < bestValue) bestValue = value, bestCell = k;
    }
    // Golden-section search over the best cell and its neighbours (centers k-1 .. k+1).
    double a = xLo + (std::max(bestCell - 1, 0) + 0.5) * cell;
    double b = xLo + (std::min(bestCell + 1, options.cells - 1) + 0.5) * cell;
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - ratio * (b - a), d = a + ratio * (b - a);
    double fc = objectiveAt(c), fd = objectiveAt(d);
    for (int it = 0; it < options.refineIterations && b - a > 1e-16; ++it) {
        if (fc <= fd)
            b = d, d = c, fd = fc, c = b - ratio * (b - a), fc = objectiveAt(c);
        else
            a = c, c = d, fc = fd, d = a + ratio * (b - a), fd = objectiveAt(d);
    }
    double x = xLo + (bestCell + 0.5) * cell;
    double value = bestValue;
    if (fc < value) x = c, value = fc;
    if (fd < value) x = d, value = fd;
    return MakeSolution(samples, std::tan(x), value, options.cells + 2 * options.refineIterations);
}

}  // namespace lexel::flatland
