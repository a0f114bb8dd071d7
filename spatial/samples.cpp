#include "lexel/spatial/samples.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "lexel/solvers/footprint_metrics.h"
#include "lexel/spatial/energy_gradient.h"

namespace lexel::spatial {

std::vector<std::uint32_t> BoundaryPixels(Resolution resolution, std::span<const Shade> shades) {
    if (shades.size() != resolution.Count())
        throw std::invalid_argument("BoundaryPixels: " + std::to_string(shades.size()) +
                                    " decisions for " + std::to_string(resolution.Count()) +
                                    " pixels");
    const int w = resolution.width, h = resolution.height;
    std::vector<std::uint32_t> pixels;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const Shade here = shades[i];
            if (here != Shade::kLit && here != Shade::kShadowed) continue;
            bool boundary = false;
            for (int dy = -1; dy <= 1 && !boundary; ++dy)
                for (int dx = -1; dx <= 1 && !boundary; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const Shade there = shades[static_cast<std::size_t>(ny) * w + nx];
                    boundary = (there == Shade::kLit || there == Shade::kShadowed) && there != here;
                }
            if (boundary) pixels.push_back(static_cast<std::uint32_t>(i));
        }
    }
    return pixels;
}

glm::dvec2 EdgeNormalAt(Resolution resolution, std::span<const Shade> shades, std::uint32_t pixel) {
    if (shades.size() != resolution.Count())
        throw std::invalid_argument("EdgeNormalAt: shades do not match the resolution");
    if (pixel >= shades.size())
        throw std::invalid_argument("EdgeNormalAt: pixel outside the image");
    const int w = resolution.width, h = resolution.height;
    const int x = static_cast<int>(pixel % static_cast<std::uint32_t>(w));
    const int y = static_cast<int>(pixel / static_cast<std::uint32_t>(w));
    const auto indicator = [](Shade s, double fallback) {
        return s == Shade::kShadowed ? 1.0 : s == Shade::kLit ? 0.0 : fallback;
    };
    const double centre = indicator(shades[pixel], 0.0);
    double s[3][3];
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
            s[dy + 1][dx + 1] = indicator(shades[static_cast<std::size_t>(ny) * w + nx], centre);
        }
    const glm::dvec2 g((s[0][2] + 2.0 * s[1][2] + s[2][2]) - (s[0][0] + 2.0 * s[1][0] + s[2][0]),
                       (s[2][0] + 2.0 * s[2][1] + s[2][2]) - (s[0][0] + 2.0 * s[0][1] + s[0][2]));
    const double length = glm::length(g);
    return length > 0.0 ? g / length : glm::dvec2(0.0);
}

// Why |n_c·l| / |n_r·l| is a thin shadow's width per unit of its caster (ThinShadowContacts): let
// the caster's plane (normal n_c) meet the receiver's (n_r) along a line, a the unit direction in
// the caster's plane perpendicular to that line and away from the receiver, b the same in the
// receiver's plane, θ the planes' dihedral angle (n_r·a = ±sin θ, n_c·b = ±sin θ). The caster's
// point C = t·a projects along the light direction l onto the receiver's plane at
// S = C − (n_r·C / n_r·l)·l, whose distance from the caster's plane is
// |n_c·S| = t·|n_r·a|·|n_c·l| / |n_r·l| (n_c·a = 0); measured in the receiver's plane from the
// contact line it is |n_c·S| / |n_c·b| = t·|n_c·l| / |n_r·l|, for every θ.
double ThinShadowWidth(const glm::dvec3& casterNormal, const glm::dvec3& receiverNormal,
                       const glm::dvec3& toLight) {
    return std::abs(glm::dot(casterNormal, toLight)) / std::abs(glm::dot(receiverNormal, toLight));
}

std::vector<std::uint32_t> ThinShadowContacts(const Readback& readback,
                                              const LightSpace& lightSpace,
                                              std::span<const Shade> shades) {
    const CameraBuffer& buf = readback.buffer;
    if (shades.size() != buf.resolution.Count())
        throw std::invalid_argument("ThinShadowContacts: shades do not match the resolution");
    const int w = buf.resolution.width, h = buf.resolution.height;
    // Whether the facing-away pixel q touches receiver i in space and casts a thin shadow on it
    // (the light's direction taken at the caster's point: the two are within kContactReach).
    const auto thinContact = [&](std::size_t i, std::size_t q, double reach) {
        if (shades[q] != Shade::kFacingAway) return false;
        if (glm::length(buf.wsPosition[q] - buf.wsPosition[i]) > reach) return false;
        const glm::dvec3 toLight = lightSpace.DirectionToLight(buf.wsPosition[q]);
        return ThinShadowWidth(buf.wsNormal[q], buf.wsNormal[i], toLight) < kThinShadowRatio;
    };
    std::vector<std::uint32_t> pixels;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (shades[i] != Shade::kShadowed || !readback.smooth[i]) continue;
            const double reach = kContactReach * std::max(glm::length(readback.dWdx1[i]),
                                                          glm::length(readback.dWdx2[i]));
            bool contact = false;
            for (int dy = -1; dy <= 1 && !contact; ++dy)
                for (int dx = -1; dx <= 1 && !contact; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    contact = thinContact(i, static_cast<std::size_t>(ny) * w + nx, reach);
                }
            if (contact) pixels.push_back(static_cast<std::uint32_t>(i));
        }
    }
    return pixels;
}

