// The light matrix as a rasterizer's 4×4: texel coordinates through the clip matrix equal the
// light matrix's map, and depth spans the requested range in both conventions.
#include "lexel/spatial/clip_matrix.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "lexel/spatial/camera.h"
#include "lexel/spatial/depth_buffer.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/standard_map.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

Bounds SceneBounds() {
    Bounds b;
    b.Add({-10.0, 0.0, -10.0});
    b.Add({10.0, 4.0, 10.0});
    return b;
}

// A light matrix with a tilted axis and a non-trivial affine part.
LightMatrix SomeMatrix(const LightSpace& ls, const Bounds& wsBounds, double tilt) {
    const glm::dvec3 p4 = glm::normalize(glm::dvec3(tilt, -0.5 * tilt, 1.0));
    std::vector<glm::dvec3> lsCorners;
    for (const glm::dvec3& c : wsBounds.Corners()) lsCorners.push_back(ls.ToLight(c));
    return *FitMapToPoints(p4, lsCorners, {512, 256});
}

TEST(ClipFromWorld, TexelsAreTheLightMatrixMapAndDepthSpansTheRange) {
    const Bounds wsBounds = SceneBounds();
    const Light point{Light::Type::kPoint, {30.0, 40.0, 20.0}, {}};
    const Light sun{Light::Type::kDirectional, {}, {-0.3, -1.0, 0.2}};
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (const Light& light : {point, sun})
        for (double tilt : {0.0, 0.2})
            for (ClipDepth convention : {ClipDepth::kMinusOneToOne, ClipDepth::kZeroToOne}) {
                const LightSpace ls(light, wsBounds);
                const LightMatrix m = SomeMatrix(ls, wsBounds, tilt);
                const Resolution map{512, 256};
                // The range: the extreme w (point) or depth (directional) over the corners.
                double lo = 1e300, hi = -1e300;
                for (const glm::dvec3& c : wsBounds.Corners()) {
                    const double v = ls.IsPoint() ? glm::dot(m.p4, ls.ToLight(c)) : ls.Depth(c);
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
                const glm::dmat4 clip = ClipFromWorld(ls, m, map, {lo, hi}, convention);
                const double zNear = convention == ClipDepth::kZeroToOne ? 0.0 : -1.0;
                for (int k = 0; k < 100; ++k) {
                    const glm::dvec3 x = wsBounds.lo + glm::dvec3(u01(rng), u01(rng), u01(rng)) *
                                                           (wsBounds.hi - wsBounds.lo);
                    const glm::dvec4 h = clip * glm::dvec4(x, 1.0);
                    ASSERT_GT(h.w, 0.0);
                    const glm::dvec2 u = m.Map(ls.ToLight(x));
                    EXPECT_NEAR((h.x / h.w + 1.0) * 0.5 * map.width, u.x, 1e-9 * map.width);
                    EXPECT_NEAR((h.y / h.w + 1.0) * 0.5 * map.height, u.y, 1e-9 * map.height);
                    const double z = h.z / h.w;
                    if (ls.IsPoint() || tilt == 0.0) {  // the range is exact here
                        EXPECT_GE(z, zNear - 1e-12);
                        EXPECT_LE(z, 1.0 + 1e-12);
                    }
                    // Depth grows along the light ray through x.
                    const glm::dvec3 toLight = ls.DirectionToLight(x);
                    const glm::dvec4 nearer = clip * glm::dvec4(x + 0.5 * toLight, 1.0);
                    EXPECT_LT(nearer.z / nearer.w, z) << "point " << k;
                }
                // The ends of the range land on the ends of the depth interval.
                if (ls.IsPoint()) {
                    glm::dvec3 origin, dir;
                    ls.Ray(glm::dvec3(0.0, 0.0, 1.0), &origin, &dir);
                    const double along = glm::dot(m.p4, glm::dvec3(0.0, 0.0, 1.0));
                    const glm::dvec4 a = clip * glm::dvec4(origin + (lo / along) * dir, 1.0);
                    const glm::dvec4 b = clip * glm::dvec4(origin + (hi / along) * dir, 1.0);
                    EXPECT_NEAR(a.z / a.w, zNear, 1e-9);
                    EXPECT_NEAR(b.z / b.w, 1.0, 1e-9);
                }
            }
}

TEST(MapFromWorld, RowsOneTwoFourAreTheLightMatrixInWorldForm) {
    const Bounds wsBounds = SceneBounds();
    const LightSpace ls(Light{Light::Type::kPoint, {5.0, 30.0, -25.0}, {}}, wsBounds);
    const LightMatrix m = SomeMatrix(ls, wsBounds, 0.3);
    const glm::dmat4 world = MapFromWorld(ls, m);
    for (const glm::dvec3& x : wsBounds.Corners()) {
        const glm::dvec4 h = world * glm::dvec4(x, 1.0);
        const glm::dvec3 expected = m.Homogeneous(ls.ToLight(x));
        EXPECT_NEAR(h.x, expected.x, 1e-9 * std::abs(expected.z) * 512);
        EXPECT_NEAR(h.y, expected.y, 1e-9 * std::abs(expected.z) * 512);
        EXPECT_EQ(h.z, 0.0);
        EXPECT_NEAR(h.w, expected.z, 1e-12 * glm::length(x - ls.light().position));
    }
}

// ClipFromWorld's depth, as a function of the quantity LightDepthRange bounds.
double NdcDepth(const LightSpace& ls, double q, DepthRange range) {
    const double n = range.near, f = range.far;
    return ls.IsPoint() ? f / (f - n) * (1.0 - n / q) : (q - n) / (f - n);  // kZeroToOne
}

TEST(LightDepthRange, ClipDepthQuantityIsWhatClipFromWorldMapsToTheDepthRange) {
    const Bounds wsBounds = SceneBounds();
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (const Light& light : {Light{Light::Type::kPoint, {30.0, 40.0, 20.0}, {}},
                               Light{Light::Type::kDirectional, {}, {-0.3, -1.0, 0.2}}}) {
        const LightSpace ls(light, wsBounds);
        const LightMatrix m = SomeMatrix(ls, wsBounds, 0.2);
        const DepthRange range{20.0, 70.0};
        const glm::dmat4 clip = ClipFromWorld(ls, m, {512, 256}, range, ClipDepth::kZeroToOne);
        for (int k = 0; k < 50; ++k) {
            const glm::dvec3 x = wsBounds.lo + glm::dvec3(u01(rng), u01(rng), u01(rng)) *
                                                   (wsBounds.hi - wsBounds.lo);
            const glm::dvec4 h = clip * glm::dvec4(x, 1.0);
            EXPECT_NEAR(h.z / h.w, NdcDepth(ls, ClipDepthQuantity(ls, m, x), range), 1e-12);
        }
    }
}

// The NDC z ∈ [0, 1] range of `points` under `clip`.
std::pair<double, double> NdcDepthSpan(const glm::dmat4& clip, std::span<const glm::dvec3> points) {
    double lo = 1.0, hi = 0.0;
    for (const glm::dvec3& x : points) {
        const glm::dvec4 h = clip * glm::dvec4(x, 1.0);
        lo = std::min(lo, h.z / h.w);
        hi = std::max(hi, h.z / h.w);
    }
    return {lo, hi};
}

// The least NDC z under `clip` of the possible casters: points of the bounds on the segments
// from every 7th receiver toward the light (20 per segment, to the light or out of the bounds).
double NearestCasterNdc(const LightSpace& ls, const glm::dmat4& clip, const Bounds& wsBounds,
                        std::span<const glm::dvec3> wsReceivers) {
    double lowest = 1.0;
    for (std::size_t i = 0; i < wsReceivers.size(); i += 7) {
        const glm::dvec3& x = wsReceivers[i];
        const glm::dvec3 toLight = ls.DirectionToLight(x);
        double reach = ls.DistanceToLight(x);
        for (int a = 0; a < 3; ++a)
            if (toLight[a] != 0.0)
                reach =
                    std::min(reach, ((toLight[a] > 0 ? wsBounds.hi[a] : wsBounds.lo[a]) - x[a]) /
                                        toLight[a]);
        for (int k = 1; k <= 20; ++k)
            lowest =
                std::min(lowest, NdcDepthSpan(clip, {{x + (reach * k / 20.0) * toLight}}).first);
    }
    return lowest;
}

// The least ClipDepthQuantity over 200,000 random points of the bounds inside the map's frustum.
double SampledNearestInMap(const LightSpace& ls, const LightMatrix& matrix, Resolution map,
                           const Bounds& wsBounds, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double nearest = 1e300;
    for (int k = 0; k < 200000; ++k) {
        const glm::dvec3 x =
            wsBounds.lo + glm::dvec3(u01(rng), u01(rng), u01(rng)) * (wsBounds.hi - wsBounds.lo);
        const glm::dvec3 lsX = ls.ToLight(x);
        if (!InFront(matrix.p4, lsX)) continue;
        const glm::dvec2 u = matrix.Map(lsX);
        if (u.x < 0 || u.y < 0 || u.x > map.width || u.y > map.height) continue;
        nearest = std::min(nearest, ClipDepthQuantity(ls, matrix, x));
    }
    return nearest;
}

// The embedding scene's readback and the standard map of a point light and a directional one.
TEST(LightDepthRange, KeepsEveryCasterAndSpansTheReceiversTightly) {
    const testing::FloorAndBox scene = testing::EmbeddingScene();
    const Readback readback =
        RenderReadback(*MakeCpuRenderer(scene.mesh), scene.camera, scene.camera.resolution);
    const Resolution map{1024, 1024};
    std::mt19937_64 rng(8);
    for (const Light& light : {Light{Light::Type::kPoint, {10.0, 15.0, 6.0}, {}},
                               Light{Light::Type::kDirectional, {}, {-0.4, -1.0, -0.3}}}) {
        const LightSpace ls(light, scene.wsBounds);
        const LightMatrix standard = StandardLightMatrix(readback, ls, scene.wsBounds, map);
        const DepthRange range =
            LightDepthRange(ls, standard, map, scene.wsBounds, readback.wsRelevant);
        const glm::dmat4 clip = ClipFromWorld(ls, standard, map, range, ClipDepth::kZeroToOne);
        // Receivers: inside [0, 1], the farthest at 1 less the margin's share.
        const auto [receiversLo, receiversHi] = NdcDepthSpan(clip, readback.wsRelevant);
        EXPECT_GE(receiversLo, 0.0) << light.position.x;
        EXPECT_LE(receiversHi, 1.0);
        EXPECT_GT(receiversHi, 0.96);
        // Casters: every point of the bounds on a segment from a receiver toward the light.
        const double castersLo = NearestCasterNdc(ls, clip, scene.wsBounds, readback.wsRelevant);
        EXPECT_GE(castersLo, 0.0);
        // The near end is the nearest point of the bounds inside the map's frustum: no sampled
        // point of the bounds there is nearer, and some come within 2% of it.
        const double sampledNearest = SampledNearestInMap(ls, standard, map, scene.wsBounds, rng);
        const double nearest = range.near + 0.02 / 1.04 * (range.far - range.near);
        EXPECT_GE(sampledNearest, nearest * (1.0 - 1e-12));
        EXPECT_LT(sampledNearest, nearest * 1.02);
        // A guess for the point light ({0.5, 60}) squeezes the receivers.
        const DepthRange guess{0.5, 60.0};
        std::pair<double, double> guessed{1.0, 0.0};
        if (ls.IsPoint()) {
            guessed = NdcDepthSpan(ClipFromWorld(ls, standard, map, guess, ClipDepth::kZeroToOne),
                                   readback.wsRelevant);
            EXPECT_GT(receiversHi - receiversLo, 10.0 * (guessed.second - guessed.first));
        }
        std::cout << "[   INFO   ] " << (ls.IsPoint() ? "point" : "directional") << ": range {"
                  << range.near << ", " << range.far << "}, receivers at z " << receiversLo << "–"
                  << receiversHi << ", nearest caster " << castersLo << ", sampled nearest "
                  << sampledNearest / nearest << " × near; guess {0.5, 60}: " << guessed.first
                  << "–" << guessed.second << '\n';
    }
}

// The readback of a 20 × 20 floor at y = 0 seen from above, its points exactly on the plane (as a
// renderer that keeps world positions in double has them).
Readback ExactFloorReadback(Bounds* wsBounds) {
    Camera camera;
    camera.position = {0.0, 5.0, -8.0};
    camera.target = {0.0, 0.0, 0.0};
    camera.resolution = {96, 72};
    const Resolution res = camera.resolution;
    const glm::dmat4 screenFromWorld = camera.ScreenFromWorld(res);
    std::vector<float> depth(res.Count(), 1.0f);
    for (int y = 0; y < res.height; ++y)
        for (int x = 0; x < res.width; ++x) {
            const glm::dvec3 d = camera.RayDirection({x + 0.5, y + 0.5}, res);
            const glm::dvec3 p = camera.position - (camera.position.y / d.y) * d;
            if (d.y >= 0.0 || std::abs(p.x) > 10.0 || std::abs(p.z) > 10.0) continue;
            const glm::dvec4 h = screenFromWorld * glm::dvec4(p, 1.0);
            depth[static_cast<std::size_t>(y) * res.width + x] = static_cast<float>(h.z / h.w);
        }
    CameraBuffer buffer = CameraBufferFromDepth(
        DepthBuffer{res, depth, camera.ClipFromView() * camera.ViewFromWorld(), DepthConvention{}});
    for (glm::dvec3& wsPoint : buffer.wsPosition) wsPoint.y = 0.0;
    wsBounds->Add({-10.0, 0.0, -10.0});
    wsBounds->Add({10.0, 0.0, 10.0});
    return MakeReadback(std::move(buffer), screenFromWorld);
}

// A floor facing the light (the sun at noon, a lamp straight above): every receiver and every
// possible caster at one depth. Before, near = far, and ClipFromWorld's depth row divided by
// f - n = 0: NaN depth for every point, silently.
TEST(LightDepthRange, AFloorFacingTheLightGetsARangeOfItsOwn) {
    Bounds wsBounds;
    const Readback readback = ExactFloorReadback(&wsBounds);
    const Resolution map{512, 512};
    for (const Light& light : {Light{Light::Type::kDirectional, {}, {0.0, -1.0, 0.0}},
                               Light{Light::Type::kPoint, {0.0, 20.0, 0.0}, {}}}) {
        const LightSpace ls(light, wsBounds);
        const LightMatrix standard = StandardLightMatrix(readback, ls, wsBounds, map);
        const DepthRange range = LightDepthRange(ls, standard, map, wsBounds, readback.wsRelevant);
        const double depth = ClipDepthQuantity(ls, standard, readback.wsRelevant.front());
        // At least 1e-3 of the depth (so that float rounding of the points stays inside), and
        // no more.
        EXPECT_GE(range.far - range.near, 1e-3 * depth * (1.0 - 1e-9)) << light.position.y;
        EXPECT_LE(range.far - range.near, 1.05e-3 * depth) << light.position.y;
        EXPECT_GT(range.near, 0.0);
        const glm::dmat4 clip = ClipFromWorld(ls, standard, map, range, ClipDepth::kZeroToOne);
        std::size_t outside = 0;
        for (const glm::dvec3& ws : readback.wsRelevant) {
            const glm::dvec4 h = clip * glm::dvec4(ws, 1.0);
            outside += !(h.z / h.w > 0.0 && h.z / h.w < 1.0);  // NaN counts
        }
        EXPECT_EQ(outside, 0u) << "of " << readback.wsRelevant.size() << " receivers at NDC z "
                               << "outside (0, 1), range {" << range.near << ", " << range.far
                               << "}";
    }
}

TEST(LightDepthRange, RefusesNoReceivers) {
    const Bounds wsBounds = SceneBounds();
    const LightSpace ls(Light{Light::Type::kPoint, {30.0, 40.0, 20.0}, {}}, wsBounds);
    EXPECT_THROW(LightDepthRange(ls, LightMatrix{}, {64, 64}, wsBounds, {}), std::invalid_argument);
}

// A matrix's |p4| = 1 form with p4 · X > 0 at the bounds' centre (what FromScreenRows returns).
LightMatrix Normalized(const LightMatrix& m, const LightSpace& ls, const Bounds& wsBounds) {
    double norm = glm::length(m.p4);
    if (glm::dot(m.p4, ls.ToLight(wsBounds.Center())) < 0.0) norm = -norm;
    return {m.p1 / norm, m.p2 / norm, m.p4 / norm};
}

TEST(LightMatrixFromClip, InvertsClipFromWorldInBothConventions) {
    const Bounds wsBounds = SceneBounds();
    const Light point{Light::Type::kPoint, {30.0, 40.0, 20.0}, {}};
    const Light sun{Light::Type::kDirectional, {}, glm::normalize(glm::dvec3(-0.3, -1.0, 0.2))};
    const Resolution map{512, 256};
    for (const Light& light : {point, sun})
        for (double tilt : {0.0, 0.2})
            for (ClipDepth convention : {ClipDepth::kMinusOneToOne, ClipDepth::kZeroToOne}) {
                const LightSpace ls(light, wsBounds);
                // Scaled by 3 (not |p4| = 1) and with a depth range of any kind: both drop out.
                LightMatrix m = SomeMatrix(ls, wsBounds, tilt);
                m = {3.0 * m.p1, 3.0 * m.p2, 3.0 * m.p4};
                const glm::dmat4 clip = ClipFromWorld(ls, m, map, {2.0, 90.0}, convention);
                std::string failure;
                const std::optional<LightMatrix> back =
                    LightMatrixFromClip(ls, clip, map, wsBounds.Center(), &failure);
                ASSERT_TRUE(back) << failure;
                const LightMatrix expected = Normalized(m, ls, wsBounds);
                for (int i = 0; i < 3; ++i) {
                    EXPECT_NEAR(back->p1[i], expected.p1[i], 1e-12 * glm::length(expected.p1));
                    EXPECT_NEAR(back->p2[i], expected.p2[i], 1e-12 * glm::length(expected.p2));
                    EXPECT_NEAR(back->p4[i], expected.p4[i], 1e-15);
                }
                // And back again: the clip matrix's x, y, w rows to rounding.
                const glm::dmat4 again = ClipFromWorld(ls, *back, map, {2.0, 90.0}, convention);
                const double scale = clip[3][3] / again[3][3];  // |p4| 3 became 1
                for (int c = 0; c < 4; ++c)
                    for (int r : {0, 1, 3})
                        EXPECT_NEAR(scale * again[c][r], clip[c][r], 1e-12 * glm::length(clip[c]))
                            << "row " << r << " column " << c;
            }
}

TEST(LightMatrixFromClip, RefusesAMatrixThatDoesNotProjectFromTheLight) {
    const Bounds wsBounds = SceneBounds();
    const Light point{Light::Type::kPoint, {30.0, 40.0, 20.0}, {}};
    const Light sun{Light::Type::kDirectional, {}, glm::normalize(glm::dvec3(-0.3, -1.0, 0.2))};
    for (const Light& light : {point, sun}) {
        const LightSpace ls(light, wsBounds);
        std::string failure;
        // The identity: clip x, y, w are world x, y and 1, none of which vanish at the light.
        EXPECT_FALSE(
            LightMatrixFromClip(ls, glm::dmat4(1.0), {64, 64}, wsBounds.Center(), &failure));
        EXPECT_NE(failure.find("does not send the"), std::string::npos) << failure;
        // A matrix for another light of the same kind is refused too.
        const Light other = light.type == Light::Type::kPoint
                                ? Light{Light::Type::kPoint, {-30.0, 40.0, 20.0}, {}}
                                : Light{Light::Type::kDirectional, {}, {0.0, -1.0, 0.0}};
        const LightSpace otherSpace(other, wsBounds);
        const glm::dmat4 clip = ClipFromWorld(otherSpace, SomeMatrix(otherSpace, wsBounds, 0.1),
                                              {64, 64}, {1.0, 90.0}, ClipDepth::kMinusOneToOne);
        EXPECT_FALSE(LightMatrixFromClip(ls, clip, {64, 64}, wsBounds.Center()));
    }
}

}  // namespace
}  // namespace lexel::spatial
