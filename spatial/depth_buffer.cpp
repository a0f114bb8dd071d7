// Depth buffers of every convention as readbacks (depth_buffer.h).
#include "lexel/spatial/depth_buffer.h"

#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <stdexcept>
#include <string>

namespace lexel::spatial {

namespace {

// The viewport of `convention` at `resolution`: clip → (x¹ w, x² w, x³ w, w) (depth_buffer.h).
glm::dmat4 ScreenFromClip(Resolution resolution, const DepthConvention& convention) {
    const double halfW = 0.5 * resolution.width, halfH = 0.5 * resolution.height;
    const double ySign = convention.firstRow == FirstRow::kAtNdcYPlusOne ? -1.0 : 1.0;
    const bool zeroToOne = convention.clipDepth == ClipDepth::kZeroToOne;
    glm::dmat4 m(0.0);  // column-major: m[column][row]
    m[0][0] = halfW;
    m[1][1] = ySign * halfH;
    m[2][2] = zeroToOne ? 1.0 : 0.5;
    m[3] = glm::dvec4(halfW, halfH, zeroToOne ? 0.0 : 0.5, 1.0);
    return m;
}

std::string SizeText(Resolution r) {
    return std::to_string(r.width) + "×" + std::to_string(r.height);
}

void CheckSize(Resolution resolution, std::size_t values) {
    if (resolution.width < 1 || resolution.height < 1 || values != resolution.Count())
        throw std::invalid_argument("depth buffer: " + std::to_string(values) + " values for a " +
                                    SizeText(resolution) + " image");
}

void CheckMatrix(const glm::dmat4& screenFromWorld) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(screenFromWorld[c][r]))
                throw std::invalid_argument("depth buffer: its matrix is not finite");
    if (glm::determinant(screenFromWorld) == 0.0)
        throw std::invalid_argument("depth buffer: the screen-from-world matrix is singular");
}

// For a perspective projection (clip w not constant), whether stored depth grows away from the
// eye: the points stored at 1/4 and 3/4 under the image centre, compared by |w_clip|, which is
// their distance along the view axis up to one positive factor.
void CheckDirection(const DepthBuffer& buffer, const glm::dmat4& screenFromWorld) {
    const glm::dvec4 rowW = glm::row(buffer.clipFromWorld, 3);
    if (!(glm::length(glm::dvec3(rowW)) > 1e-12 * glm::length(rowW))) return;  // orthographic
    const glm::dmat4 worldFromScreen = glm::inverse(screenFromWorld);
    const glm::dvec2 centre(0.5 * buffer.resolution.width, 0.5 * buffer.resolution.height);
    const auto viewDepth = [&](double stored) {
        const glm::dvec4 h = worldFromScreen * glm::dvec4(centre, stored, 1.0);
        return std::abs(glm::dot(rowW, h / h.w));
    };
    const bool grows = viewDepth(0.75) > viewDepth(0.25);
    const bool reversed = buffer.convention.direction == DepthDirection::kReversed;
    if (grows == reversed)
        throw std::invalid_argument(
            std::string("depth buffer: the projection stores depth that ") +
            (grows ? "grows" : "falls") + " away from the camera, but the convention says " +
            (reversed ? "DepthDirection::kReversed; use kStandard"
                      : "DepthDirection::kStandard; use kReversed (reversed-Z)"));
}

// The covered pixels' world points: Q⁻¹ (x¹, x², x³, 1) dehomogenized at the pixel centres.
CameraBuffer Unproject(Resolution resolution, std::span<const float> depth,
                       const glm::dmat4& screenFromWorld, bool reversed) {
    const glm::dmat4 worldFromScreen = glm::inverse(screenFromWorld);
    CameraBuffer buf;
    buf.resolution = resolution;
    const std::size_t n = resolution.Count();
    buf.windowDepth.assign(n, 1.0);
    buf.wsPosition.assign(n, glm::dvec3(0.0));
    buf.wsNormal.assign(n, glm::dvec3(0.0));
    buf.triangle.assign(n, -1);
    for (int y = 0; y < resolution.height; ++y)
        for (int x = 0; x < resolution.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * resolution.width + x;
            const float d = depth[i];
            if (!std::isfinite(d) || !(reversed ? d > 0.0f : d < 1.0f)) continue;
            buf.windowDepth[i] = d;
            const glm::dvec4 h = worldFromScreen * glm::dvec4(x + 0.5, y + 0.5, d, 1.0);
            buf.wsPosition[i] = glm::dvec3(h) / h.w;
            buf.triangle[i] = static_cast<std::int32_t>(i);
        }
    return buf;
}

