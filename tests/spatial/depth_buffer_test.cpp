// A renderer's depth buffer in every convention engines use (before: a reversed-Z buffer was
// read as a standard one, and Vulkan/Direct3D conventions were not covered): each gives the world
// points of the exact camera pass to float precision, a convention that contradicts its
// projection is refused, and DownsampleDepth keeps exactly the source pixels' points.
#include "lexel/spatial/depth_buffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "spatial/spatial_test_scenes.h"

namespace lexel::spatial {
namespace {

// A projection and the convention a renderer declares with it.
struct Convention {
    const char* name;
    DepthConvention convention;
    glm::dmat4 clipFromView;
    bool rowsFlipped;  // memory row r holds the image's row H - 1 - r (image row 0 at the top)
};

std::vector<Convention> Conventions(const Camera& camera) {
    const double fovY = glm::radians(camera.fovYDeg), aspect = camera.AspectRatio();
    const double n = camera.nearPlane, f = camera.farPlane;
    const glm::dmat4 gl = glm::perspectiveRH_NO(fovY, aspect, n, f);
    const glm::dmat4 zeroToOne = glm::perspectiveRH_ZO(fovY, aspect, n, f);
    glm::dmat4 reversed = zeroToOne;  // z' = w - z: z_ndc' = 1 - z_ndc
    for (int c = 0; c < 4; ++c) reversed[c][2] = zeroToOne[c][3] - zeroToOne[c][2];
    glm::dmat4 reversedInfinite = zeroToOne;  // z_ndc = n / z_view: 1 at the near plane, 0 at ∞
    reversedInfinite[2][2] = 0.0;
    reversedInfinite[3][2] = n;
    glm::dmat4 reversedGl = gl;  // z_ndc' = -z_ndc
    for (int c = 0; c < 4; ++c) reversedGl[c][2] = -gl[c][2];
    glm::dmat4 vulkan = reversedInfinite;  // NDC y down
    for (int c = 0; c < 4; ++c) vulkan[c][1] = -vulkan[c][1];
    using enum ClipDepth;
    using enum DepthDirection;
    using enum FirstRow;
    return {
        {"OpenGL", {kMinusOneToOne, kStandard, kAtNdcYPlusOne}, gl, false},
        {"OpenGL, glReadPixels rows", {kMinusOneToOne, kStandard, kAtNdcYMinusOne}, gl, true},
        {"OpenGL reversed-Z", {kMinusOneToOne, kReversed, kAtNdcYPlusOne}, reversedGl, false},
        {"Direct3D", {kZeroToOne, kStandard, kAtNdcYPlusOne}, zeroToOne, false},
        {"Direct3D reversed-Z", {kZeroToOne, kReversed, kAtNdcYPlusOne}, reversed, false},
        {"reversed-Z, infinite far",
         {kZeroToOne, kReversed, kAtNdcYPlusOne},
         reversedInfinite,
         false},
        {"Vulkan reversed-Z, infinite far",
         {kZeroToOne, kReversed, kAtNdcYMinusOne},
         vulkan,
         false},
        {"glClipControl reversed-Z, glReadPixels rows",
         {kZeroToOne, kReversed, kAtNdcYMinusOne},
         reversed,
         true},
    };
}

// The stored depth of the exact pass's points under one convention, in its memory order.
std::vector<float> StoredDepth(const CameraBuffer& exact, const glm::dmat4& clipFromWorld,
                               const Convention& c) {
    const Resolution r = exact.resolution;
    const float cleared = c.convention.direction == DepthDirection::kReversed ? 0.0f : 1.0f;
    std::vector<float> depth(r.Count(), cleared);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * r.width + x;
            if (!exact.Covered(i)) continue;
            const glm::dvec4 h = clipFromWorld * glm::dvec4(exact.wsPosition[i], 1.0);
            const double zNdc = h.z / h.w;
            const double stored =
                c.convention.clipDepth == ClipDepth::kZeroToOne ? zNdc : 0.5 * (zNdc + 1.0);
            const int row = c.rowsFlipped ? r.height - 1 - y : y;
            depth[static_cast<std::size_t>(row) * r.width + x] = static_cast<float>(stored);
        }
    return depth;
}

struct Pass {
    TriangleMesh scene;
    Camera camera;
    CameraBuffer exact;
};

Pass FloorAndBox(Resolution resolution) {
    Pass p;
    p.scene = testing::FloorQuad(30.0);
    p.scene.Append(testing::BoxMesh({-1.0, 0.0, -1.0}, {1.0, 1.5, 1.0}));
    p.camera = testing::ReadbackCamera();
    p.camera.resolution = resolution;
    p.exact = MakeCpuRenderer(p.scene)->RenderCamera(p.camera, resolution);
    return p;
}

TEST(DepthBuffer, EveryConventionGivesTheExactPassesPoints) {
    const Pass pass = FloorAndBox({160, 120});
    const Resolution r = pass.camera.resolution;
    const Readback exactReadback = MakeReadback(pass.exact, pass.camera.ScreenFromWorld(r));
    for (const Convention& c : Conventions(pass.camera)) {
        const glm::dmat4 clipFromWorld = c.clipFromView * pass.camera.ViewFromWorld();
        const std::vector<float> depth = StoredDepth(pass.exact, clipFromWorld, c);
        const DepthBuffer buffer{r, depth, clipFromWorld, c.convention};
        const Readback readback = MakeReadback(buffer);
        double worst = 0.0;
        std::size_t smooth = 0, exactSmooth = 0;
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * r.width + x;
                const int row = c.rowsFlipped ? r.height - 1 - y : y;
                const std::size_t m = static_cast<std::size_t>(row) * r.width + x;
                ASSERT_EQ(readback.buffer.Covered(m), pass.exact.Covered(i))
                    << c.name << ", pixel " << x << "," << y;
                if (!pass.exact.Covered(i)) continue;
                const glm::dvec3& ws = pass.exact.wsPosition[i];
                worst = std::max(worst, glm::length(readback.buffer.wsPosition[m] - ws) /
                                            glm::length(ws - pass.camera.position));
                smooth += readback.smooth[m];
                exactSmooth += exactReadback.smooth[i];
            }
        // Float depth: ~6e-8 relative, amplified near the far end of a standard depth range
        // (observed 6.6e-6 for OpenGL's; reversed-Z keeps float's relative precision).
        const bool reversed = c.convention.direction == DepthDirection::kReversed;
        EXPECT_LT(worst, reversed ? 1e-6 : 5e-5) << c.name;
        EXPECT_GT(smooth, 0.95 * exactSmooth) << c.name;
        EXPECT_EQ(readback.wsRelevant.size(), exactReadback.wsRelevant.size()) << c.name;
        std::cout << "[   INFO   ] " << c.name << ": worst point " << worst << ", smooth " << smooth
                  << " of " << exactSmooth << '\n';
    }
}