namespace {

// LightSamples::lsPrior and its derivatives: every `stride`-th eligible pixel in pixel order.
void AddPriorPoints(const Readback& readback, const LightSpace& lightSpace,
                    std::span<const Shade> shades, LightSamples* s) {
    const CameraBuffer& buf = readback.buffer;
    const auto eligible = [&](std::size_t i) {
        if (!readback.smooth[i]) return false;
        return shades.empty() || shades[i] == Shade::kLit || shades[i] == Shade::kShadowed;
    };
    std::size_t count = 0;
    for (std::size_t i = 0; i < buf.resolution.Count(); ++i) count += eligible(i);
    const std::size_t stride = std::max<std::size_t>(1, (count + kPriorPoints - 1) / kPriorPoints);
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    std::size_t seen = 0;
    for (std::size_t i = 0; i < buf.resolution.Count(); ++i) {
        if (!eligible(i) || seen++ % stride != 0) continue;
        s->lsPrior.push_back(lightSpace.ToLight(buf.wsPosition[i]));
        s->priorDXdx1.push_back(lsFromWs * readback.dWdx1[i]);
        s->priorDXdx2.push_back(lsFromWs * readback.dWdx2[i]);
        s->wsPrior.push_back(buf.wsPosition[i]);
    }
}

// The thin-shadow contacts that are not boundary pixels, after the boundary samples: no edge
// direction at them (every neighbour is dark), so their normal is (0, 0).
void AddContactSamples(const Readback& readback, const LightSpace& lightSpace,
                       std::span<const std::uint32_t> boundaryPixels, std::span<const Shade> shades,
                       LightSamples* s) {
    const CameraBuffer& buf = readback.buffer;
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    for (const std::uint32_t i : ThinShadowContacts(readback, lightSpace, shades)) {
        if (std::binary_search(boundaryPixels.begin(), boundaryPixels.end(), i)) continue;
        s->lsX.push_back(lightSpace.ToLight(buf.wsPosition[i]));
        s->dXdx1.push_back(lsFromWs * readback.dWdx1[i]);
        s->dXdx2.push_back(lsFromWs * readback.dWdx2[i]);
        s->pixel.push_back(i);
        s->wsX.push_back(buf.wsPosition[i]);
        s->edgeNormal.push_back(glm::dvec2(0.0));
        ++s->contactSamples;
    }
}

// The entries of `values` whose sample is kept, when it holds one per sample (samples built by
// hand may leave the pixels, world points or normals empty: those stay as they are).
template <typename T>
void KeepWhere(std::vector<T>& values, const std::vector<bool>& keep) {
    if (values.size() != keep.size()) return;
    std::size_t kept = 0;
    for (std::size_t s = 0; s < keep.size(); ++s)
        if (keep[s]) values[kept++] = values[s];
    values.resize(kept);
}

}  // namespace

