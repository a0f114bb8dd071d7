#include "lexel/spatial/rtw.h"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "lexel/solvers/lagrange_allocation.h"
#include "lexel/spatial/perspective_aliasing.h"

namespace lexel::spatial {

namespace {

// J = ∂b/∂x (base texels per readback pixel) of a point with light-space derivatives.
Eigen::Matrix2d BaseJacobian(const LightMatrix& base, const glm::dvec3& lsX,
                             const glm::dvec3& dXdx1, const glm::dvec3& dXdx2) {
    glm::dvec2 r1, r2;
    SampleJacobian(base, lsX, dXdx1, dXdx2, &r1, &r2);
    Eigen::Matrix2d j;
    j << r1.x, r1.y, r2.x, r2.y;
    return j;
}

// Max-splats `value` over the texels within (hx, hy) of b (capped at kRtwMaxSplat).
void Splat(ImportanceMap* map, const glm::dvec2& b, double hx, double hy, double value) {
    const Resolution r = map->resolution;
    const double cx = std::min(hx, static_cast<double>(kRtwMaxSplat));
    const double cy = std::min(hy, static_cast<double>(kRtwMaxSplat));
    const int x0 = std::max(0, static_cast<int>(std::floor(b.x - cx)));
    const int x1 = std::min(r.width - 1, static_cast<int>(std::floor(b.x + cx)));
    const int y0 = std::max(0, static_cast<int>(std::floor(b.y - cy)));
    const int y1 = std::min(r.height - 1, static_cast<int>(std::floor(b.y + cy)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            double& v = map->value[static_cast<std::size_t>(y) * r.width + x];
            v = std::max(v, value);
        }
}

// The knot values W w_i of one axis's warp from its 1-D profile (steps 3–5).
AxisWarp AxisFromProfile(std::span<const double> profile, double extent,
                         const RtwOptions& options) {
    if (profile.empty()) return AxisWarp();
    const std::vector<double> blurred =
        GaussianBlur(profile, options.blurSigma * static_cast<double>(profile.size()));
    std::vector<double> w = CumulativeWarp(FlooredDensity(blurred, options.densityFloor));
    for (double& v : w) v *= extent;
    return AxisWarp::Piecewise(0.0, extent, std::move(w));
}

}  // namespace

ImportanceMap RtwImportance(const Readback& readback, const Camera& camera,
                            const LightSpace& lightSpace, const LightMatrix& base, Resolution map,
                            Resolution frame, std::span<const std::uint32_t> edgePixels,
                            const RtwOptions& options) {
    ImportanceMap out{map, std::vector<double>(map.Count(), 0.0)};
    const CameraBuffer& buffer = readback.buffer;
    const Resolution rb = buffer.resolution;
    std::vector<glm::dvec3> planeDx1, planeDx2;
    PlaneDerivatives(buffer, camera.ScreenFromWorld(rb), &planeDx1, &planeDx2);
    std::vector<std::uint8_t> edge(rb.Count(), 0);
    for (std::uint32_t p : edgePixels)
        if (p < edge.size()) edge[p] = 1;
    // The perspective aliasing is measured against the pixels of a `frame`-sized image.
    Camera frameCamera = camera;
    frameCamera.resolution = frame;
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    for (std::size_t i = 0; i < buffer.triangle.size(); ++i) {
        if (!buffer.Covered(i)) continue;
        glm::dvec3 dx1 = planeDx1[i], dx2 = planeDx2[i];
        if (dx1 == glm::dvec3(0.0) && dx2 == glm::dvec3(0.0)) {
            if (!readback.smooth[i]) continue;
            dx1 = readback.dWdx1[i], dx2 = readback.dWdx2[i];
        }
        const glm::dvec3 lsX = lightSpace.ToLight(buffer.wsPosition[i]);
        if (!InFront(base.p4, lsX)) continue;
        // The texels the pixel asks for: base texels' width over the frame pixel's there,
        // without the receiver's orientation (projection aliasing, which no warp of the map
        // can serve and which is unbounded where the pixel's plane nears its light ray).
        const double rate =
            PerspectiveAliasing(frameCamera, lightSpace, base, buffer.wsPosition[i]);
        if (!std::isfinite(rate)) continue;  // the map is singular there
        // Where the pixel lands in the map: the parallelogram its readback pixel covers.
        const Eigen::Matrix2d perReadback = BaseJacobian(base, lsX, lsFromWs * dx1, lsFromWs * dx2);
        const double value = rate * (edge[i] ? 1.0 + options.edgeWeight : 1.0);
        const double hx = 0.5 * (std::abs(perReadback(0, 0)) + std::abs(perReadback(0, 1)));
        const double hy = 0.5 * (std::abs(perReadback(1, 0)) + std::abs(perReadback(1, 1)));
        Splat(&out, base.Map(lsX), hx, hy, value);
    }
    return out;
}

AxisProfile RowColumnMaxima(const ImportanceMap& importance) {
    const Resolution r = importance.resolution;
    AxisProfile out{std::vector<double>(r.width, 0.0), std::vector<double>(r.height, 0.0)};
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const double v = importance.value[static_cast<std::size_t>(y) * r.width + x];
            out.x[x] = std::max(out.x[x], v);
            out.y[y] = std::max(out.y[y], v);
        }
    return out;
}

std::vector<double> GaussianBlur(std::span<const double> values, double sigma) {
    std::vector<double> out(values.begin(), values.end());
    if (!(sigma > 0.0) || values.empty()) return out;
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> kernel(2 * radius + 1);
    for (int k = -radius; k <= radius; ++k)
        kernel[k + radius] = std::exp(-0.5 * (k / sigma) * (k / sigma));
    const int n = static_cast<int>(values.size());
    for (int i = 0; i < n; ++i) {
        double sum = 0.0, weight = 0.0;
        for (int k = std::max(-radius, -i); k <= std::min(radius, n - 1 - i); ++k) {
            sum += kernel[k + radius] * values[i + k];
            weight += kernel[k + radius];
        }
        out[i] = sum / weight;
    }
    return out;
}

std::vector<double> FlooredDensity(std::span<const double> values, double floor) {
    const double mean = values.empty() ? 0.0
                                       : std::accumulate(values.begin(), values.end(), 0.0) /
                                             static_cast<double>(values.size());
    std::vector<double> out(values.size(), 1.0);
    if (!(mean > 0.0) || !std::isfinite(mean)) return out;
    for (std::size_t i = 0; i < values.size(); ++i)
        out[i] = std::max(values[i], std::max(floor, 0.0) * mean);
    return out;
}

std::vector<double> CumulativeWarp(std::span<const double> density) {
    if (density.empty()) throw std::invalid_argument("CumulativeWarp: no bins");
    std::vector<double> w(density.size() + 1, 0.0);
    for (std::size_t i = 0; i < density.size(); ++i) {
        if (!(density[i] > 0.0) || !std::isfinite(density[i]))
            throw std::invalid_argument("CumulativeWarp: densities must be finite and > 0");
        w[i + 1] = w[i] + density[i];
    }
    const double total = w.back();
    for (double& v : w) v /= total;
    w.back() = 1.0;
    return w;
}

MapWarp RectilinearWarp(const LightMatrix& base, Resolution map, const AxisProfile& profile,
                        const RtwOptions& options) {
    MapWarp warp = MapWarp::Linear(base);
    warp.x = AxisFromProfile(profile.x, map.width, options);
    warp.y = AxisFromProfile(profile.y, map.height, options);
    return warp;
}

SeparableCost EnergyHCost() {
    return {2, [](std::size_t, const glm::dvec2& c1, const glm::dvec2& c2) {
                return glm::dvec2(glm::dot(c1, c1), glm::dot(c2, c2));
            }};
}

AxisProfile LagrangeAxisCosts(const LightSamples& samples, const LightMatrix& base, Resolution map,
                              Resolution bins, const SeparableCost& cost) {
    AxisProfile out{std::vector<double>(bins.width, 0.0), std::vector<double>(bins.height, 0.0)};
    for (std::size_t k = 0; k < samples.lsX.size(); ++k) {
        if (!InFront(base.p4, samples.lsX[k])) continue;
        const glm::dvec2 b = base.Map(samples.lsX[k]);
        if (!(b.x >= 0.0 && b.y >= 0.0 && b.x < map.width && b.y < map.height)) continue;
        const Eigen::Matrix2d j =
            BaseJacobian(base, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]);
        const double det = j.determinant();
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) continue;
        const Eigen::Matrix2d inverse = j.inverse();
        const glm::dvec2 terms = cost.terms(k, glm::dvec2(inverse(0, 0), inverse(1, 0)),
                                            glm::dvec2(inverse(0, 1), inverse(1, 1)));
        const auto bx = static_cast<std::size_t>(b.x * bins.width / map.width);
        const auto by = static_cast<std::size_t>(b.y * bins.height / map.height);
        out.x[std::min<std::size_t>(bx, bins.width - 1)] += terms.x;
        out.y[std::min<std::size_t>(by, bins.height - 1)] += terms.y;
    }
    return out;
}

AxisProfile LagrangeDensities(const AxisProfile& costs, int exponent) {
    return {AllocateLexelsReal(costs.x, exponent, static_cast<double>(costs.x.size())),
            AllocateLexelsReal(costs.y, exponent, static_cast<double>(costs.y.size()))};
}

}  // namespace lexel::spatial
