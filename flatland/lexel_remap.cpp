#include "lexel/flatland/lexel_remap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

LexelSamples MakeLexelSamples(std::span<const double> lsAngle, std::span<const double> dpdAngle,
                              double wsAxisRef, double lexels) {
    if (lsAngle.empty()) return LexelSamples{wsAxisRef, 0.0, 0.0, lexels, {}, {}};
    const auto [lo, hi] = std::minmax_element(lsAngle.begin(), lsAngle.end());
    return MakeLexelSamples(lsAngle, dpdAngle, wsAxisRef, lexels, *lo, *hi);
}

LexelSamples MakeLexelSamples(std::span<const double> lsAngle, std::span<const double> dpdAngle,
                              double wsAxisRef, double lexels, double lsLow, double lsHigh) {
    return MakeLexelSamples(std::vector<double>(lsAngle.begin(), lsAngle.end()),
                            std::vector<double>(dpdAngle.begin(), dpdAngle.end()), wsAxisRef,
                            lexels, lsLow, lsHigh);
}

namespace {

// θ0, T_lo, T_hi and N of a frustum spanning light angles [lsLow, lsHigh] relative to wsAxisRef.
LexelSamples LexelFrame(double wsAxisRef, double lexels, double lsLow, double lsHigh) {
    LexelSamples out;
    out.lexels = lexels;
    const double half = 0.5 * (lsHigh - lsLow);
    out.wsAxis0 = wsAxisRef + 0.5 * (lsLow + lsHigh);
    out.tanLow = -std::tan(half);
    out.tanHigh = std::tan(half);
    return out;
}

}  // namespace

LexelSamples MakeLexelSamples(std::vector<double>&& lsAngle, std::vector<double>&& dpdAngle,
                              double wsAxisRef, double lexels, double lsLow, double lsHigh) {
    LexelSamples out = LexelFrame(wsAxisRef, lexels, lsLow, lsHigh);
    const double mid = 0.5 * (lsLow + lsHigh);
    const double width = out.tanHigh - out.tanLow;  // W(θ0)
    out.tanOffset = std::move(lsAngle);
    out.footprint0 = std::move(dpdAngle);
    for (std::size_t i = 0; i < out.tanOffset.size(); ++i) {
        const double a = out.tanOffset[i] - mid;
        const double c = std::cos(a);
        out.tanOffset[i] = std::tan(a);
        out.footprint0[i] = out.footprint0[i] * width * c * c / lexels;  // (R1) at θ = θ0
    }
    return out;
}

LexelSamples MakeLexelSamples(const SamplingPass& pass, double lexels) {
    if (pass.samples.empty()) return LexelSamples{pass.wsAxis0, 0.0, 0.0, lexels, {}, {}};
    std::vector<double> angle(pass.samples.size()), g(pass.samples.size());
    for (std::size_t i = 0; i < pass.samples.size(); ++i) {
        angle[i] = pass.samples[i].lsAngle;
        g[i] = PixelsPerRadian(pass, pass.samples[i]);
    }
    // pass.lsLow/lsHigh are the extremes of the samples' lsAngle (sampling.h).
    return MakeLexelSamples(std::move(angle), std::move(g), pass.wsAxis0, lexels, pass.lsLow,
                            pass.lsHigh);
}

LexelSamples MakeLexelFrame(const SamplingPass& pass, double lexels) {
    if (pass.samples.empty()) return LexelSamples{pass.wsAxis0, 0.0, 0.0, lexels, {}, {}};
    return LexelFrame(pass.wsAxis0, lexels, pass.lsLow, pass.lsHigh);
}

double LexelCoordinate(const LexelSamples& samples, std::size_t i) {
    return samples.lexels * (samples.tanOffset[i] - samples.tanLow) /
           (samples.tanHigh - samples.tanLow);
}

ValidInterval ValidTInterval(const LexelSamples& samples) {
    return {-1.0 / samples.tanHigh, -1.0 / samples.tanLow};
}

std::vector<double> RemappedFootprints(const LexelSamples& samples, double t) {
    std::vector<double> f(samples.size());
    const double denom = (1.0 + t * samples.tanHigh) * (1.0 + t * samples.tanLow);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double n = 1.0 + t * samples.tanOffset[i];
        f[i] = samples.footprint0[i] * n * n / denom;
    }
    return f;
}

double WsAxisFromT(const LexelSamples& samples, double t) { return samples.wsAxis0 + std::atan(t); }

double TFromLexelPlaneDeg(const LexelSamples& samples, double lexelPlaneDeg) {
    return std::tan(Radians(lexelPlaneDeg) - samples.wsAxis0);
}

std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels) {
    return FootprintsFromScratch(pass, wsLight, wsAxis, lexels, NAN, NAN);
}

namespace {

// FootprintsFromScratch over all samples (subset false) or over pass.samples[indices[k]].
std::optional<std::vector<double>> Footprints(const SamplingPass& pass, bool subset,
                                              std::span<const std::uint32_t> indices,
                                              const Vec2& wsLight, double wsAxis, double lexels,
                                              double wsRayLow, double wsRayHigh) {
    const Vec2 a{std::cos(wsAxis), std::sin(wsAxis)};
    const Vec2 b{-a.y(), a.x()};
    const std::size_t n = subset ? indices.size() : pass.samples.size();
    const auto sampleAt = [&](std::size_t i) -> const FlatSample& {
        return pass.samples[subset ? indices[i] : i];
    };
    // Pass 1: the film extent. Nothing but f is stored per sample (flatland/memory.h); pass 2
    // recomputes d and its dot products by the same expressions.
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 d = sampleAt(i).wsPoint - wsLight;
        const double da = d.dot(a);
        if (!(da > 0.0)) return std::nullopt;
        const double film = d.dot(b) / da;
        lo = std::min(lo, film);
        hi = std::max(hi, film);
    }
    if (!std::isnan(wsRayLow)) {
        // Film coordinates of the bounding rays: s = tan(β − θ); both must be in front.
        const double xLow = std::remainder(wsRayLow - wsAxis, 2 * std::numbers::pi);
        const double xHigh = std::remainder(wsRayHigh - wsAxis, 2 * std::numbers::pi);
        if (!(std::abs(xLow) < std::numbers::pi / 2 && std::abs(xHigh) < std::numbers::pi / 2))
            return std::nullopt;
        lo = std::min(lo, std::tan(xLow));
        hi = std::max(hi, std::tan(xHigh));
    }
    std::vector<double> f(n);
    const double lexelsPerFilm = lexels / (hi - lo);
    for (std::size_t i = 0; i < n; ++i) {
        const FlatSample& s = sampleAt(i);
        const Vec2 d = s.wsPoint - wsLight;
        const Vec2 e = SegmentTangent(pass, s);
        const double da = d.dot(a);
        // d/dλ [(d·b)/(d·a)] with dd/dλ = e.
        const double dFilmdLambda = (e.dot(b) * da - d.dot(b) * e.dot(a)) / (da * da);
        f[i] = std::abs(PixelsPerLambda(pass, s) / (lexelsPerFilm * dFilmdLambda));
    }
    return f;
}

}  // namespace

std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels, double wsRayLow,
                                                         double wsRayHigh) {
    return Footprints(pass, false, {}, wsLight, wsAxis, lexels, wsRayLow, wsRayHigh);
}

std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         std::span<const std::uint32_t> indices,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels, double wsRayLow,
                                                         double wsRayHigh) {
    return Footprints(pass, true, indices, wsLight, wsAxis, lexels, wsRayLow, wsRayHigh);
}

}  // namespace lexel::flatland
