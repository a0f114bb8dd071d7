#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "lexel/cases/plot/axes.h"
#include "lexel/cases/plot/case_figure.h"
#include "lexel/cases/plot/curve_plot.h"
#include "lexel/cases/plot/image_figure.h"
#include "lexel/flatland/methods.h"
#include "lexel/spatial/harness/image_io.h"

namespace lexel::cases {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed afterwards, so parallel runs do not collide.
struct ScratchDir {
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path = fs::temp_directory_path() /
               ("lexel_figures_" + std::string(info->name()) + "_" + std::to_string(stamp));
        fs::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    fs::path path;
};

flatland::FlatScene MakeScene() {
    flatland::FlatScene scene;
    scene.name = "figures test: ground and a step";
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = flatland::Vec2(1, -0.25).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = 200;
    scene.wsLight = {-3, 10};
    scene.lexels = 200;
    scene.geometry = {{{-50, 0}, {200, 0}}, {{6, 0}, {6, 2}, {8, 2.5}}};
    return scene;
}

// Non-white pixels and distinct 8-bit colours: a blank or single-colour image fails both.
std::pair<int, int> CountInk(const spatial::Image& image) {
    int nonWhite = 0;
    std::set<std::tuple<int, int, int>> colours;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int r = static_cast<int>(std::lround(255 * image.at(x, y, 0)));
            const int g = static_cast<int>(std::lround(255 * image.at(x, y, 1)));
            const int b = static_cast<int>(std::lround(255 * image.at(x, y, 2)));
            if (r < 250 || g < 250 || b < 250) ++nonWhite;
            colours.emplace(r, g, b);
        }
    return {nonWhite, static_cast<int>(colours.size())};
}

bool HasPartialFile(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().find(".partial") != std::string::npos) return true;
    return false;
}

// The plotting module's tick steps: 1, 2 or 5 times a power of ten, nearest the rough step or the
// least with at most five steps across a span; whole decades around the data.
TEST(PlotAxes, TickStepsAndDecadesAreRound) {
    EXPECT_DOUBLE_EQ(plot::NiceStep(0.7), 0.5);
    EXPECT_DOUBLE_EQ(plot::NiceStep(1.4), 1.0);
    EXPECT_DOUBLE_EQ(plot::NiceStep(3.0), 2.0);
    EXPECT_DOUBLE_EQ(plot::NiceStep(80.0), 100.0);
    EXPECT_DOUBLE_EQ(plot::NiceStep(-1.0), 1.0);
    EXPECT_DOUBLE_EQ(plot::NiceStepAtLeast(7.0), 2.0);    // 1.4 rounded up
    EXPECT_DOUBLE_EQ(plot::NiceStepAtLeast(50.0), 10.0);  // exactly five steps
    EXPECT_DOUBLE_EQ(plot::NiceStepAtLeast(0.26), 0.1);   // 0.052 rounded up
    EXPECT_EQ(plot::DecadeRange(3.0, 2000.0), std::make_pair(0, 4));
    EXPECT_EQ(plot::DecadeRange(100.0, 100.0), std::make_pair(2, 3));
    EXPECT_FALSE(plot::DecadeRange(0.0, 1.0));
    EXPECT_EQ(plot::FormatTick(1e-4), "0.0001");
    EXPECT_EQ(plot::PaletteColour(12).r, plot::PaletteColour(0).r);
    EXPECT_NE(plot::PaletteColour(1).g, plot::PaletteColour(0).g);
}

TEST(Figures, CaseFigureIsATwoPanelPngWithContent) {
    const ScratchDir scratch;
    const flatland::FlatScene scene = MakeScene();
    const std::vector<std::string> methods = {"optimal-l1", "normal", "psm", "split-dp"};
    const flatland::CaseReport report = flatland::RunFlatlandCase(
        scene, methods, Metric::kL1, nullptr, nullptr, /*keepFootprints=*/true);
    ASSERT_EQ(report.methods.size(), methods.size());

    const fs::path path = scratch.path / "case.png";
    WriteCaseFigure(path.string(), scene, report);
    ASSERT_TRUE(fs::exists(path));
    EXPECT_FALSE(HasPartialFile(scratch.path));

    const spatial::Image image = spatial::ReadImage(path.string());
    EXPECT_EQ(image.width, 1600);
    EXPECT_EQ(image.height, 700);
    ASSERT_GE(image.channels, 3);
    const auto [nonWhite, colours] = CountInk(image);
    EXPECT_GT(nonWhite, image.width * image.height / 100);
    EXPECT_GE(colours, 3);
    // The background is white: the top-left corner is outside both panels.
    EXPECT_FLOAT_EQ(image.at(2, 2, 0), 1.0f);
}

