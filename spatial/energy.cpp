#include "lexel/spatial/energy.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace lexel::spatial {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

glm::dvec2 EdgeNormalOf(const LightSamples& samples, std::size_t k) {
    return samples.edgeNormal.size() == samples.lsX.size() ? samples.edgeNormal[k]
                                                           : glm::dvec2(0.0);
}

// One summand of the chosen energy, no in-front test (NaN: singular).
double Summand(const LightMatrix& m, const EnergyOptions& options, const glm::dvec3& X,
               const glm::dvec3& D1, const glm::dvec3& D2, const glm::dvec2& n) {
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    if (options.kind == EnergyKind::kReport)
        return SampleEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, X, D1, D2);
    return SampleEdgeEnergy(glm::value_ptr(m.p1), glm::value_ptr(m.p2), p4, X, D1, D2, n,
                            options.exponent);
}

// Σ over the boundary samples, stopping at `bound` (every summand ≥ 0 or +inf).
double SampleSum(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options,
                 double bound) {
    double total = 0.0;
    for (std::size_t k = 0; k < s.lsX.size(); ++k) {
        if (!InFront(m.p4, s.lsX[k])) return kInf;
        const double f = Summand(m, options, s.lsX[k], s.dXdx1[k], s.dXdx2[k], EdgeNormalOf(s, k));
        total += std::isnan(f) ? kInf : f;
        if (total >= bound) return total;
    }
    return total;
}

}  // namespace

double PriorEnergy(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options) {
    if (options.priorWeight == 0.0 || s.lsPrior.empty()) return 0.0;
    double total = 0.0;
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
        if (!InFront(m.p4, s.lsPrior[k])) continue;
        const double f =
            Summand(m, options, s.lsPrior[k], s.priorDXdx1[k], s.priorDXdx2[k], {0.0, 0.0});
        if (std::isfinite(f)) total += f;
    }
    return options.priorWeight * total / static_cast<double>(s.lsPrior.size());
}

double Energy(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options) {
    if (options.IsReport()) return Energy(m, s);
    const double samplesPart = SampleSum(m, s, options, kInf);
    return samplesPart + PriorEnergy(m, s, options);
}

WeightedPoints BoundaryPoints(const LightSamples& s, double exponent) {
    return {s.lsX,
            s.dXdx1,
            s.dXdx2,
            s.edgeNormal.size() == s.lsX.size() ? std::span<const glm::dvec2>(s.edgeNormal)
                                                : std::span<const glm::dvec2>(),
            1.0,
            exponent};
}

WeightedPoints PriorPoints(const LightSamples& s, double priorWeight, double exponent) {
    const double weight = s.lsPrior.empty() ? 0.0 : priorWeight / double(s.lsPrior.size());
    return {s.lsPrior, s.priorDXdx1, s.priorDXdx2, {}, weight, exponent};
}

namespace {

// Σ weight ∂||J⁻¹||_F²/∂p4 over the prior points (h's summand, eq. 10–11).
glm::dvec3 ReportPriorGradient(const LightMatrix& m, const LightSamples& s, double priorWeight,
                               bool jets) {
    if (priorWeight == 0.0 || s.lsPrior.empty()) return glm::dvec3(0.0);
    LightSamples prior;
    prior.lsX = s.lsPrior;
    prior.dXdx1 = s.priorDXdx1;
    prior.dXdx2 = s.priorDXdx2;
    const glm::dvec3 g = jets ? EnergyGradientJets(m, prior) : EnergyGradientAnalytic(m, prior);
    return priorWeight / double(s.lsPrior.size()) * g;
}

glm::dvec3 Gradient(const LightMatrix& m, const LightSamples& s, const EnergyOptions& options,
                    bool jets) {
    if (options.kind == EnergyKind::kReport) {
        const glm::dvec3 g = jets ? EnergyGradientJets(m, s) : EnergyGradientAnalytic(m, s);
        if (options.priorWeight == 0.0) return g;
        return g + ReportPriorGradient(m, s, options.priorWeight, jets);
    }
    const auto edge = jets ? &EdgeEnergyGradientJets : &EdgeEnergyGradientAnalytic;
    glm::dvec3 g = edge(m, BoundaryPoints(s, options.exponent));
    if (options.priorWeight != 0.0)
        g += edge(m, PriorPoints(s, options.priorWeight, options.exponent));
    return g;
}

}  // namespace

