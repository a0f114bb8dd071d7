// The optimization samples and the energy h of eq. (6): boundary samples on the analytic shadow
// edge, h against a hand-computed sample, the bounded search energy against Energy.
#include "lexel/spatial/samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <random>
#include <set>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/convex_hull.h"
#include "lexel/solvers/convex_hull_3d.h"
#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

TEST(Energy, SampleBadnessIsTheInverseJacobianFrobeniusNorm) {
    // u = (2 X1/X3, 3 X2/X3) with X = (x¹, x², 1) + small depth: J = diag(2, 3) at X3 = 1, so
    // ||J⁻¹||² = 1/4 + 1/9.
    LightMatrix m;
    m.p1 = {2, 0, 0};
    m.p2 = {0, 3, 0};
    m.p4 = {0, 0, 1};
    const glm::dvec3 lsX(0.3, -0.2, 1.0), dX1(1, 0, 0), dX2(0, 1, 0);
    EXPECT_NEAR(SampleBadness(m, lsX, dX1, dX2), 1.0 / 4 + 1.0 / 9, 1e-15);
    // Behind the light's plane: unbounded, never NaN.
    EXPECT_TRUE(std::isinf(SampleBadness(m, {0.3, 0.2, -1.0}, dX1, dX2)));
    // A sample whose screen directions are parallel in the map: singular J, +inf.
    EXPECT_TRUE(std::isinf(SampleBadness(m, lsX, dX1, dX1)));
    LightSamples s;
    s.lsX = {lsX, lsX};
    s.dXdx1 = {dX1, 2.0 * dX1};
    s.dXdx2 = {dX2, dX2};
    EXPECT_NEAR(Energy(m, s), (1.0 / 4 + 1.0 / 9) + (1.0 / 16 + 1.0 / 9), 1e-15);
}

