// Report Appendix A: the screen → world derivatives of the readback.
//
// Writing the world point as W(x¹, x², x³) = dehomogenized Q⁻¹ (x¹, x², x³, 1), the chain rule
// gives
//     dW/dx^j = ∂W/∂x^j + ∂W/∂x³ · ∂x³/∂x^j,   ∂W/∂x^k = (q_k,xyz - W q_k,w) / h_w   (eq. 7),
// with q_k the k-th column of Q⁻¹ and h = Q⁻¹ x̂. ∂x³/∂x^j is the central difference of the
// z-buffer: the window depth is affine in screen space over a plane, so this is exact on planes.
//
// Depth discontinuities (report §2.4: "derivative continuity is checked by thresholding the
// acceleration in z"): a sample is kept only where, along both screen axes, the three pixels are
// covered and |Δ²x³| ≤ kSmoothness |Δx³| + kDepthNoise. The second difference is exactly 0 on a
// plane, of the order of the pixel's angular size over the surface's angular radius on a curved
// surface (≈ 0.05 for a unit sphere 10 units away at 180²), and of the order of the first
// difference itself across a silhouette or a crease.
#include "lexel/spatial/readback.h"

#include <Eigen/Core>

#include "lexel/solvers/convex_hull_3d.h"
#include "lexel/solvers/stopwatch.h"

namespace lexel::spatial {

namespace {

// Eq. (7): dW/dx^j = ∂W/∂x^j + ∂W/∂x³ · ∂x³/∂x^j at screen point (x¹, x², x³).
void ChainRule(const glm::dmat4& worldFromScreen, glm::dvec3 xs, double dz1, double dz2,
               glm::dvec3* dWdx1, glm::dvec3* dWdx2) {
    const glm::dvec4 hs = worldFromScreen * glm::dvec4(xs, 1.0);
    const glm::dvec3 ws = glm::dvec3(hs) / hs.w;
    glm::dvec3 dW[3];
    for (int k = 0; k < 3; ++k)
        dW[k] = (glm::dvec3(worldFromScreen[k]) - ws * worldFromScreen[k].w) / hs.w;
    *dWdx1 = dW[0] + dW[2] * dz1;
    *dWdx2 = dW[1] + dW[2] * dz2;
}

// Eq. (7) at covered pixel i = (x, y) whose four neighbours are covered; false where the depth is
// not smooth there.
bool PixelDerivatives(const CameraBuffer& buf, const glm::dmat4& worldFromScreen, int x, int y,
                      glm::dvec3* dWdx1, glm::dvec3* dWdx2) {
    const int w = buf.resolution.width;
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    const double z = buf.windowDepth[i];
    const double dz1 = 0.5 * (buf.windowDepth[i + 1] - buf.windowDepth[i - 1]);
    const double dz2 = 0.5 * (buf.windowDepth[i + w] - buf.windowDepth[i - w]);
    const double ddz1 = buf.windowDepth[i + 1] - 2.0 * z + buf.windowDepth[i - 1];
    const double ddz2 = buf.windowDepth[i + w] - 2.0 * z + buf.windowDepth[i - w];
    if (std::abs(ddz1) > kSmoothness * std::abs(dz1) + kDepthNoise ||
        std::abs(ddz2) > kSmoothness * std::abs(dz2) + kDepthNoise)
        return false;
    ChainRule(worldFromScreen, {x + 0.5, y + 0.5, z}, dz1, dz2, dWdx1, dWdx2);
    return true;
}

}  // namespace

Readback MakeReadback(CameraBuffer buffer, const glm::dmat4& screenFromWorld) {
    Readback rb;
    rb.buffer = std::move(buffer);
    const CameraBuffer& buf = rb.buffer;
    const std::size_t n = buf.resolution.Count();
    rb.dWdx1.assign(n, glm::dvec3(0.0));
    rb.dWdx2.assign(n, glm::dvec3(0.0));
    rb.smooth.assign(n, 0);
    const glm::dmat4 worldFromScreen = glm::inverse(screenFromWorld);
    const int w = buf.resolution.width, h = buf.resolution.height;
    for (int y = 1; y < h - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (!buf.Covered(i) || !buf.Covered(i - 1) || !buf.Covered(i + 1) ||
                !buf.Covered(i - w) || !buf.Covered(i + w))
                continue;
            rb.smooth[i] = PixelDerivatives(buf, worldFromScreen, x, y, &rb.dWdx1[i], &rb.dWdx2[i]);
        }
    rb.wsRelevant.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (buf.Covered(i)) rb.wsRelevant.push_back(buf.wsPosition[i]);

    const Stopwatch hullTime;
    rb.wsRelevantHull = RelevantHullVertices(buf);
    rb.relevantHullMs = hullTime.Ms();
    return rb;
}

// On the plane ν·(W, 1) = 0, ν = (n, -n·P), the screen point h = Q⁻¹ (x¹, x², x³, 1) satisfies
// ν·h = 0, which is affine in (x¹, x², x³): x³ = -(ν·q_0 x¹ + ν·q_1 x² + ν·q_3) / ν·q_2, so
// ∂x³/∂x^j = -ν·q_j / ν·q_2 (q_k the columns of Q⁻¹) and eq. (7) is exact.
void PlaneDerivatives(const CameraBuffer& buffer, const glm::dmat4& screenFromWorld,
                      std::vector<glm::dvec3>* dWdx1, std::vector<glm::dvec3>* dWdx2) {
    const std::size_t n = buffer.resolution.Count();
    dWdx1->assign(n, glm::dvec3(0.0));
    dWdx2->assign(n, glm::dvec3(0.0));
    const glm::dmat4 worldFromScreen = glm::inverse(screenFromWorld);
    const int w = buffer.resolution.width;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& wsNormal = buffer.wsNormal[i];
        if (!buffer.Covered(i) || wsNormal == glm::dvec3(0.0)) continue;
        const glm::dvec4 plane(wsNormal, -glm::dot(wsNormal, buffer.wsPosition[i]));
        const double along = glm::dot(plane, worldFromScreen[2]);
        if (!(std::abs(along) > 0.0)) continue;  // the plane contains the eye ray
        const glm::dvec2 xs(static_cast<double>(i % w) + 0.5, static_cast<double>(i / w) + 0.5);
        const double x3 =
            -(glm::dot(plane, worldFromScreen[0]) * xs.x +
              glm::dot(plane, worldFromScreen[1]) * xs.y + glm::dot(plane, worldFromScreen[3])) /
            along;
        ChainRule(worldFromScreen, {xs, x3}, -glm::dot(plane, worldFromScreen[0]) / along,
                  -glm::dot(plane, worldFromScreen[1]) / along, &(*dWdx1)[i], &(*dWdx2)[i]);
    }
}