glm::dvec3 EnergyGradient(const LightMatrix& m, const LightSamples& s,
                          const EnergyOptions& options) {
    return Gradient(m, s, options, false);
}

glm::dvec3 EnergyGradientJets(const LightMatrix& m, const LightSamples& s,
                              const EnergyOptions& options) {
    return Gradient(m, s, options, true);
}

namespace {

SearchEnergy::Points ToPoints(std::span<const glm::dvec3> X, std::span<const glm::dvec3> D1,
                              std::span<const glm::dvec3> D2, std::span<const glm::dvec2> n) {
    SearchEnergy::Points p;
    p.count = X.size();
    for (std::vector<double>& c : p.c) c.resize(p.count);
    p.hasNormal.resize(p.count);
    p.frontMargin.resize(p.count);
    for (std::size_t k = 0; k < p.count; ++k) {
        const glm::dvec3* v[3] = {&X[k], &D1[k], &D2[k]};
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c) p.c[3 * a + c][k] = (*v[a])[c];
        const glm::dvec2 normal = n.empty() ? glm::dvec2(0.0) : n[k];
        p.c[9][k] = normal.x;
        p.c[10][k] = normal.y;
        p.hasNormal[k] = normal.x == 0.0 && normal.y == 0.0 ? 0.0 : 1.0;
        p.frontMargin[k] = 1e-9 * glm::length(X[k]);  // as InFront computes it
    }
    return p;
}

// The points a block of the search energy's loops takes: enough for the compiler's packed loops to
// run long, few enough that the early stop at the bound checks often (every 64 samples).
constexpr std::size_t kSummandBlock = 64;

// The summands of points [begin, begin + n) for kind, and their p4·X, without branches: the
// operations of SampleEnergy and SampleEdgeEnergy in their order (the edge summand squared).
void Summands(const SearchEnergy::Points& p, std::size_t begin, std::size_t n, EnergyKind kind,
              const LightMatrix& m, double* w, double* f) {
    const double* x[3] = {&p.c[0][begin], &p.c[1][begin], &p.c[2][begin]};
    const double* d1[3] = {&p.c[3][begin], &p.c[4][begin], &p.c[5][begin]};
    const double* d2[3] = {&p.c[6][begin], &p.c[7][begin], &p.c[8][begin]};
    const double *n1 = &p.c[9][begin], *n2 = &p.c[10][begin], *has = &p.hasNormal[begin];
    const double* p1 = glm::value_ptr(m.p1);
    const double* p2 = glm::value_ptr(m.p2);
    const double p4[3] = {m.p4.x, m.p4.y, m.p4.z};
    if (kind == EnergyKind::kReport) {
        for (std::size_t k = 0; k < n; ++k) {
            const glm::dvec3 X(x[0][k], x[1][k], x[2][k]);
            w[k] = glm::dot(m.p4, X);
            f[k] = SampleEnergy(p1, p2, p4, X, glm::dvec3(d1[0][k], d1[1][k], d1[2][k]),
                                glm::dvec3(d2[0][k], d2[1][k], d2[2][k]));
        }
        return;
    }
    const auto dot = [](const double* a, const glm::dvec3& v) {
        return a[0] * v.x + a[1] * v.y + a[2] * v.z;
    };
    for (std::size_t k = 0; k < n; ++k) {  // SampleEdgeEnergy, the branch as a 0/1 factor
        const glm::dvec3 X(x[0][k], x[1][k], x[2][k]);
        const glm::dvec3 D1(d1[0][k], d1[1][k], d1[2][k]), D2(d2[0][k], d2[1][k], d2[2][k]);
        w[k] = glm::dot(m.p4, X);
        const double wX = dot(p4, X), wD1 = dot(p4, D1), wD2 = dot(p4, D2);
        const double a1 = dot(p1, X), a2 = dot(p2, X);
        const double invW = 1.0 / wX;
        const double j11 = (dot(p1, D1) - a1 * wD1 * invW) * invW;
        const double j12 = (dot(p1, D2) - a1 * wD2 * invW) * invW;
        const double j21 = (dot(p2, D1) - a2 * wD1 * invW) * invW;
        const double j22 = (dot(p2, D2) - a2 * wD2 * invW) * invW;
        const double det = j11 * j22 - j12 * j21;
        const double a = n1[k] * j22 - n2[k] * j21, b = n2[k] * j11 - n1[k] * j12;
        const double qNone = 0.5 * (j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22);
        const double q = has[k] * (a * a + b * b) + (1.0 - has[k]) * qNone;
        f[k] = q / (det * det);  // squared: Finish takes the power in a loop of its own
    }
}