// Source column (or row) of sample 0 and the samples along one axis of `size` pixels.
void SampleAxis(int size, int step, int* samples, int* offset) {
    *samples = std::max(1, size / step);
    *offset = size >= step ? (size - step * *samples) / 2 + step / 2 : size / 2;
}

}  // namespace

glm::dmat4 ScreenFromWorld(const DepthBuffer& buffer) {
    return ScreenFromClip(buffer.resolution, buffer.convention) * buffer.clipFromWorld;
}

CameraBuffer CameraBufferFromDepth(const DepthBuffer& buffer) {
    CheckSize(buffer.resolution, buffer.depth.size());
    const glm::dmat4 screenFromWorld = ScreenFromWorld(buffer);
    CheckMatrix(screenFromWorld);
    CheckDirection(buffer, screenFromWorld);
    return Unproject(buffer.resolution, buffer.depth, screenFromWorld,
                     buffer.convention.direction == DepthDirection::kReversed);
}

CameraBuffer CameraBufferFromDepth(Resolution resolution, std::span<const float> windowDepth,
                                   const glm::dmat4& screenFromWorld) {
    CheckSize(resolution, windowDepth.size());
    CheckMatrix(screenFromWorld);
    return Unproject(resolution, windowDepth, screenFromWorld, false);
}

Readback MakeReadback(const DepthBuffer& buffer) {
    return MakeReadback(CameraBufferFromDepth(buffer), ScreenFromWorld(buffer));
}

DepthImage DownsampleDepth(const DepthBuffer& buffer, int maxSide) {
    if (maxSide < 1)
        throw std::invalid_argument("DownsampleDepth: maxSide " + std::to_string(maxSide) +
                                    " must be at least 1");
    CheckSize(buffer.resolution, buffer.depth.size());
    const Resolution source = buffer.resolution;
    const int longSide = std::max(source.width, source.height);
    DepthImage out;
    out.convention = buffer.convention;
    out.step = (longSide + maxSide - 1) / maxSide;
    SampleAxis(source.width, out.step, &out.resolution.width, &out.offset.x);
    SampleAxis(source.height, out.step, &out.resolution.height, &out.offset.y);
    out.depth.resize(out.resolution.Count());
    for (int j = 0; j < out.resolution.height; ++j)
        for (int i = 0; i < out.resolution.width; ++i) {
            const std::size_t from =
                static_cast<std::size_t>(out.step * j + out.offset.y) * source.width +
                static_cast<std::size_t>(out.step * i + out.offset.x);
            out.depth[static_cast<std::size_t>(j) * out.resolution.width + i] = buffer.depth[from];
        }
    // Sample (i, j) has its centre at source screen point step · (i + ½, j + ½) + b with
    // b = offset + ½ - step/2, so the small image's screen is (source screen - b) / step.
    const double step = out.step;
    glm::dmat4 smallFromSource(1.0);
    smallFromSource[0][0] = smallFromSource[1][1] = 1.0 / step;
    smallFromSource[3][0] = -(out.offset.x + 0.5 - 0.5 * step) / step;
    smallFromSource[3][1] = -(out.offset.y + 0.5 - 0.5 * step) / step;
    out.clipFromWorld = glm::inverse(ScreenFromClip(out.resolution, out.convention)) *
                        smallFromSource * ScreenFromWorld(buffer);
    return out;
}

}  // namespace lexel::spatial