std::uint64_t ThinningPriority(std::uint32_t pixel) {
    // SplitMix64's finalizer (Steele, Lea and Flood, "Fast splittable pseudorandom number
    // generators", OOPSLA 2014): a fixed, well-mixed value per pixel.
    std::uint64_t z = pixel + 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

namespace {

// Which of the n samples ThinSamples keeps (all when n ≤ maxSamples or maxSamples = 0).
std::vector<bool> KeptSamples(const LightSamples& samples, std::size_t maxSamples) {
    const std::size_t n = samples.lsX.size();
    if (maxSamples == 0 || n <= maxSamples) return std::vector<bool>(n, true);
    // Each sample's priority (of its index where the samples, built by hand, have no pixels),
    // ties broken by order; the maxSamples least are kept, in their order.
    std::vector<std::pair<std::uint64_t, std::size_t>> ranked(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t pixel =
            samples.pixel.size() == n ? samples.pixel[i] : static_cast<std::uint32_t>(i);
        ranked[i] = {ThinningPriority(pixel), i};
    }
    const auto budget = static_cast<std::ptrdiff_t>(maxSamples);
    std::nth_element(ranked.begin(), ranked.begin() + budget, ranked.end());
    std::vector<bool> keep(n, false);
    for (std::ptrdiff_t k = 0; k < budget; ++k) keep[ranked[k].second] = true;
    return keep;
}

// The entries of `values` whose sample is kept (KeepWhere on a copy).
template <typename T>
std::vector<T> Kept(const std::vector<T>& values, const std::vector<bool>& keep) {
    std::vector<T> out = values;
    KeepWhere(out, keep);
    return out;
}

// How many of the kept samples are contacts (the last contactSamples of the samples).
std::size_t KeptContacts(const LightSamples& samples, const std::vector<bool>& keep) {
    const std::size_t n = samples.lsX.size(), contacts = std::min(samples.contactSamples, n);
    if (keep.size() != n) return 0;
    const auto tail = keep.end() - static_cast<std::ptrdiff_t>(contacts);
    return static_cast<std::size_t>(std::count(tail, keep.end(), true));
}

// The kept samples of `samples` and its other members, the relevant points given, in
// LightSamples' member order (a member added there and not here is what -Wextra's
// missing-field-initializers warning reports).
LightSamples KeepSamples(const LightSamples& samples, const std::vector<bool>& keep,
                         const std::vector<glm::dvec3>& lsRelevant) {
    LightSamples out = {Kept(samples.lsX, keep),
                        Kept(samples.dXdx1, keep),
                        Kept(samples.dXdx2, keep),
                        Kept(samples.pixel, keep),
                        Kept(samples.wsX, keep),
                        Kept(samples.edgeNormal, keep),
                        lsRelevant,
                        samples.lsRelevantHull,
                        samples.boundaryPixels,
                        KeptContacts(samples, keep),
                        samples.lsPrior,
                        samples.priorDXdx1,
                        samples.priorDXdx2,
                        samples.wsPrior};
    return out;
}

}  // namespace

LightSamples ThinSamples(const LightSamples& samples, std::size_t maxSamples) {
    const std::size_t n = samples.lsX.size();
    if (maxSamples == 0 || n <= maxSamples) return samples;
    return KeepSamples(samples, KeptSamples(samples, maxSamples), samples.lsRelevant);
}

LightSamples PublishedSamples(const LightSamples& samples) {
    const std::size_t n = samples.lsX.size(), contacts = std::min(samples.contactSamples, n);
    if (contacts == 0) return samples;
    std::vector<bool> keep(n, true);
    std::fill(keep.end() - static_cast<std::ptrdiff_t>(contacts), keep.end(), false);
    return KeepSamples(samples, keep, samples.lsRelevant);
}

LightSamples ThinSamplesForSearch(const LightSamples& samples, std::size_t maxSamples) {
    const bool hull = !samples.lsRelevantHull.empty();
    return KeepSamples(samples, KeptSamples(samples, maxSamples),
                       hull ? samples.lsRelevantHull : samples.lsRelevant);
}

LightSamples LightSamplesAtPixels(const Readback& readback, const LightSpace& lightSpace,
                                  std::span<const std::uint32_t> boundaryPixels,
                                  std::span<const Shade> shades) {
    const CameraBuffer& buf = readback.buffer;
    for (std::size_t k = 0; k < boundaryPixels.size(); ++k)
        if (boundaryPixels[k] >= buf.resolution.Count() ||
            (k > 0 && boundaryPixels[k] <= boundaryPixels[k - 1]))
            throw std::invalid_argument(
                "LightSamplesAtPixels: pixels must be ascending and inside the readback");
    if (!shades.empty() && shades.size() != buf.resolution.Count())
        throw std::invalid_argument("LightSamplesAtPixels: " + std::to_string(shades.size()) +
                                    " decisions for " + std::to_string(buf.resolution.Count()) +
                                    " pixels");
    LightSamples s;
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    s.lsRelevant.reserve(readback.wsRelevant.size());
    for (const glm::dvec3& ws : readback.wsRelevant) s.lsRelevant.push_back(lightSpace.ToLight(ws));
    s.lsRelevantHull.reserve(readback.wsRelevantHull.size());
    for (const glm::dvec3& ws : readback.wsRelevantHull)
        s.lsRelevantHull.push_back(lightSpace.ToLight(ws));
    s.boundaryPixels = boundaryPixels.size();
    for (const std::uint32_t i : boundaryPixels) {
        if (!readback.smooth[i]) continue;
        s.lsX.push_back(lightSpace.ToLight(buf.wsPosition[i]));
        s.dXdx1.push_back(lsFromWs * readback.dWdx1[i]);
        s.dXdx2.push_back(lsFromWs * readback.dWdx2[i]);
        s.pixel.push_back(i);
        s.wsX.push_back(buf.wsPosition[i]);
        if (!shades.empty()) s.edgeNormal.push_back(EdgeNormalAt(buf.resolution, shades, i));
    }
    if (!shades.empty()) AddContactSamples(readback, lightSpace, boundaryPixels, shades, &s);
    AddPriorPoints(readback, lightSpace, shades, &s);
    return s;
}

LightSamples MakeLightSamples(const Readback& readback, const LightSpace& lightSpace,
                              std::span<const Shade> shades) {
    return LightSamplesAtPixels(readback, lightSpace,
                                BoundaryPixels(readback.buffer.resolution, shades), shades);
}

void SampleJacobian(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                    const glm::dvec3& dXdx2, glm::dvec2* row1, glm::dvec2* row2) {
    glm::dvec3 du1dX, du2dX;
    matrix.MapJacobian(lsX, &du1dX, &du2dX);
    *row1 = {glm::dot(du1dX, dXdx1), glm::dot(du1dX, dXdx2)};
    *row2 = {glm::dot(du2dX, dXdx1), glm::dot(du2dX, dXdx2)};
}

double SampleBadness(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                     const glm::dvec3& dXdx2, Badness badness) {
    if (!InFront(matrix.p4, lsX)) return std::numeric_limits<double>::infinity();
    glm::dvec2 r1, r2;
    SampleJacobian(matrix, lsX, dXdx1, dXdx2, &r1, &r2);
    Eigen::Matrix2d j;
    j << r1.x, r1.y, r2.x, r2.y;
    return JacobianBadness(j, badness);
}

double Energy(const LightMatrix& matrix, const LightSamples& samples) {
    // The closed form of energy_gradient.h's SampleEnergy (the template Ceres differentiates),
    // which the search evaluates 27 times per light; SampleBadness is the readable reference.
    const double p4[3] = {matrix.p4.x, matrix.p4.y, matrix.p4.z};
    double h = 0.0;
    for (std::size_t k = 0; k < samples.lsX.size(); ++k) {
        if (!InFront(matrix.p4, samples.lsX[k])) return std::numeric_limits<double>::infinity();
        const double f = SampleEnergy(glm::value_ptr(matrix.p1), glm::value_ptr(matrix.p2), p4,
                                      samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]);
        // det(J) = 0 gives S/0 = +inf, or 0/0 when J vanishes: both an unbounded footprint.
        h += std::isnan(f) ? std::numeric_limits<double>::infinity() : f;
    }
    return h;
}

