// The error model's closed forms (spatial/error_model.h) against brute force: the band E|g·r| by
// a fine midpoint grid over the sub-texel offset r, the boundary pixels per pixel of edge by
// counting BoundaryPixels of rasterized straight edges, and the Sobel normal of such an edge.
#include "lexel/spatial/error_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace lexel::spatial {
namespace {

// E|g·r| for r uniform on [−½, ½]², by an n × n midpoint grid (error O(1/n²)).
double BruteForceBand(glm::dvec2 g, int n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            sum += std::abs(g.x * ((i + 0.5) / n - 0.5) + g.y * ((j + 0.5) / n - 0.5));
    return sum / (static_cast<double>(n) * n);
}

TEST(ErrorModel, BandMatchesBruteForceForAnyJacobian) {
    // A seeded sweep of normals and Jacobians (texels per pixel), printed on failure.
    std::uint64_t state = 12345;
    const auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    for (int trial = 0; trial < 20; ++trial) {
        const double angle = 2.0 * std::numbers::pi * next();
        const glm::dvec2 n(std::cos(angle), std::sin(angle));
        const glm::dvec2 row1(4.0 * next() - 2.0, 4.0 * next() - 2.0);
        const glm::dvec2 row2(4.0 * next() - 2.0, 4.0 * next() - 2.0);
        const glm::dvec2 g = EdgeNormalInTexels(n, row1, row2);
        // g = n̂ᵀJ⁻¹: g·(J dx) = n̂·dx for every dx.
        const glm::dvec2 dx(0.3, -0.7);
        EXPECT_NEAR(g.x * glm::dot(row1, dx) + g.y * glm::dot(row2, dx), glm::dot(n, dx), 1e-9);
        const double band = ExpectedBandWidth(n, row1, row2);
        EXPECT_NEAR(band, BruteForceBand(g, 600), 1e-5 * glm::length(g))
            << "trial " << trial << " n " << n.x << "," << n.y << " J " << row1.x << "," << row1.y
            << ";" << row2.x << "," << row2.y;
        const double isotropic = ExpectedBandWidthIsotropic(n, row1, row2);
        EXPECT_LE(band, isotropic * (1.0 + 1e-12));
        EXPECT_GE(band, isotropic * 4.0 / (3.0 * std::numbers::sqrt2) * (1.0 - 1e-12));
    }
}

TEST(ErrorModel, BandAlongAndDiagonalToTexelAxes) {
    // J = 1/2 texel per pixel: 2 pixels per texel. An edge along a texel axis moves by
    // |δ| ≤ ½ texel: ¼ texel = ½ pixel on average; at 45°, ‖g‖/(3√2).
    const glm::dvec2 row1(0.5, 0.0), row2(0.0, 0.5);
    EXPECT_DOUBLE_EQ(ExpectedBandWidth({1.0, 0.0}, row1, row2), 0.5);
    EXPECT_DOUBLE_EQ(ExpectedBandWidthIsotropic({0.0, 1.0}, row1, row2), 0.5);
    const glm::dvec2 diagonal(std::numbers::sqrt2 / 2, std::numbers::sqrt2 / 2);
    EXPECT_NEAR(ExpectedBandWidth(diagonal, row1, row2), 2.0 / (3.0 * std::numbers::sqrt2), 1e-15);
    EXPECT_EQ(ExpectedBandWidth({0.0, 0.0}, row1, row2), 0.0);
    EXPECT_TRUE(std::isinf(ExpectedBandWidth({1.0, 0.0}, {1.0, 2.0}, {2.0, 4.0})));
}

TEST(ErrorModel, FramePixelsScaleByTheResolutionRatio) {
    EXPECT_DOUBLE_EQ(FramePixelsFromReadbackArea(2.0, {180, 180}, {720, 540}), 2.0 * 12.0);
    EXPECT_EQ(FramePixelsFromReadbackArea(2.0, {0, 0}, {720, 540}), 0.0);
}

// A half-plane of shadow at angle φ rasterized at pixel centres (x¹ right, x² down).
std::vector<Shade> HalfPlane(Resolution r, double phi, glm::dvec2 origin) {
    const glm::dvec2 n(std::cos(phi), std::sin(phi));
    std::vector<Shade> shades(r.Count());
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x)
            shades[static_cast<std::size_t>(y) * r.width + x] =
                glm::dot(glm::dvec2(x + 0.5, y + 0.5) - origin, n) > 0.0 ? Shade::kShadowed
                                                                         : Shade::kLit;
    return shades;
}

TEST(ErrorModel, BoundaryPixelsPerEdgeLengthAndSobelNormal) {
    const Resolution r{400, 400};
    for (double deg : {0.0, 13.0, 27.0, 45.0, 71.0, 90.0, 148.0}) {
        const double phi = deg * std::numbers::pi / 180.0;
        const glm::dvec2 n(std::cos(phi), std::sin(phi));
        const std::vector<Shade> shades = HalfPlane(r, phi, {200.3, 199.6});
        // Count the boundary pixels inside a disc of radius 150 around the centre: the edge's
        // 300 pixels there stand for 300 / EdgeLengthPerBoundaryPixel of them.
        std::size_t inside = 0;
        double worstCos = 1.0;
        glm::dvec2 sum(0.0);
        for (std::uint32_t p : BoundaryPixels(r, shades)) {
            const glm::dvec2 x(p % 400 + 0.5, p / 400 + 0.5);
            if (glm::length(x - glm::dvec2(200.3, 199.6)) > 150.0) continue;
            ++inside;
            const glm::dvec2 sobel = EdgeNormalAt(r, shades, p);
            worstCos = std::min(worstCos, glm::dot(sobel, n));
            sum += sobel;
        }
        const double expected = 300.0 / EdgeLengthPerBoundaryPixel(n);
        EXPECT_NEAR(static_cast<double>(inside), expected, 0.02 * expected) << deg << "°";
        // The Sobel normal of a binary staircase: within 35° of the true normal at every pixel
        // of it (measured at most 32°, at 13°), within 5° on average along it (measured at most
        // 4.0°, at 71°): a bias of that size moves the band by a few percent at most.
        EXPECT_GT(worstCos, std::cos(35.0 * std::numbers::pi / 180.0)) << deg << "°";
        EXPECT_GT(glm::dot(glm::normalize(sum), n), std::cos(5.0 * std::numbers::pi / 180.0))
            << deg << "°";
    }
}

TEST(ErrorModel, SobelNormalIgnoresPixelsThatSayNothing) {
    const Resolution r{3, 3};
    std::vector<Shade> shades(9, Shade::kLit);
    shades[2] = shades[5] = shades[8] = Shade::kShadowed;  // the right column
    shades[0] = Shade::kEmpty;
    shades[6] = Shade::kFacingAway;
    const glm::dvec2 n = EdgeNormalAt(r, shades, 4);
    EXPECT_NEAR(n.x, 1.0, 1e-12);
    EXPECT_NEAR(n.y, 0.0, 1e-12);
    // A shadow one pixel thin has no gradient at its centre.
    std::vector<Shade> line(9, Shade::kLit);
    line[3] = line[4] = line[5] = Shade::kShadowed;
    EXPECT_EQ(EdgeNormalAt(r, line, 4), glm::dvec2(0.0));
    EXPECT_THROW(EdgeNormalAt(r, line, 9), std::invalid_argument);
}

}  // namespace
}  // namespace lexel::spatial