TEST(LightSamples, BoundarySamplesSitOnTheShadowEdge) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    Light light;
    light.position = {-20.0, 30.0, -10.0};
    const Bounds bounds = scene.ComputeBounds();
    const LightSpace ls(light, bounds);
    const LightSamples s = testing::SamplesFromBoundsMap(*renderer, rb, ls, bounds, {1024, 1024});
    ASSERT_GT(s.lsX.size(), 50u);
    EXPECT_EQ(s.lsRelevant.size(), rb.wsRelevant.size());
    // Every boundary sample on the floor is within a few readback pixels' footprint of the
    // analytic shadow edge: the segment to the light grazes the box.
    for (std::size_t k = 0; k < s.lsX.size(); ++k) {
        const std::size_t i = s.pixel[k];
        const glm::dvec3 ws = rb.buffer.wsPosition[i];
        if (std::abs(ws.y) > 1e-9) continue;
        const double step = 2.0 * std::max(glm::length(rb.dWdx1[i]), glm::length(rb.dWdx2[i]));
        bool mixed = false;
        const bool here = testing::SegmentHitsBox(ws, light.position, {-1, 0, -1}, {1, 1.5, 1});
        for (const glm::dvec3 d : {glm::dvec3(step, 0, 0), glm::dvec3(-step, 0, 0),
                                   glm::dvec3(0, 0, step), glm::dvec3(0, 0, -step)})
            mixed = mixed || testing::SegmentHitsBox(ws + d, light.position, {-1, 0, -1},
                                                     {1, 1.5, 1}) != here;
        EXPECT_TRUE(mixed) << "sample at " << ws.x << "," << ws.z;
    }
}
TEST(LightSamples, EdgeNormalsPointFromLitToShadowed) {
    // On the floor, two readback pixels along the edge normal from a sample is in the box's
    // analytic shadow and two pixels against it is lit (screen steps through ∂W/∂x^j).
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    Light light;
    light.position = {-20.0, 30.0, -10.0};
    const Bounds bounds = scene.ComputeBounds();
    const LightSpace ls(light, bounds);
    const LightSamples s = testing::SamplesFromBoundsMap(*renderer, rb, ls, bounds, {1024, 1024});
    ASSERT_EQ(s.edgeNormal.size(), s.lsX.size());
    int checked = 0, agree = 0, undefined = 0;
    for (std::size_t k = 0; k < s.lsX.size(); ++k) {
        const glm::dvec2 n = s.edgeNormal[k];
        if (n == glm::dvec2(0.0)) {
            ++undefined;
            continue;
        }
        EXPECT_NEAR(glm::length(n), 1.0, 1e-15);
        const std::size_t i = s.pixel[k];
        const glm::dvec3 ws = rb.buffer.wsPosition[i];
        if (std::abs(ws.y) > 1e-9) continue;
        const glm::dvec3 step = 2.0 * (n.x * rb.dWdx1[i] + n.y * rb.dWdx2[i]);
        ++checked;
        agree += testing::SegmentHitsBox(ws + step, light.position, {-1, 0, -1}, {1, 1.5, 1}) &&
                 !testing::SegmentHitsBox(ws - step, light.position, {-1, 0, -1}, {1, 1.5, 1});
    }
    ASSERT_GT(checked, 50);
    EXPECT_GE(agree, 0.9 * checked) << agree << " of " << checked;
    EXPECT_LT(undefined, 0.05 * double(s.lsX.size()));
    // The prior's points: lit or shadowed smooth receivers, at most kPriorPoints, in light space.
    ASSERT_FALSE(s.lsPrior.empty());
    EXPECT_LE(s.lsPrior.size(), kPriorPoints);
    EXPECT_EQ(s.priorDXdx1.size(), s.lsPrior.size());
    EXPECT_EQ(s.wsPrior.size(), s.lsPrior.size());
    for (std::size_t k = 0; k < s.lsPrior.size(); ++k)
        EXPECT_LT(glm::length(ls.ToLight(s.wsPrior[k]) - s.lsPrior[k]), 1e-12);
    // The same pixels without the shades: no normals, the prior over every smooth pixel.
    const LightSamples bare = LightSamplesAtPixels(rb, ls, s.pixel);
    EXPECT_TRUE(bare.edgeNormal.empty());
    EXPECT_EQ(bare.lsX, s.lsX);
    EXPECT_FALSE(bare.lsPrior.empty());
}

TEST(ThinShadowWidth, IsTheCastShadowsWidthPerUnitOfItsCaster) {
    // Brute force: random caster and receiver planes through the z axis and random directions to
    // the light; the caster's point t·a (a ⊥ the line, in the caster's plane) is projected along
    // the light onto the receiver's plane, and its distance from the contact line there is
    // t·ThinShadowWidth for every dihedral angle.
    std::mt19937_64 rng(25);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), uni(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const double alpha = angle(rng), beta = angle(rng), t = 0.5 + std::abs(uni(rng));
        const glm::dvec3 a(std::cos(alpha), std::sin(alpha), 0.0);  // in the caster's plane
        const glm::dvec3 b(std::cos(beta), std::sin(beta), 0.0);    // in the receiver's plane
        const glm::dvec3 nCaster(-a.y, a.x, 0.0), nReceiver(-b.y, b.x, 0.0);
        const glm::dvec3 toLight = glm::normalize(glm::dvec3(uni(rng), uni(rng), uni(rng)));
        if (std::abs(glm::dot(nReceiver, toLight)) < 0.05) continue;  // nearly grazing
        const glm::dvec3 caster = t * a;
        const glm::dvec3 shadow =
            caster - glm::dot(nReceiver, caster) / glm::dot(nReceiver, toLight) * toLight;
        ASSERT_NEAR(glm::dot(nReceiver, shadow), 0.0, 1e-12);
        const double fromLine = std::hypot(shadow.x, shadow.y);  // the line is the z axis
        EXPECT_NEAR(fromLine, t * ThinShadowWidth(nCaster, nReceiver, toLight),
                    1e-9 * (1 + fromLine))
            << "trial " << trial << ": alpha " << alpha << ", beta " << beta;
    }
    // A wall and the floor: the shadow is |l_x| / l_y wide per unit of wall height.
    EXPECT_DOUBLE_EQ(ThinShadowWidth({1, 0, 0}, {0, 1, 0}, glm::normalize(glm::dvec3(0.1, 1, 0))),
                     0.1);
}

