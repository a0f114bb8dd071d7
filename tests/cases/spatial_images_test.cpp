// The images of `lexel run --out` on a 3D case: uncovered pixels are marked exactly
// where the evaluation counts them, and every image is a titled figure the index can list.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/run/spatial_run.h"
#include "lexel/spatial/harness/image_io.h"
#include "lexel/spatial/harness/images.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {
namespace {

namespace fs = std::filesystem;

const std::string kSmallCase =
    std::string(LEXEL_CASES_DIR) + "/../tests/cases/data/spatial_small.json";

// spatial_small with every method, buffers kept (the run `lexel run --out` makes).
const SpatialRun& SmallRun(const spatial::Scene& scene) {
    static const SpatialRun run = [&] {
        SpatialRunOptions options;
        options.methods = spatial::SpatialMethodNames();
        options.mapTruth = false;
        options.keepBuffers = true;
        return RunSpatialCase(scene, options);
    }();
    return run;
}

const spatial::Scene& SmallScene() {
    static const spatial::Scene scene = LoadSpatialScene(kSmallCase);
    return scene;
}

bool Is(const spatial::Image& image, std::size_t i, spatial::ImageColour c) {
    return image.pixels[3 * i] == c.r && image.pixels[3 * i + 1] == c.g &&
           image.pixels[3 * i + 2] == c.b;
}

TEST(SpatialImages, MarkUncoveredPixelsWhereTheEvaluationCountsThem) {
    const spatial::Scene& scene = SmallScene();
    const SpatialRun& run = SmallRun(scene);
    const spatial::Evaluator& evaluator = *run.evaluator;
    const spatial::LightOutcome& o = run.outcomes.at(0);
    const spatial::LightSpace lightSpace(o.light, evaluator.bounds());
    int methodsWithUncovered = 0;
    for (const spatial::MethodOutcome& m : o.methods) {
        std::vector<spatial::Cascade> cascades;
        for (const spatial::CascadeOutcome& c : m.cascades) cascades.push_back(c.cascade);
        // A virtual shadow map's pages are not one matrix: the evaluation keeps its mask.
        const std::vector<std::uint8_t> uncovered =
            m.pages ? m.buffers.uncoveredPixels
                    : spatial::UncoveredPixels(evaluator.frame(), lightSpace, scene.camera,
                                               m.buffers.shades, m.buffers.map.matrix,
                                               m.buffers.map.resolution, cascades,
                                               m.buffers.map.warp ? &*m.buffers.map.warp : nullptr);
        if (m.pages) {
            EXPECT_EQ(uncovered.size(), m.buffers.shades.size()) << m.method;
        }
        std::int64_t marked = 0;
        for (std::uint8_t u : uncovered) marked += u;
        EXPECT_EQ(marked, m.metrics.uncovered) << m.method;
        methodsWithUncovered += m.metrics.uncovered > 0;
        const spatial::Image errors = spatial::MisclassificationImage(
            evaluator.frame(), lightSpace, m.buffers.shades, o.truth, uncovered);
        const spatial::Image frame =
            spatial::FrameImage(evaluator.frame(), lightSpace, m.buffers.shades, uncovered);
        std::int64_t amberErrors = 0, amberFrame = 0;
        for (std::size_t i = 0; i < uncovered.size(); ++i) {
            amberErrors += Is(errors, i, spatial::kUncoveredColour);
            amberFrame += Is(frame, i, spatial::kUncoveredColour);
        }
        EXPECT_EQ(amberErrors, m.metrics.uncovered) << m.method;
        EXPECT_EQ(amberFrame, m.metrics.uncovered) << m.method;
    }
    // focused-tight (169 here), plane-optimal, pssm, ... leave pixels uncovered.
    EXPECT_GE(methodsWithUncovered, 5);
}

TEST(SpatialImages, EveryImageIsListedWithItsLightMethodAndKind) {
    const spatial::Scene& scene = SmallScene();
    const SpatialRun& run = SmallRun(scene);
    const fs::path dir =
        fs::temp_directory_path() /
        ("lexel_spatial_images_" +
         std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(dir);
    std::size_t calls = 0;
    const std::vector<SpatialImageFile> files =
        WriteSpatialImages(dir, scene, run, [&] { ++calls; });
    // 21 single-map methods (rtw, rtw-lagrange and logpsm among them) × 3 (vsm and vsm-dynamic:
    // frame, errors and the page pool), 6 partitioned × (2 + 4 cascades), fp-lispsm 2 + 3 wedges.
    EXPECT_EQ(files.size(), 104u);
    EXPECT_EQ(SpatialImageCount(run), 104u);
    EXPECT_EQ(calls, 104u);
    std::set<std::string> names;
    for (const SpatialImageFile& f : files) {
        EXPECT_TRUE(fs::is_regular_file(dir / f.file)) << f.file;
        EXPECT_EQ(f.file, "spatial_small_light0_" + f.method + "_" + f.kind + ".png");
        EXPECT_FALSE(f.caption.empty()) << f.file;
        names.insert(f.file);
    }
    EXPECT_EQ(names.size(), files.size());
    // A figure: the 160 × 120 frame scaled by 3 (600 / 160), under a title and above a key.
    const spatial::Image frame =
        spatial::ReadImage((dir / "spatial_small_light0_optimal_frame.png").string());
    EXPECT_EQ(frame.width, 720);
    EXPECT_GT(frame.height, 3 * 120 + 60);
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

// Lexel run on a 3D case was silent for 30-40 s; its progress bar counts these steps.
TEST(SpatialRun, CallsOnStepOncePerCountedStep) {
    spatial::Scene scene = SmallScene();
    spatial::Camera moved = scene.camera;
    moved.position += glm::dvec3(0.5, 0.0, 0.0);
    scene.cameraPath = {scene.camera, moved};
    SpatialRunOptions options;
    options.methods = {"focused", "normal"};
    options.mapTruth = false;
    std::size_t calls = 0;
    options.onStep = [&] { ++calls; };
    // One light: 2 methods, then 2 poses × (2 methods + optimal for the hysteresis).
    EXPECT_EQ(SpatialRunSteps(scene, options), 2u + 2u * 3u);
    const SpatialRun run = RunSpatialCase(scene, options);
    EXPECT_EQ(calls, SpatialRunSteps(scene, options));
    ASSERT_EQ(run.cameraPath.size(), 1u);
    EXPECT_EQ(run.cameraPath[0].poses.size(), 2u);
}

}  // namespace
}  // namespace lexel::cases
