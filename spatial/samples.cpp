#include "spatial/samples.h"

#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <cmath>

#include "solvers/footprint_metrics.h"
#include "spatial/energy_gradient.h"

namespace lexel::spatial {

Readback MakeReadback(const RenderBackend& backend, const Camera& camera, Resolution resolution) {
    Readback rb;
    rb.buffer = backend.RenderCamera(camera, resolution);
    const CameraBuffer& buf = rb.buffer;
    const std::size_t n = resolution.Count();
    rb.dWdx1.assign(n, glm::dvec3(0.0));
    rb.dWdx2.assign(n, glm::dvec3(0.0));
    rb.smooth.assign(n, 0);
    const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(resolution);
    const glm::dmat4 worldFromScreen = glm::inverse(screenFromWorld);
    const int w = resolution.width, h = resolution.height;

    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (!buf.Covered(i) || x == 0 || y == 0 || x == w - 1 || y == h - 1) continue;
            const std::size_t nb[4] = {i - 1, i + 1, i - w, i + w};
            bool ok = true;
            for (std::size_t j : nb) ok = ok && buf.Covered(j);
            if (!ok) continue;
            const double z = buf.windowDepth[i];
            const double dz1 = 0.5 * (buf.windowDepth[i + 1] - buf.windowDepth[i - 1]);
            const double dz2 = 0.5 * (buf.windowDepth[i + w] - buf.windowDepth[i - w]);
            const double ddz1 = buf.windowDepth[i + 1] - 2.0 * z + buf.windowDepth[i - 1];
            const double ddz2 = buf.windowDepth[i + w] - 2.0 * z + buf.windowDepth[i - w];
            if (std::abs(ddz1) > kSmoothness * std::abs(dz1) + kDepthNoise ||
                std::abs(ddz2) > kSmoothness * std::abs(dz2) + kDepthNoise)
                continue;
            // Eq. (7): differentiate W = h.xyz / h.w, h = Q⁻¹ (x¹, x², x³, 1).
            const glm::dvec4 hs = worldFromScreen * glm::dvec4(x + 0.5, y + 0.5, z, 1.0);
            const glm::dvec3 ws = glm::dvec3(hs) / hs.w;
            glm::dvec3 dW[3];
            for (int k = 0; k < 3; ++k)
                dW[k] = (glm::dvec3(worldFromScreen[k]) - ws * worldFromScreen[k].w) / hs.w;
            rb.dWdx1[i] = dW[0] + dW[2] * dz1;
            rb.dWdx2[i] = dW[1] + dW[2] * dz2;
            rb.smooth[i] = 1;
        }
    });
    rb.wsRelevant.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (buf.Covered(i)) rb.wsRelevant.push_back(buf.wsPosition[i]);
    return rb;
}

LightSamples MakeLightSamples(const Readback& readback, const LightSpace& lightSpace,
                              std::span<const Shade> shades) {
    LightSamples s;
    const CameraBuffer& buf = readback.buffer;
    const int w = buf.resolution.width, h = buf.resolution.height;
    const glm::dmat3 lsFromWs = lightSpace.LightFromWorldLinear();
    s.lsRelevant.reserve(readback.wsRelevant.size());
    for (const glm::dvec3& ws : readback.wsRelevant) s.lsRelevant.push_back(lightSpace.ToLight(ws));
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
            if (!boundary) continue;
            ++s.boundaryPixels;
            if (!readback.smooth[i]) continue;
            s.lsX.push_back(lightSpace.ToLight(buf.wsPosition[i]));
            s.dXdx1.push_back(lsFromWs * readback.dWdx1[i]);
            s.dXdx2.push_back(lsFromWs * readback.dWdx2[i]);
            s.pixel.push_back(static_cast<std::uint32_t>(i));
        }
    }
    return s;
}

void SampleJacobian(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                    const glm::dvec3& dXdx2, glm::dvec2* row1, glm::dvec2* row2) {
    glm::dvec3 du1dX, du2dX;
    matrix.MapJacobian(lsX, &du1dX, &du2dX);
    *row1 = {glm::dot(du1dX, dXdx1), glm::dot(du1dX, dXdx2)};
    *row2 = {glm::dot(du2dX, dXdx1), glm::dot(du2dX, dXdx2)};
}

double SampleBadness(const LightMatrix& matrix, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                     const glm::dvec3& dXdx2) {
    if (!InFront(matrix.p4, lsX)) return std::numeric_limits<double>::infinity();
    glm::dvec2 r1, r2;
    SampleJacobian(matrix, lsX, dXdx1, dXdx2, &r1, &r2);
    Eigen::Matrix2d j;
    j << r1.x, r1.y, r2.x, r2.y;
    return JacobianBadness(j, Badness::kFrobeniusInverseSquared);
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

}  // namespace lexel::spatial