// Reversed-Z buffers "failed": read as standard ones, their cleared 0 is the near plane.
TEST(DepthBuffer, AConventionThatContradictsItsProjectionIsRefused) {
    const Pass pass = FloorAndBox({64, 48});
    for (const Convention& c : Conventions(pass.camera)) {
        const glm::dmat4 clipFromWorld = c.clipFromView * pass.camera.ViewFromWorld();
        const std::vector<float> depth = StoredDepth(pass.exact, clipFromWorld, c);
        DepthBuffer wrong{pass.camera.resolution, depth, clipFromWorld, c.convention};
        const bool reversed = c.convention.direction == DepthDirection::kReversed;
        wrong.convention.direction =
            reversed ? DepthDirection::kStandard : DepthDirection::kReversed;
        try {
            CameraBufferFromDepth(wrong);
            ADD_FAILURE() << c.name << ": accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(reversed ? "use kReversed" : "use kStandard"),
                      std::string::npos)
                << e.what();
        }
    }
    const std::vector<float> few(10, 0.5f);
    EXPECT_THROW(CameraBufferFromDepth(DepthBuffer{
                     .resolution = pass.camera.resolution, .depth = few, .convention = {}}),
                 std::invalid_argument);
    const std::vector<float> depth(pass.camera.resolution.Count(), 0.5f);
    EXPECT_THROW(CameraBufferFromDepth(DepthBuffer{.resolution = pass.camera.resolution,
                                                   .depth = depth,
                                                   .clipFromWorld = glm::dmat4(0.0),
                                                   .convention = {}}),
                 std::invalid_argument);
}