TEST(ThinShadowContacts, LieAtTheFootOfAWallTheLightGrazes) {
    // A box on a floor, its +z face (seen by the camera) facing away from a directional light
    // that grazes it: |n·l| / (floor's n·l) = 0.05 / 0.8 < kThinShadowRatio. The contacts are
    // floor pixels in shadow beside that face's foot (z = 1); tilting the light away from the
    // face (ratio 0.5) leaves none, as does a light the face is turned to.
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    Camera camera;
    camera.position = {0.3, 1.2, 4.0};
    camera.target = {0.0, 0.3, 1.0};
    camera.resolution = {180, 180};
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    const Bounds bounds = scene.ComputeBounds();
    const auto contactsFor = [&](const glm::dvec3& toLight) {
        Light light;
        light.type = Light::Type::kDirectional;
        light.direction = -glm::normalize(toLight);
        const LightSpace ls(light, bounds);
        std::vector<glm::dvec3> corners;
        for (const glm::dvec3& c : bounds.Corners()) corners.push_back(ls.ToLight(c));
        const ShadowMap map = renderer->RenderShadowMap(
            ls, *FitMapToPoints({0, 0, 1}, corners, {2048, 2048}), {2048, 2048});
        const std::vector<Shade> shades = renderer->ShadePixels(rb.buffer, ls, map);
        const LightSamples samples = MakeLightSamples(rb, ls, shades);
        const std::vector<std::uint32_t> contacts = ThinShadowContacts(rb, ls, shades);
        // The samples: the boundary pixels, then the contacts that are not, normal (0, 0).
        const std::vector<std::uint32_t> boundary = BoundaryPixels(rb.buffer.resolution, shades);
        std::size_t extra = 0;
        for (const std::uint32_t p : contacts)
            extra += !std::binary_search(boundary.begin(), boundary.end(), p);
        EXPECT_EQ(samples.contactSamples, extra);
        for (std::size_t k = samples.lsX.size() - samples.contactSamples; k < samples.lsX.size();
             ++k)
            EXPECT_EQ(samples.edgeNormal[k], glm::dvec2(0.0));
        return contacts;
    };
    const std::vector<std::uint32_t> grazing = contactsFor({0.6, 0.8, -0.05});
    ASSERT_GT(grazing.size(), 10u);
    for (const std::uint32_t p : grazing) {
        const glm::dvec3 ws = rb.buffer.wsPosition[p];
        const double reach = 3.0 * std::max(glm::length(rb.dWdx1[p]), glm::length(rb.dWdx2[p]));
        EXPECT_NEAR(ws.y, 0.0, 1e-9) << "pixel " << p;  // on the floor
        EXPECT_GE(ws.z, 1.0 - 1e-9) << "pixel " << p;   // in front of the face
        EXPECT_LE(ws.z, 1.0 + reach) << "pixel " << p;  // at its foot
        EXPECT_LE(std::abs(ws.x), 1.0 + reach) << "pixel " << p;
    }
    EXPECT_TRUE(contactsFor({0.6, 0.8, -0.4}).empty());  // ratio 0.5: a wide shadow
    EXPECT_TRUE(contactsFor({0.6, 0.8, 0.05}).empty());  // the face is lit at a graze
}

// Ten samples on pixels 100..109, distinguishable by their x (sample i has i in every array).
LightSamples TenSamples() {
    LightSamples s;
    for (int i = 0; i < 10; ++i) {
        s.lsX.push_back({double(i), 0.0, 1.0});
        s.dXdx1.push_back({1.0, double(i), 0.0});
        s.dXdx2.push_back({0.0, 1.0, double(i)});
        s.pixel.push_back(static_cast<std::uint32_t>(100 + i));
        s.wsX.push_back({double(i), 1.0, 2.0});
        s.edgeNormal.push_back({double(i), 1.0});
    }
    return s;
}