TEST(Figures, CaseFigureIntoMissingDirectoryThrowsAndLeavesNothing) {
    const ScratchDir scratch;
    const flatland::FlatScene scene = MakeScene();
    const std::vector<std::string> methods = {"normal"};
    const flatland::CaseReport report = flatland::RunFlatlandCase(
        scene, methods, Metric::kL1, nullptr, nullptr, /*keepFootprints=*/true);
    const fs::path missing = scratch.path / "missing";
    const fs::path path = missing / "case.png";
    EXPECT_THROW(WriteCaseFigure(path.string(), scene, report), std::runtime_error);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(missing));
    EXPECT_FALSE(HasPartialFile(scratch.path));
}

TEST(Figures, CaseFigureWithoutFullPassIsRejected) {
    const ScratchDir scratch;
    const flatland::FlatScene scene = MakeScene();
    const fs::path path = scratch.path / "case.png";
    EXPECT_ANY_THROW(WriteCaseFigure(path.string(), scene, flatland::CaseReport{}));
    EXPECT_FALSE(fs::exists(path));
}

std::vector<LowresCurve> MakeCurves() {
    return {{"L1 (average)", {16, 32, 64, 128, 256, 512}, {14.0, 7.5, 3.1, 1.2, 0.4, 0.1}},
            {"L2 (average)", {16, 32, 64, 128, 256, 512}, {9.0, 4.0, 2.2, 0.8, 0.3, 0.05}}};
}

TEST(Figures, LowresPlotIsAPngWithContent) {
    const ScratchDir scratch;
    const fs::path path = scratch.path / "lowres.png";
    WriteLowresPlot(path.string(), "extra error against decision pixels", MakeCurves());
    ASSERT_TRUE(fs::exists(path));
    EXPECT_FALSE(HasPartialFile(scratch.path));
    const spatial::Image image = spatial::ReadImage(path.string());
    EXPECT_EQ(image.width, 900);
    EXPECT_EQ(image.height, 600);
    ASSERT_GE(image.channels, 3);
    const auto [nonWhite, colours] = CountInk(image);
    EXPECT_GT(nonWhite, image.width * image.height / 200);
    EXPECT_GE(colours, 3);
}

TEST(Figures, LowresPlotToleratesEmptyAndDegenerateCurves) {
    const ScratchDir scratch;
    const fs::path path = scratch.path / "lowres.png";
    const std::vector<LowresCurve> curves = {
        {"empty", {}, {}}, {"one point", {100}, {0.0}}, {"bad", {-1, 0, NAN}, {1, 2, 3}}};
    WriteLowresPlot(path.string(), "degenerate", curves);
    EXPECT_TRUE(fs::exists(path));
    WriteLowresPlot(path.string(), "no curves", {});  // overwrites the previous figure
    EXPECT_TRUE(fs::exists(path));
    EXPECT_FALSE(HasPartialFile(scratch.path));
}

TEST(Figures, LowresPlotIntoMissingDirectoryThrowsAndLeavesNothing) {
    const ScratchDir scratch;
    const fs::path path = scratch.path / "missing" / "lowres.png";
    EXPECT_THROW(WriteLowresPlot(path.string(), "title", MakeCurves()), std::runtime_error);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(HasPartialFile(scratch.path));
}

// ---- image figures (before: error and map images had no title, count or colour key) ----

int Byte(float v) { return static_cast<int>(std::lround(255 * v)); }