// The summands of Summands as Energy has them: e's squared norms to the power p/2 in place, by
// BandPower's operations in its order, in loops without branches that the compiler may vectorize
// (this file is built with -fno-math-errno: std::sqrt then needs no errno path, and its result,
// correctly rounded, is the same packed or not); h's as they are.
void Finish(const EnergyOptions& options, std::size_t n, double* f) {
    if (options.kind != EnergyKind::kEdge) return;
    const int eighths = EdgeExponentEighths(options.exponent);
    if (options.exponent == 1.0) {
        for (std::size_t k = 0; k < n; ++k) f[k] = std::sqrt(f[k]);
    } else if (eighths != 0) {
        double r[kSummandBlock];  // n ≤ kSummandBlock: SearchEnergy's blocks
        for (std::size_t k = 0; k < n; ++k) r[k] = std::sqrt(std::sqrt(std::sqrt(std::sqrt(f[k]))));
        for (std::size_t k = 0; k < n; ++k) f[k] = r[k];
        for (int j = 1; j < eighths; ++j)
            for (std::size_t k = 0; k < n; ++k) f[k] = f[k] * r[k];
    } else {
        for (std::size_t k = 0; k < n; ++k) f[k] = BandPower(f[k], options.exponent);
    }
}

// The terms of EdgeEnergyGradientAnalytic for one block of points, in its operations and their
// order (JacobianTermsAt, the summand's power, NegatedChainToP4), computed in loops without
// branches: each point's weighted, negated contribution g[c][k] to ∂e/∂p4 and whether that
// function counts it (in front, det J ≠ 0, q > 0, f_e finite).
struct GradientBlock {
    double w[kSummandBlock], invW[kSummandBlock], u[2][kSummandBlock], v[2][kSummandBlock];
    double J[2][2][kSummandBlock], det[kSummandBlock], q[kSummandBlock], power[kSummandBlock];
    double a[kSummandBlock], c[kSummandBlock];  // nᵀ times J's cofactor columns (q = a² + c²)
    double g[3][kSummandBlock];
    bool counts[kSummandBlock];
};

// JacobianTermsAt and the edge summand's q (with or without a normal) of points [begin, n);
// power receives q / det², the summand's square, for Finish.
void JacobianBlock(const SearchEnergy::Points& p, std::size_t begin, std::size_t n,
                   const LightMatrix& m, GradientBlock* b) {
    const double* x[3] = {&p.c[0][begin], &p.c[1][begin], &p.c[2][begin]};
    const double* d[2][3] = {{&p.c[3][begin], &p.c[4][begin], &p.c[5][begin]},
                             {&p.c[6][begin], &p.c[7][begin], &p.c[8][begin]}};
    const double *n1 = &p.c[9][begin], *n2 = &p.c[10][begin], *has = &p.hasNormal[begin];
    const glm::dvec3 rows[2] = {m.p1, m.p2};
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec3 X(x[0][k], x[1][k], x[2][k]);
        const glm::dvec3 D[2] = {{d[0][0][k], d[0][1][k], d[0][2][k]},
                                 {d[1][0][k], d[1][1][k], d[1][2][k]}};
        const double w = glm::dot(m.p4, X), invW = 1.0 / w;
        const double wD[2] = {glm::dot(m.p4, D[0]), glm::dot(m.p4, D[1])};
        double J[2][2], u[2];
        for (int i = 0; i < 2; ++i) {
            u[i] = glm::dot(rows[i], X) * invW;
            b->u[i][k] = u[i];
            b->v[i][k] = wD[i] * invW;
        }
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                J[i][j] = (glm::dot(rows[i], D[j]) - u[i] * wD[j]) * invW;
                b->J[i][j][k] = J[i][j];
            }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        const double a = n1[k] * J[1][1] - n2[k] * J[1][0], c = n2[k] * J[0][0] - n1[k] * J[0][1];
        const double qNone =
            0.5 * (J[0][0] * J[0][0] + J[0][1] * J[0][1] + J[1][0] * J[1][0] + J[1][1] * J[1][1]);
        const double q = has[k] != 0.0 ? a * a + c * c : qNone;
        b->a[k] = a;
        b->c[k] = c;
        b->w[k] = w;
        b->invW[k] = invW;
        b->det[k] = det;
        b->q[k] = q;
        b->power[k] = q / (det * det);
    }
}