TEST(ThinSamples, KeepsTheLeastPrioritiesInOrderAndEverythingElse) {
    // TenSamples' SplitMix64 priorities by hand, in units of 10¹⁸: 2.533, 15.06, 1.243, 1.867,
    // 5.150, 13.52, 2.476, 2.523, 14.78, 12.91. A budget of 4 keeps the four least (102, 103,
    // 106, 107) in their order; of 5 adds 100.
    LightSamples s = TenSamples();
    s.lsRelevant = {{1, 2, 3}, {4, 5, 6}};
    s.lsPrior = {{7, 8, 9}};
    s.boundaryPixels = 12;
    s.contactSamples = 4;  // samples 6..9 are thin-shadow contacts
    // SplitMix64's first output from seed 0 (the published reference value), and pixel 106's.
    EXPECT_EQ(ThinningPriority(0), 0xE220A8397B1DCDAFull);
    EXPECT_EQ(ThinningPriority(106), 2475505609494469522ull);
    const LightSamples t = ThinSamples(s, 4);
    ASSERT_EQ(t.lsX.size(), 4u);
    const int kept[] = {2, 3, 6, 7};
    for (std::size_t k = 0; k < 4; ++k) {
        const double i = kept[k];
        EXPECT_EQ(t.lsX[k].x, i);
        EXPECT_EQ(t.dXdx1[k].y, i);
        EXPECT_EQ(t.dXdx2[k].z, i);
        EXPECT_EQ(t.pixel[k], 100u + kept[k]);
        EXPECT_EQ(t.wsX[k].x, i);
        EXPECT_EQ(t.edgeNormal[k].x, i);
    }
    EXPECT_EQ(t.lsRelevant, s.lsRelevant);
    EXPECT_EQ(t.lsPrior, s.lsPrior);
    EXPECT_EQ(t.boundaryPixels, 12u);
    EXPECT_EQ(t.contactSamples, 2u);  // 6 and 7 are kept
    // The report's samples: the six before the contacts, everything else as it is.
    const LightSamples published = PublishedSamples(s);
    EXPECT_EQ(published.pixel, (std::vector<std::uint32_t>{100, 101, 102, 103, 104, 105}));
    EXPECT_EQ(published.contactSamples, 0u);
    EXPECT_EQ(published.edgeNormal.size(), 6u);
    EXPECT_EQ(published.lsPrior, s.lsPrior);
    EXPECT_EQ(ThinSamples(s, 5).pixel, (std::vector<std::uint32_t>{100, 102, 103, 106, 107}));
    EXPECT_EQ(ThinSamples(s, 0).lsX, s.lsX);
    EXPECT_EQ(ThinSamples(s, 10).lsX, s.lsX);
    EXPECT_EQ(ThinSamples(s, 1).pixel, std::vector<std::uint32_t>{102});
    // Samples made by hand without normals or pixels keep those empty (priorities by index).
    LightSamples bare = s;
    bare.edgeNormal.clear();
    bare.pixel.clear();
    const LightSamples b = ThinSamples(bare, 4);
    EXPECT_EQ(b.lsX.size(), 4u);
    EXPECT_TRUE(b.edgeNormal.empty());
    EXPECT_TRUE(b.pixel.empty());
}

