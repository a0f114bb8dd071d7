// `lexel storage`'s runner (cases/studies/storage/storage_study.h): the best single map's S̄ and the
// scheme each method is compared with, against the closed forms of Lloyd et al. 2006
// (storage_factor.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "lexel/cases/studies/storage/storage_report.h"
#include "lexel/cases/studies/storage/storage_study.h"
#include "lexel/spatial/harness/image_io.h"

namespace lexel::cases {
namespace {

using spatial::DirectionToLight;
using spatial::ViewFrustum;

TEST(StorageRun, BestSingleMapWithTheLightOverheadIsLispsmsFlatMinimum) {
    // Eq. 12: S̄(n') is (f/n - 1)/(2 tanθ) on [n, n + √(fn)] and larger beyond, so the least S̄
    // of any warp is that value (865.159 for f/n = 1000, θ = 30°; 85.7365 for f/n = 100).
    for (double far : {100.0, 1000.0}) {
        const ViewFrustum frustum{60.0, 1.0, 1.0, far};
        const double flat = (far - 1.0) / (2.0 * std::tan(std::numbers::pi / 6.0));
        EXPECT_NEAR(BestSingleMapStorage(frustum, DirectionToLight(90.0)), flat, 1e-9 * flat)
            << "f = " << far;
    }
}

TEST(StorageRun, BestSingleMapIsNoMoreThanEveryWarpForSkewedLights) {
    const ViewFrustum frustum{60.0, 1.5, 0.5, 200.0};
    for (double gamma : {20.0, 45.0, 70.0, 120.0, 160.0}) {
        const glm::dvec3 esToLight = DirectionToLight(gamma, 30.0);
        const double best = BestSingleMapStorage(frustum, esToLight);
        for (double eta : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
            const double nPrime = spatial::WarpOffsetFromEta(eta, 0.5, 200.0);
            EXPECT_LE(best, spatial::StorageFactorForWarpOffset(frustum, esToLight, nPrime))
                << "γ " << gamma << "°, η " << eta;
        }
    }
}

TEST(StorageRun, EachMethodIsComparedWithItsScheme) {
    // Fig. 12's set-up with the light overhead: ZP eq. 17, ZP + W eq. 18, unwarped eq. 12 at
    // n' = ∞, LiSPSM and PSM both (f/n - 1)/(2 tanθ).
    const ViewFrustum frustum{60.0, 1.0, 1.0, 1000.0};
    const glm::dvec3 overhead = DirectionToLight(90.0);
    const auto value = [&](const char* method, int k) {
        return AnalyticStorageOf(method, k, frustum, overhead);
    };
    EXPECT_EQ(value("pssm", 4).scheme, "ZP (k = 4)");
    EXPECT_NEAR(value("pssm", 4).storage, 90.0644, 1e-4);
    EXPECT_NEAR(value("sdsm-rect", 4).storage, 90.0644, 1e-4);
    EXPECT_EQ(value("zp-lispsm", 8).scheme, "ZP + W (k = 8)");
    EXPECT_NEAR(value("zp-lispsm", 8).storage, 9.50116, 1e-5);
    EXPECT_NEAR(value("sdsm-optimal", 2).storage, 53.0402, 1e-4);
    EXPECT_EQ(value("sdsm-optimal-h", 2).scheme, "ZP + W (k = 2)");  // on h, the same scheme
    EXPECT_NEAR(value("focused-tight", 1).storage, 865159.4, 0.1);
    EXPECT_NEAR(value("lispsm", 1).storage, 865.159, 1e-3);
    EXPECT_NEAR(value("psm-tight", 1).storage, 865.159, 1e-3);
    EXPECT_EQ(value("optimal", 1).scheme, "best single map");
    EXPECT_NEAR(value("optimal", 1).storage, 865.159, 1e-3);
    EXPECT_EQ(value("fp-lispsm", 3).scheme, "FP + W");
    // LogPSM reaches the log bound with the light overhead (Lloyd 2006 Appendix C): 5.98229.
    EXPECT_EQ(value("logpsm", 1).scheme, "LogPSM");
    EXPECT_NEAR(value("logpsm", 1).storage, OptimalStorageFactor(frustum), 1e-12);
    EXPECT_NEAR(value("logpsm", 1).storage, 5.98229, 1e-5);
    EXPECT_TRUE(std::isnan(value("rtw", 1).storage));
    EXPECT_TRUE(std::isnan(value("rtw-lagrange", 1).storage));
}

TEST(StorageRun, StudyHoldsEveryFigure) {
    const StorageStudy study = RunStorageStudy({60.0, 1.0, 1.0, 1000.0}, {5, 9, 8, 2});
    EXPECT_NEAR(study.optimal, 5.98229, 1e-5);
    ASSERT_EQ(study.warpRatios.size(), 3u);                    // 20, 100, 1000
    EXPECT_NEAR(study.warp[1].back().storage, 85.7365, 1e-4);  // PSM at f/n = 100
    ASSERT_EQ(study.maps.size(), 8u);
    EXPECT_NEAR(study.maps[3].zpWarpOverhead, 16.016, 1e-3);
    ASSERT_EQ(study.hemisphere.size(), 3u);
    // LiSPSM's least S̄ over the hemisphere is the overhead light's (the grid's centre column
    // holds γ = 90° exactly for an odd size).
    EXPECT_NEAR(study.hemisphere[1].minStorage, 865.159, 1e-3);
    EXPECT_GT(study.hemisphere[1].maxStorage, 100.0 * study.hemisphere[1].minStorage);
    ASSERT_EQ(study.crossover.size(), 2u);
    EXPECT_NEAR(study.crossover[1].depthRatio, 29.1141, 1e-4);
}

TEST(StorageRun, BadFrustumThrowsNamingTheQuantity) {
    EXPECT_THROW(RunStorageStudy({60.0, 1.0, 1.0, 0.5}), spatial::StorageFactorError);
}

TEST(StorageRun, FiguresAreSevenPngFiles) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "lexel_storage_figures_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const StorageStudy study = RunStorageStudy({60.0, 1.0, 1.0, 100.0}, {9, 9, 8, 2});
    const std::vector<std::string> files = WriteStorageFigures(dir, study);
    ASSERT_EQ(files.size(), 7u);
    for (const std::string& f : files) {
        EXPECT_EQ(std::filesystem::path(f).extension(), ".png") << f;
        EXPECT_GT(std::filesystem::file_size(dir / f), 300u) << f;
    }
    // Fig. 7: a titled figure, the 9 × 9 grid scaled by 8, with its log scale (before: the
    // hemisphere images had no scale): the bar runs from the ramp's dark blue to its red.
    const spatial::Image hemisphere = spatial::ReadImage((dir / files[1]).string());
    EXPECT_EQ(hemisphere.width, 720);
    EXPECT_GT(hemisphere.height, 9 * 8 + 100);
    const auto count = [&](float r, float g, float b) {
        int n = 0;
        for (int y = 0; y < hemisphere.height; ++y)
            for (int x = 0; x < hemisphere.width; ++x)
                n += std::abs(hemisphere.at(x, y, 0) - r) < 2.5f / 255 &&
                     std::abs(hemisphere.at(x, y, 1) - g) < 2.5f / 255 &&
                     std::abs(hemisphere.at(x, y, 2) - b) < 2.5f / 255;
        return n;
    };
    EXPECT_GE(count(0.1f, 0.1f, 0.5f), 10);    // the bar's low end (and maybe cells)
    EXPECT_GE(count(0.8f, 0.05f, 0.05f), 10);  // its high end
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lexel::cases