// After Finish has raised power[k] to the summand f_e^p: p f_e^(p−1), ∂f_e/∂J and the chain to
// p4, times `weight`, into g; and the points EdgeEnergyGradientAnalytic skips (its summand not
// finite among them).
void ChainBlock(const SearchEnergy::Points& p, std::size_t begin, std::size_t n, double exponent,
                double weight, GradientBlock* b) {
    const double* x[3] = {&p.c[0][begin], &p.c[1][begin], &p.c[2][begin]};
    const double* d[2][3] = {{&p.c[3][begin], &p.c[4][begin], &p.c[5][begin]},
                             {&p.c[6][begin], &p.c[7][begin], &p.c[8][begin]}};
    const double *n1 = &p.c[9][begin], *n2 = &p.c[10][begin], *has = &p.hasNormal[begin];
    const bool unitPower = exponent == 1.0;
    for (std::size_t k = 0; k < n; ++k) {
        double J[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) J[i][j] = b->J[i][j][k];
        const double a = b->a[k], c = b->c[k];
        const bool normal = has[k] != 0.0;
        const double dQ[2][2] = {
            {normal ? 2.0 * c * n2[k] : J[0][0], normal ? -2.0 * c * n1[k] : J[0][1]},
            {normal ? -2.0 * a * n2[k] : J[1][0], normal ? 2.0 * a * n1[k] : J[1][1]}};
        const double det = b->det[k], q = b->q[k];
        const double root = std::sqrt(q), absDet = std::abs(det);
        const double f = root / absDet;
        b->counts[k] = det != 0.0 && q > 0.0 && std::isfinite(f) && std::isfinite(b->power[k]);
        const double cof[2][2] = {{J[1][1], -J[1][0]}, {-J[0][1], J[0][0]}};
        const double power = unitPower ? 1.0 : exponent * b->power[k] / f;
        const double g = power * 0.5 / (root * absDet), t = power * f / det;
        double cX = 0.0, cD[2] = {0.0, 0.0};
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                const double dF = g * dQ[i][j] - t * cof[i][j];
                cX += dF * (J[i][j] - b->u[i][k] * b->v[j][k]);
                cD[j] += dF * b->u[i][k];
            }
        const double scale = weight * b->invW[k];
        for (int e = 0; e < 3; ++e)
            b->g[e][k] = scale * (cX * x[e][k] + cD[0] * d[0][e][k] + cD[1] * d[1][e][k]);
    }
}

// Σ weight ∂(f_e^p)/∂p4 over the points: EdgeEnergyGradientAnalytic's value, bit for bit.
glm::dvec3 PackedEdgeGradient(const SearchEnergy::Points& p, const LightMatrix& m,
                              const EnergyOptions& options, double weight) {
    glm::dvec3 grad(0.0);
    GradientBlock b;
    for (std::size_t begin = 0; begin < p.count; begin += kSummandBlock) {
        const std::size_t n = std::min(kSummandBlock, p.count - begin);
        JacobianBlock(p, begin, n, m, &b);
        Finish(options, n, b.power);
        ChainBlock(p, begin, n, options.exponent, weight, &b);
        for (std::size_t k = 0; k < n; ++k) {
            if (!(b.w[k] > p.frontMargin[begin + k]) || !b.counts[k])
                continue;  // !InFront, or skipped as EdgeEnergyGradientAnalytic skips it
            grad -= glm::dvec3(b.g[0][k], b.g[1][k], b.g[2][k]);
        }
    }
    return grad;
}

}  // namespace