TEST(ThinSamples, ForSearchKeepsTheSameSamplesAndOfTheRelevantPointsTheHull) {
    LightSamples s = TenSamples();
    s.lsRelevant = {{1, 2, 3}, {4, 5, 6}, {2, 3, 4}};
    s.lsRelevantHull = {{1, 2, 3}, {4, 5, 6}};
    s.lsPrior = {{7, 8, 9}};
    s.priorDXdx1 = {{1, 0, 0}};
    s.priorDXdx2 = {{0, 1, 0}};
    s.wsPrior = {{3, 2, 1}};
    s.boundaryPixels = 12;
    for (const std::size_t budget : {4u, 10u}) {
        const LightSamples t = ThinSamples(s, budget), u = ThinSamplesForSearch(s, budget);
        EXPECT_EQ(u.lsX, t.lsX);
        EXPECT_EQ(u.dXdx1, t.dXdx1);
        EXPECT_EQ(u.dXdx2, t.dXdx2);
        EXPECT_EQ(u.pixel, t.pixel);
        EXPECT_EQ(u.wsX, t.wsX);
        EXPECT_EQ(u.edgeNormal, t.edgeNormal);
        EXPECT_EQ(u.lsRelevant, s.lsRelevantHull);  // the cone's generators only
        EXPECT_EQ(u.lsRelevantHull, s.lsRelevantHull);
        EXPECT_EQ(u.lsPrior, s.lsPrior);
        EXPECT_EQ(u.priorDXdx1, s.priorDXdx1);
        EXPECT_EQ(u.priorDXdx2, s.priorDXdx2);
        EXPECT_EQ(u.wsPrior, s.wsPrior);
        EXPECT_EQ(u.boundaryPixels, 12u);
    }
    // Without a hull (samples made by hand) the relevant points stay whole.
    s.lsRelevantHull.clear();
    EXPECT_EQ(ThinSamplesForSearch(s, 4).lsRelevant, s.lsRelevant);
}

// The pixels ThinSamples keeps of samples on `pixels` (ascending).
std::vector<std::uint32_t> KeptPixels(const std::vector<std::uint32_t>& pixels,
                                      std::size_t budget) {
    LightSamples s;
    for (const std::uint32_t p : pixels) {
        s.lsX.push_back({double(p), 0.0, 1.0});
        s.pixel.push_back(p);
    }
    return ThinSamples(s, budget).pixel;
}

TEST(ThinSamples, OneBoundaryPixelLessChangesAtMostTwoKeptSamples) {
    // Seeded boundaries on a 720² readback (about 5,200 pixels; the walkthrough's lights have
    // 3,500-13,600), budget 512: dropping one pixel (a GPU readback against the CPU's) swaps at
    // most one kept sample for another. Every k-th sample in pixel order, the thinning before,
    // changed hundreds when the pixel lay in the first half: the stride check shows this input
    // would catch it.
    constexpr std::uint32_t kPixels = 720 * 720;
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937 rng(seed);
        std::vector<std::uint32_t> pixels;
        for (std::uint32_t p = 0; p < kPixels; ++p)
            if (rng() % 100 == 0) pixels.push_back(p);
        const std::size_t drop = rng() % (pixels.size() / 2);
        std::vector<std::uint32_t> fewer = pixels;
        fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(drop));
        const std::vector<std::uint32_t> a = KeptPixels(pixels, 512);
        const std::vector<std::uint32_t> b = KeptPixels(fewer, 512);
        EXPECT_EQ(a.size(), 512u);
        std::vector<std::uint32_t> differ;
        std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(),
                                      std::back_inserter(differ));
        EXPECT_LE(differ.size(), 2u) << "seed " << seed << ", " << pixels.size()
                                     << " pixels, dropped pixel " << pixels[drop];
        std::vector<std::uint32_t> strideA, strideB, strideDiffer;
        const std::size_t k = (pixels.size() + 511) / 512;
        for (std::size_t i = 0; i < pixels.size(); i += k) strideA.push_back(pixels[i]);
        for (std::size_t i = 0; i < fewer.size(); i += k) strideB.push_back(fewer[i]);
        std::set_symmetric_difference(strideA.begin(), strideA.end(), strideB.begin(),
                                      strideB.end(), std::back_inserter(strideDiffer));
        EXPECT_GT(strideDiffer.size(), 100u) << "seed " << seed;
    }
}