// The pre-filter. The camera pass gives under each pixel centre the point of its triangle on the
// ray through that centre, and the rays through three consecutive centres of a row (or column)
// lie in one plane through the eye, which cuts the triangle's plane in a line; so the three
// points lie on that line in the pixels' order, the middle one strictly between the others, and
// cannot be a vertex of the hull. Every vertex therefore survives, whatever else is dropped (a
// vertex of conv(S) is never strictly inside a segment of two points of S). In floating point the
// points carry the camera pass's rounding, so the hull of the survivors contains every relevant
// point up to that rounding. On the walkthrough's 180² readback this keeps about 10% of the
// points: the floor's interior goes.
std::vector<glm::dvec3> RelevantHullVertices(const CameraBuffer& buffer) {
    const int w = buffer.resolution.width, h = buffer.resolution.height;
    std::vector<Eigen::Vector3d> wsCandidates;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            const std::int32_t t = buffer.triangle[i];
            if (t < 0) continue;
            const bool rowInterior =
                x > 0 && x < w - 1 && buffer.triangle[i - 1] == t && buffer.triangle[i + 1] == t;
            const bool columnInterior =
                y > 0 && y < h - 1 && buffer.triangle[i - w] == t && buffer.triangle[i + w] == t;
            if (rowInterior || columnInterior) continue;
            const glm::dvec3& ws = buffer.wsPosition[i];
            wsCandidates.emplace_back(ws.x, ws.y, ws.z);
        }
    std::vector<glm::dvec3> wsVertices;
    for (std::size_t k : ConvexHullVertices3D(wsCandidates)) {
        const Eigen::Vector3d& v = wsCandidates[k];
        wsVertices.emplace_back(v.x(), v.y(), v.z());
    }
    return wsVertices;
}

}  // namespace lexel::spatial
