// The light matrix as a rasterizer's 4×4: texel coordinates through the clip matrix equal the
// light matrix's map, and depth spans the requested range in both conventions.
#include "lexel/spatial/clip_matrix.h"

#include <gtest/gtest.h>

#include <random>

namespace lexel::spatial {
namespace {

struct ClipCase {
    Light light;
    LightMatrix matrix;
};

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

}  // namespace
}  // namespace lexel::spatial