TEST(ThinSamples, FavoursNoEdgeDirection) {
    // Two straight edges of 150 boundary pixels each on a 720² readback, one along a row and one
    // at every whole degree, thinned to 60: the angled edge keeps between a quarter and three
    // quarters of them at every angle (measured 30–52%). A priority with a lattice structure
    // (frac(column/g + row/g²), tried) keeps all or none of an edge along its level lines.
    constexpr std::uint32_t kWidth = 720;
    std::vector<std::uint32_t> row;
    for (std::uint32_t i = 0; i < 150; ++i) row.push_back(100 * kWidth + 200 + i);
    for (int degrees = 0; degrees < 180; ++degrees) {
        const double angle = glm::radians(static_cast<double>(degrees));
        std::vector<std::uint32_t> edge;
        for (double t = 0.0; edge.size() < 150; t += 0.25) {
            const auto column = static_cast<std::uint32_t>(std::lround(360 + t * std::cos(angle)));
            const auto r = static_cast<std::uint32_t>(std::lround(360 + t * std::sin(angle)));
            if (edge.empty() || edge.back() != r * kWidth + column)
                edge.push_back(r * kWidth + column);
        }
        std::vector<std::uint32_t> pixels = row;
        pixels.insert(pixels.end(), edge.begin(), edge.end());
        std::sort(pixels.begin(), pixels.end());
        pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
        const std::vector<std::uint32_t> kept = KeptPixels(pixels, 60);
        const auto onEdge = std::count_if(kept.begin(), kept.end(), [&](std::uint32_t p) {
            return std::find(edge.begin(), edge.end(), p) != edge.end();
        });
        EXPECT_GE(onEdge, 15) << degrees << "°";
        EXPECT_LE(onEdge, 45) << degrees << "°";
    }
}

TEST(BoundedEnergy, EqualsEnergyBitForBitBelowTheBound) {
    TriangleMesh scene = testing::FloorQuad(30.0);
    scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    const auto renderer = MakeCpuRenderer(scene);
    const Camera camera = testing::ReadbackCamera();
    const Readback rb = RenderReadback(*renderer, camera, camera.resolution);
    Light light;
    light.position = {-20.0, 30.0, -10.0};
    const LightSpace ls(light, scene.ComputeBounds());
    const Resolution mapRes{400, 400};
    const LightSamples s =
        testing::SamplesFromBoundsMap(*renderer, rb, ls, scene.ComputeBounds(), mapRes);
    ASSERT_GT(s.lsX.size(), 130u);  // more than two blocks of 64
    const BoundedEnergy energy(s);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> uni(-1.0, 1.0);
    int finite = 0, behind = 0;
    for (int k = 0; k < 200; ++k) {
        // Random light matrices, some with a sample not in front of p4 (h = +inf).
        LightMatrix m;
        m.p4 = glm::normalize(glm::dvec3(uni(rng), uni(rng), 1.0));
        if (k % 5 == 0)  // one sample on the plane p4·X = 0: not in front
            m.p4 = glm::normalize(glm::cross(s.lsX[(k * 7) % s.lsX.size()], m.p4));
        m.p1 = glm::dvec3(uni(rng), uni(rng), uni(rng)) + 200.0 * m.p4;
        m.p2 = glm::dvec3(uni(rng), uni(rng), uni(rng)) + 200.0 * m.p4;
        const double h = Energy(m, s);
        EXPECT_EQ(energy(m), h) << "k " << k;  // the same bits
        if (std::isinf(h)) {
            ++behind;
            EXPECT_GE(energy(m, 1.0), 1.0);  // may stop before the sample that is not in front
            continue;
        }
        ++finite;
        EXPECT_EQ(energy(m, std::nextafter(h, 2.0 * h)), h);  // just above: the full sum
        for (double fraction : {0.999999, 0.5, 1e-3}) {
            const double bound = fraction * h;
            const double partial = energy(m, bound);
            EXPECT_GE(partial, bound);  // stopped at the bound, never below it
            EXPECT_LE(partial, h);
        }
        EXPECT_GE(energy(m, h), h);
    }
    EXPECT_GT(finite, 50);
    EXPECT_GT(behind, 5);
}

}  // namespace
}  // namespace lexel::spatial