bool PixelIs(const spatial::Image& image, int x, int y, spatial::ImageColour c) {
    return std::abs(Byte(image.at(x, y, 0)) - Byte(c.r)) <= 1 &&
           std::abs(Byte(image.at(x, y, 1)) - Byte(c.g)) <= 1 &&
           std::abs(Byte(image.at(x, y, 2)) - Byte(c.b)) <= 1;
}

// Pixels of colour c in rows [y0, y1).
int CountColour(const spatial::Image& image, spatial::ImageColour c, int y0, int y1) {
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
        for (int x = 0; x < image.width; ++x) n += PixelIs(image, x, y, c);
    return n;
}

int InkRows(const spatial::Image& image, int y0, int y1) {
    int rows = 0;
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
        bool ink = false;
        for (int x = 0; x < image.width && !ink; ++x) ink = Byte(image.at(x, y, 0)) < 128;
        rows += ink;
    }
    return rows;
}

TEST(ImageFigure, ShowsThePictureScaledUnderItsTitleWithItsKeyAndScale) {
    const ScratchDir scratch;
    // A 4 × 3 picture: each pixel its own colour.
    spatial::Image picture = spatial::MakeImage(4, 3, 3);
    const auto colourAt = [](int x, int y) {
        return spatial::ImageColour{0.2f * x + 0.1f, 0.3f * y + 0.05f, 0.5f};
    };
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            picture.at(x, y, 0) = colourAt(x, y).r;
            picture.at(x, y, 1) = colourAt(x, y).g;
            picture.at(x, y, 2) = colourAt(x, y).b;
        }
    const spatial::ImageColour keyColour{0.9f, 0.3f, 0.7f};  // a colour the picture lacks
    ImageFigure figure;
    figure.title = "case · light 0 · optimal · errors";
    figure.lines = {"22 of 11165 counted pixels misclassified"};
    figure.key = {{"false shadow (12)", keyColour}};
    figure.bar = ColourBar{"depth", {{1, 1, 0}, {0, 1, 1}}, 2.0, 10.0, false};
    const ImageFigureLayout layout = LayOutImageFigure(picture, figure);
    EXPECT_EQ(layout.scale, 8);  // 600 / 4 = 150, at most 8
    EXPECT_EQ(layout.width, 720);
    const fs::path path = scratch.path / "figure.png";
    WriteImageFigure(path.string(), picture, figure);
    EXPECT_FALSE(HasPartialFile(scratch.path));
    const spatial::Image image = spatial::ReadImage(path.string());
    ASSERT_EQ(image.width, layout.width);
    ASSERT_EQ(image.height, layout.height);
    // Every source pixel is an 8 × 8 block at its place.
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            for (int d : {0, 7})
                EXPECT_TRUE(PixelIs(image, layout.imageX + 8 * x + d, layout.imageY + 8 * y + d,
                                    colourAt(x, y)))
                    << x << ", " << y;
    // Title and line above the picture: two lines of dark ink.
    EXPECT_GE(InkRows(image, 0, layout.imageY), 20);
    const int below = layout.imageY + 3 * layout.scale;
    EXPECT_EQ(CountColour(image, keyColour, 0, below), 0);
    EXPECT_GE(CountColour(image, keyColour, below, image.height), 12 * 12);  // the swatch
    // The bar runs from yellow to cyan under the key.
    EXPECT_GE(CountColour(image, {1, 1, 0}, below, image.height), 10);
    EXPECT_GE(CountColour(image, {0, 1, 1}, below, image.height), 10);
}

TEST(ImageFigure, LargePicturesKeepTheirSizeAndLongTitlesWrap) {
    const spatial::Image picture = spatial::MakeImage(900, 700, 3, 0.5f);
    ImageFigure figure;
    figure.title = std::string(400, 'x') + " " + std::string(10, 'y');
    const ImageFigureLayout layout = LayOutImageFigure(picture, figure);
    EXPECT_EQ(layout.scale, 1);
    EXPECT_EQ(layout.width, 900 + 32);
    ImageFigure shortTitle;
    shortTitle.title = "x";
    EXPECT_GT(layout.imageY, LayOutImageFigure(picture, shortTitle).imageY);  // two title lines
    EXPECT_THROW(WriteImageFigure("/nonexistent/x.png", spatial::Image{}, figure),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lexel::cases