// The default convention with a Camera's matrices is Camera::ScreenFromWorld.
TEST(DepthBuffer, DefaultConventionIsTheCamerasScreenFromWorld) {
    const Camera camera = FloorAndBox({16, 9}).camera;
    const DepthBuffer buffer{.resolution = camera.resolution,
                             .depth = {},
                             .clipFromWorld = camera.ClipFromView() * camera.ViewFromWorld(),
                             .convention = {}};
    const glm::dmat4 a = ScreenFromWorld(buffer), b = camera.ScreenFromWorld(camera.resolution);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], 1e-12 * (1.0 + std::abs(b[c][r])));
}

// Every sample of the small image is its source pixel: the same stored depth, and the exact
// point of the source pixel lands on the small pixel's centre under the small image's Q.
void ExpectDownsamplingKeepsTheSourcePoints(Resolution source, int maxSide, Resolution expected,
                                            int expectedStep) {
    const Pass pass = FloorAndBox(source);
    for (const Convention& c : Conventions(pass.camera)) {
        const glm::dmat4 clipFromWorld = c.clipFromView * pass.camera.ViewFromWorld();
        const std::vector<float> depth = StoredDepth(pass.exact, clipFromWorld, c);
        const DepthImage small =
            DownsampleDepth(DepthBuffer{source, depth, clipFromWorld, c.convention}, maxSide);
        ASSERT_EQ(small.resolution.width, expected.width) << c.name;
        ASSERT_EQ(small.resolution.height, expected.height) << c.name;
        ASSERT_EQ(small.step, expectedStep);
        const glm::dmat4 screenFromWorld = ScreenFromWorld(small.View());
        double worst = 0.0;
        for (int j = 0; j < small.resolution.height; ++j)
            for (int i = 0; i < small.resolution.width; ++i) {
                const int x = small.step * i + small.offset.x,
                          row = small.step * j + small.offset.y;
                ASSERT_EQ(small.depth[static_cast<std::size_t>(j) * small.resolution.width + i],
                          depth[static_cast<std::size_t>(row) * source.width + x]);
                const int y = c.rowsFlipped ? source.height - 1 - row : row;
                const std::size_t s = static_cast<std::size_t>(y) * source.width + x;
                if (!pass.exact.Covered(s)) continue;
                const glm::dvec4 h = screenFromWorld * glm::dvec4(pass.exact.wsPosition[s], 1.0);
                worst = std::max(worst,
                                 glm::length(glm::dvec2(h) / h.w - glm::dvec2(i + 0.5, j + 0.5)));
            }
        EXPECT_LT(worst, 1e-9) << c.name << ": small-image pixels";
        // The sampled grid is centred: the margins left and right differ by at most one pixel.
        const int right =
            source.width - (small.step * (small.resolution.width - 1) + small.offset.x + 1);
        EXPECT_LE(std::abs(right - small.offset.x), 1) << c.name;
    }
}

TEST(DepthBuffer, DownsamplingKeepsExactlyTheSourcePixels) {
    ExpectDownsamplingKeepsTheSourcePoints({320, 180}, 64, {64, 36}, 5);  // 16:9, divisible
    ExpectDownsamplingKeepsTheSourcePoints({197, 333}, 50, {28, 47}, 7);  // 9:16-ish, not
    ExpectDownsamplingKeepsTheSourcePoints({40, 30}, 180, {40, 30}, 1);   // already small
}

TEST(DepthBuffer, DownsamplingASmallBufferChangesNothing) {
    const Pass pass = FloorAndBox({40, 30});
    const glm::dmat4 clipFromWorld = pass.camera.ClipFromView() * pass.camera.ViewFromWorld();
    const Convention gl = Conventions(pass.camera)[0];
    const std::vector<float> depth = StoredDepth(pass.exact, clipFromWorld, gl);
    const DepthImage same = DownsampleDepth(DepthBuffer{
        .resolution = {40, 30}, .depth = depth, .clipFromWorld = clipFromWorld, .convention = {}});
    EXPECT_EQ(same.depth, depth);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(same.clipFromWorld[c][r], clipFromWorld[c][r],
                        1e-12 * (1.0 + std::abs(clipFromWorld[c][r])));
    EXPECT_THROW(DownsampleDepth(DepthBuffer{.resolution = {40, 30},
                                             .depth = depth,
                                             .clipFromWorld = clipFromWorld,
                                             .convention = {}},
                                 0),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lexel::spatial