BoundedEnergy::BoundedEnergy(const LightSamples& samples) : count_(samples.lsX.size()) {
    for (std::vector<double>& c : soa_) c.resize(count_);
    frontMargin_.resize(count_);
    for (std::size_t k = 0; k < count_; ++k) {
        const glm::dvec3* v[3] = {&samples.lsX[k], &samples.dXdx1[k], &samples.dXdx2[k]};
        for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c) soa_[3 * a + c][k] = (*v[a])[c];
        frontMargin_[k] = 1e-9 * glm::length(samples.lsX[k]);  // as InFront computes it
    }
}

double BoundedEnergy::operator()(const LightMatrix& matrix, double bound) const {
    constexpr std::size_t kBlock = 64;
    const double* p1 = glm::value_ptr(matrix.p1);
    const double* p2 = glm::value_ptr(matrix.p2);
    const double p4[3] = {matrix.p4.x, matrix.p4.y, matrix.p4.z};
    double f[kBlock], w[kBlock];
    double h = 0.0;
    for (std::size_t begin = 0; begin < count_; begin += kBlock) {
        const std::size_t n = std::min(kBlock, count_ - begin);
        const double *x0 = &soa_[0][begin], *x1 = &soa_[1][begin], *x2 = &soa_[2][begin];
        const double *a0 = &soa_[3][begin], *a1 = &soa_[4][begin], *a2 = &soa_[5][begin];
        const double *b0 = &soa_[6][begin], *b1 = &soa_[7][begin], *b2 = &soa_[8][begin];
        for (std::size_t k = 0; k < n; ++k) {  // no branches: vectorized
            const glm::dvec3 X(x0[k], x1[k], x2[k]);
            w[k] = glm::dot(matrix.p4, X);
            f[k] = SampleEnergy(p1, p2, p4, X, glm::dvec3(a0[k], a1[k], a2[k]),
                                glm::dvec3(b0[k], b1[k], b2[k]));
        }
        const double* margin = &frontMargin_[begin];
        for (std::size_t k = 0; k < n; ++k) {  // Energy's loop
            if (!(w[k] > margin[k])) return std::numeric_limits<double>::infinity();  // !InFront
            h += std::isnan(f[k]) ? std::numeric_limits<double>::infinity() : f[k];
            if (h >= bound) return h;
        }
    }
    return h;
}

}  // namespace lexel::spatial