SearchEnergy::SearchEnergy(const LightSamples& samples, const EnergyOptions& options)
    : options_(options), source_(&samples) {
    if (options.IsReport()) {
        report_.emplace(samples);
        return;
    }
    samples_ = ToPoints(samples.lsX, samples.dXdx1, samples.dXdx2,
                        samples.edgeNormal.size() == samples.lsX.size()
                            ? std::span<const glm::dvec2>(samples.edgeNormal)
                            : std::span<const glm::dvec2>());
    if (options.priorWeight != 0.0)
        prior_ = ToPoints(samples.lsPrior, samples.priorDXdx1, samples.priorDXdx2, {});
}

double SearchEnergy::operator()(const LightMatrix& m, double bound) const {
    if (report_) return (*report_)(m, bound);
    constexpr std::size_t kBlock = kSummandBlock;
    double w[kBlock], f[kBlock];
    // The samples: SampleSum's sum, stopping at the bound.
    double sum = 0.0;
    for (std::size_t begin = 0; begin < samples_.count; begin += kBlock) {
        const std::size_t n = std::min(kBlock, samples_.count - begin);
        Summands(samples_, begin, n, options_.kind, m, w, f);
        Finish(options_, n, f);
        for (std::size_t k = 0; k < n; ++k) {
            if (!(w[k] > samples_.frontMargin[begin + k])) return kInf;  // !InFront
            const double fk = f[k];
            sum += std::isnan(fk) ? kInf : fk;
            if (sum >= bound) return sum;
        }
    }
    if (prior_.count == 0) return sum + 0.0;
    // The prior: PriorEnergy's sum in its order, checked against the bound after every block
    // (its partial sums only grow).
    const double scale = options_.priorWeight / static_cast<double>(prior_.count);
    double prior = 0.0;
    for (std::size_t begin = 0; begin < prior_.count; begin += kBlock) {
        const std::size_t n = std::min(kBlock, prior_.count - begin);
        Summands(prior_, begin, n, options_.kind, m, w, f);
        Finish(options_, n, f);
        for (std::size_t k = 0; k < n; ++k) {
            const double fk = f[k];
            if (w[k] > prior_.frontMargin[begin + k] && std::isfinite(fk)) prior += fk;
        }
        if (begin + n < prior_.count && sum + scale * prior >= bound)
            return std::max(sum + scale * prior, bound);
    }
    return sum + options_.priorWeight * prior / static_cast<double>(prior_.count);
}

glm::dvec3 SearchEnergy::Gradient(const LightMatrix& m) const {
    if (options_.kind != EnergyKind::kEdge) return EnergyGradient(m, *source_, options_);
    glm::dvec3 g = PackedEdgeGradient(samples_, m, options_, 1.0);
    if (options_.priorWeight != 0.0) {
        const double weight =
            prior_.count == 0 ? 0.0 : options_.priorWeight / static_cast<double>(prior_.count);
        g += PackedEdgeGradient(prior_, m, options_, weight);
    }
    return g;
}

std::optional<double> RelevantFootprint(const LightMatrix& m, const LightSamples& s) {
    double total = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k) {
        if (!InFront(m.p4, s.lsPrior[k])) continue;
        // ||J⁻¹||_F = √2 · f_e without a normal.
        const double f = Summand(m, EnergyOptions{EnergyKind::kEdge}, s.lsPrior[k], s.priorDXdx1[k],
                                 s.priorDXdx2[k], glm::dvec2(0.0));
        if (std::isfinite(f)) total += std::sqrt(2.0) * f, ++count;
    }
    if (count == 0) return std::nullopt;
    return total / static_cast<double>(count);
}

bool Collapses(const LightMatrix& start, const LightMatrix& refined, const LightSamples& s,
               double factor) {
    if (!(factor > 0.0)) return false;
    const std::optional<double> before = RelevantFootprint(start, s);
    const std::optional<double> after = RelevantFootprint(refined, s);
    if (!before || !after) return false;
    return *after > factor * *before;
}

}  // namespace lexel::spatial
