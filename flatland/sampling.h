// The exact sampling pass (Chong 2003, §3 "initial rendering pass", §2.1.3).
//
// Pixel k of a pass with P pixels is the ray from the camera along
//     r_k = d + tan(fov/2) σ_k u,    σ_k = 2(k + ½)/P − 1,    u ⟂ d (u = d rotated by +90°),
// so the continuous pixel coordinate of a world point X with camera coordinates
// (x_c, y_c) = ((X−C)·d, (X−C)·u) is p = P(σ + 1)/2 with σ = y_c / (x_c tan(fov/2)), and pixel
// centers sit at p = k + ½. A pixel is in Ω when its ray hits a segment at positive depth within
// [near, far]; the nearest hit wins.
//
// Along the hit segment's line X(λ) = A + λ e both p and the light angle α (world angle of X − L)
// are smooth, and the pass records their derivatives in closed form:
//     dp/dλ = P / (2 tan(fov/2)) · ((e·u) x_c − (e·d) y_c) / x_c²
//     dα/dλ = (d_L × e) / |d_L|²,    d_L = X − L   (2D cross product)
// g = |dp/dα| = |dp/dλ / dα/dλ| is the pixels per radian of light angle, which does not depend on
// the lexel plane; every footprint dp/dl at every angle follows from (α, g) (lexel_remap.h).
#pragma once

#include <optional>
#include <vector>

#include "lexel/flatland/scene.h"
#include "lexel/solvers/errors.h"

namespace lexel::flatland {

// One visible pixel: 32 bytes (flatland/memory.h counts on it). Only what cannot be recomputed
// cheaply is stored; dp/dλ and g = |dp/dα| follow from it and the pass (PixelsPerLambda,
// PixelsPerRadian below), computed by the same expressions the pass used, so bit for bit.
struct FlatSample {
    Vec2 wsPoint{0, 0};    // hit point
    double lsAngle = 0.0;  // α − θ0: light angle relative to the pass's reference axis, radians
    int pixel = 0;         // k at this pass's resolution; the pixel center is p = k + ½
    int segment = 0;       // index into SamplingPass::segments (Segments(scene))
};
static_assert(sizeof(FlatSample) == 32, "flatland/memory.h assumes 32 bytes per visible pixel");

struct SamplingPass {
    int pixels = 0;
    double wsAxis0 = 0.0;    // θ0: the normal shadow map's axis, bisecting the light's sweep
    double halfSweep = 0.0;  // Δ/2: half the angular sweep of the visible points from the light
    double lsLow = 0.0, lsHigh = 0.0;        // least and greatest lsAngle of the samples
    double depthNear = 0.0, depthFar = 0.0;  // least and greatest hit depth x_c of the samples
    FlatCamera camera;                       // the scene's camera and light, for the derivatives
    Vec2 wsLight{0, 0};
    std::vector<FlatSegment> segments;  // Segments(scene)
    std::vector<FlatSample> samples;    // the visible pixels in pixel order
};

// p = k + ½, the continuous pixel coordinate of a sample's center.
inline double PixelCenter(const FlatSample& s) { return s.pixel + 0.5; }
// e = B − A of the sample's segment.
inline Vec2 SegmentTangent(const SamplingPass& pass, const FlatSample& s) {
    const FlatSegment& segment = pass.segments[s.segment];
    return segment.b - segment.a;
}
// dp/dλ along the sample's segment (PixelDerivativeAlong).
double PixelsPerLambda(const SamplingPass& pass, const FlatSample& s);
// g = |dp/dα|, pixels per radian of light angle.
double PixelsPerRadian(const SamplingPass& pass, const FlatSample& s);

struct RayHit {
    Vec2 wsPoint;
    double depth;
    int segment;
    double lambda;  // position along the segment, [0, 1]
};

// Nearest hit of the camera ray through continuous pixel coordinate p (P pixels), or none.
std::optional<RayHit> CastPixelRay(const FlatCamera& camera,
                                   const std::vector<FlatSegment>& segments, int pixels, double p);

// dp/dλ of a point on a segment line with tangent e (closed form above).
double PixelDerivativeAlong(const FlatCamera& camera, int pixels, const Vec2& wsPoint,
                            const Vec2& wsTangent);

// Runs the pass at `pixels` resolution. Throws DomainError: Subject::kGeometry when no pixel sees
// geometry; kLight when the visible points span 180° or more from the light (no lexel plane has
// them all in front) or all lie on one ray from the light (zero extent); kSegment when a visible
// segment's line passes through the light (its footprints are unbounded).
SamplingPass RunSamplingPass(const FlatScene& scene, int pixels);
// The same without throwing: nullopt, with the error in *defect when given.
std::optional<SamplingPass> TrySamplingPass(const FlatScene& scene, int pixels,
                                            std::optional<DomainError>* defect = nullptr);

}  // namespace lexel::flatland
