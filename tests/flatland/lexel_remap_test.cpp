#include "lexel/flatland/lexel_remap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "test_scenes.h"

namespace lexel::flatland {
namespace {

using testing::Describe;
using testing::RandomScene;

// Remapped footprints (R2) equal footprints recomputed from scratch in world space at the new
// angle, over the whole valid interval.
TEST(LexelRemap, RemappedFootprintsEqualFromScratch) {
    std::mt19937_64 rng(3);
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
        const FlatScene scene = RandomScene(seed);
        SCOPED_TRACE(Describe(scene));
        const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
        const LexelSamples samples = MakeLexelSamples(pass, scene.lexels);
        const ValidInterval valid = ValidTInterval(samples);
        const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
        std::uniform_real_distribution<double> u(0.02, 0.98);
        for (int k = 0; k < 5; ++k) {
            const double t = std::tan(xLo + u(rng) * (xHi - xLo));
            const auto remapped = RemappedFootprints(samples, t);
            const auto scratch =
                FootprintsFromScratch(pass, scene.wsLight, WsAxisFromT(samples, t), scene.lexels);
            ASSERT_TRUE(scratch.has_value()) << "t = " << t;
            for (std::size_t i = 0; i < remapped.size(); ++i)
                ASSERT_NEAR(remapped[i] / (*scratch)[i], 1.0, 1e-9)
                    << "t = " << t << " sample " << i;
        }
    }
}

TEST(LexelRemap, ValidityMatchesPointsInFront) {
    const FlatScene scene = RandomScene(11);
    const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
    const LexelSamples samples = MakeLexelSamples(pass, scene.lexels);
    const ValidInterval valid = ValidTInterval(samples);
    const double xLo = std::atan(valid.lo), xHi = std::atan(valid.hi);
    // The valid range of the axis is (Δ/2 − 90°, 90° − Δ/2) about the bisector.
    EXPECT_NEAR(xHi, std::numbers::pi / 2 - pass.halfSweep, 1e-12);
    EXPECT_NEAR(xLo, -(std::numbers::pi / 2 - pass.halfSweep), 1e-12);
    EXPECT_TRUE(
        FootprintsFromScratch(pass, scene.wsLight, pass.wsAxis0 + xHi - 1e-6, 1).has_value());
    EXPECT_FALSE(
        FootprintsFromScratch(pass, scene.wsLight, pass.wsAxis0 + xHi + 1e-6, 1).has_value());
    // f → ∞ at the ends.
    EXPECT_GT(RemappedFootprints(samples, std::tan(xHi - 1e-9)).front() +
                  RemappedFootprints(samples, std::tan(xHi - 1e-9)).back(),
              1e6 * samples.footprint0.front());
}

// The thesis's rescaling for a sub-frustum (§3.2: l re-expressed in the smaller frustum, dp/dl
// multiplied by the ratio of the frusta's sizes) is what MakeLexelSamples with bounds computes.
TEST(LexelRemap, SubFrustumSamplesEqualTheThesisRescaling) {
    const FlatScene scene = RandomScene(5);
    const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
    const LexelSamples whole = MakeLexelSamples(pass, scene.lexels);
    // A sub-frustum: the middle half of the light's sweep, with 300 lexels.
    const double lo = -0.5 * pass.halfSweep, hi = 0.5 * pass.halfSweep;
    std::vector<double> angle, g;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < pass.samples.size(); ++i)
        if (pass.samples[i].lsAngle >= lo && pass.samples[i].lsAngle <= hi)
            angle.push_back(pass.samples[i].lsAngle),
                g.push_back(PixelsPerRadian(pass, pass.samples[i])), index.push_back(i);
    ASSERT_GT(angle.size(), 5u);
    const double subLexels = 300;
    const LexelSamples sub = MakeLexelSamples(angle, g, pass.wsAxis0, subLexels, lo, hi);
    // Both are bisected by θ0 here, so the sub-frustum's footprint at θ0 (t = 0) is the whole
    // frustum's scaled by (sub film width / whole film width) · (N_whole / N_sub).
    const double sizeRatio = (std::tan(hi) - std::tan(lo)) / (whole.tanHigh - whole.tanLow);
    for (std::size_t k = 0; k < index.size(); ++k) {
        EXPECT_NEAR(sub.footprint0[k],
                    whole.footprint0[index[k]] * sizeRatio * scene.lexels / subLexels,
                    1e-12 * whole.footprint0[index[k]]);
        // l re-expressed: l_sub = N_sub (l/N − l_lo/N) / (l_hi/N − l_lo/N) on the film.
        const double lWhole = LexelCoordinate(whole, index[k]) / scene.lexels;
        const double lLo = (std::tan(lo) - whole.tanLow) / (whole.tanHigh - whole.tanLow);
        const double lHi = (std::tan(hi) - whole.tanLow) / (whole.tanHigh - whole.tanLow);
        EXPECT_NEAR(LexelCoordinate(sub, k), subLexels * (lWhole - lLo) / (lHi - lLo), 1e-9);
    }
}

}  // namespace
}  // namespace lexel::flatland
