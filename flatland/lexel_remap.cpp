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
    LexelSamples out;
    out.lexels = lexels;
    const double mid = 0.5 * (lsLow + lsHigh);
    const double half = 0.5 * (lsHigh - lsLow);
    out.wsAxis0 = wsAxisRef + mid;
    out.tanLow = -std::tan(half);
    out.tanHigh = std::tan(half);
    const double width = out.tanHigh - out.tanLow;  // W(θ0)
    out.tanOffset.resize(lsAngle.size());
    out.footprint0.resize(lsAngle.size());
    for (std::size_t i = 0; i < lsAngle.size(); ++i) {
        const double a = lsAngle[i] - mid;
        const double c = std::cos(a);
        out.tanOffset[i] = std::tan(a);
        out.footprint0[i] = dpdAngle[i] * width * c * c / lexels;  // (R1) at θ = θ0
    }
    return out;
}

LexelSamples MakeLexelSamples(const SamplingPass& pass, double lexels) {
    std::vector<double> angle(pass.samples.size()), g(pass.samples.size());
    for (std::size_t i = 0; i < pass.samples.size(); ++i) {
        angle[i] = pass.samples[i].lsAngle;
        g[i] = pass.samples[i].dpdAngle;
    }
    return MakeLexelSamples(angle, g, pass.wsAxis0, lexels);
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

std::optional<std::vector<double>> FootprintsFromScratch(const SamplingPass& pass,
                                                         const Vec2& wsLight, double wsAxis,
                                                         double lexels, double wsRayLow,
                                                         double wsRayHigh) {
    const Vec2 a{std::cos(wsAxis), std::sin(wsAxis)};
    const Vec2 b{-a.y(), a.x()};
    const std::size_t n = pass.samples.size();
    std::vector<double> film(n), dFilmdLambda(n);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& s = pass.samples[i];
        const Vec2 d = s.wsPoint - wsLight;
        const double da = d.dot(a);
        if (!(da > 0.0)) return std::nullopt;
        film[i] = d.dot(b) / da;
        // d/dλ [(d·b)/(d·a)] with dd/dλ = e.
        dFilmdLambda[i] = (s.wsTangent.dot(b) * da - d.dot(b) * s.wsTangent.dot(a)) / (da * da);
        lo = std::min(lo, film[i]);
        hi = std::max(hi, film[i]);
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
    for (std::size_t i = 0; i < n; ++i)
        f[i] = std::abs(pass.samples[i].dpdLambda / (lexelsPerFilm * dFilmdLambda[i]));
    return f;
}

}  // namespace lexel::flatland
