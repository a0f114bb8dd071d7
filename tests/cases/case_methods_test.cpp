// A 3D case's own methods (`methods`): matrices read inline and from CSV, assigned to the fixed
// or the sweep's lights by their count, and every kind of bad input an InputError naming the
// JSON pointer (the matrix, the CSV line) and the reason.
#include "lexel/cases/load/case_methods.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {
namespace {

const char* kCase = R"({
  "camera": {"position": [0, 3, -9], "target": [0, 0.5, 0], "fov_y_deg": 60,
             "width": 32, "height": 24},
  "lights": [{"type": "point", "position": [8, 8, 2]},
             {"type": "directional", "direction": [-0.3, -1, 0.4]}],
  "shadow_map": {"width": 64, "height": 32},
  "geometry": [{"primitive": "plane", "transform": {"scale": [20, 1, 20]}},
               {"primitive": "box", "transform": {"translate": [0, 1, 0]}}],
  "light_sweep": {"count": 3, "seed": 7, "radius": 40}
})";

spatial::Scene Load(const nlohmann::json& doc, const std::filesystem::path& dir = ".") {
    return SpatialSceneFromJson(doc, "methods", dir);
}

// A valid clip matrix for `light` in the case's scene: the default light matrix's.
glm::dmat4 ClipFor(const spatial::Light& light) {
    const spatial::Scene scene = Load(nlohmann::json::parse(kCase));
    const spatial::LightSpace ls(light, scene.geometry.ComputeBounds());
    const spatial::DepthRange range =
        ls.IsPoint() ? spatial::DepthRange{1.0, 80.0} : spatial::DepthRange{-40.0, 40.0};
    return spatial::ClipFromWorld(ls, spatial::LightMatrix{}, scene.shadowMap, range,
                                  spatial::ClipDepth::kMinusOneToOne);
}

nlohmann::json RowMajor(const glm::dmat4& m) {
    nlohmann::json rows = nlohmann::json::array();
    for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}

// The case with methods [{"name": name, "clip_from_world": matrices}].
nlohmann::json WithMethod(const std::string& name, const nlohmann::json& matrices) {
    nlohmann::json doc = nlohmann::json::parse(kCase);
    doc["methods"] = {{{"name", name}, {"clip_from_world", matrices}}};
    return doc;
}

std::string ErrorOf(const nlohmann::json& doc, const std::filesystem::path& dir = ".") {
    try {
        Load(doc, dir);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

nlohmann::json FixedMatrices() {
    const spatial::Scene scene = Load(nlohmann::json::parse(kCase));
    return {RowMajor(ClipFor(scene.lights[0])), RowMajor(ClipFor(scene.lights[1]))};
}

TEST(CaseMethods, InlineMatricesAreTheFixedLightsRowMajor) {
    const spatial::Scene scene = Load(WithMethod("mine", FixedMatrices()));
    ASSERT_EQ(scene.methods.size(), 1u);
    const spatial::CaseMethod& m = scene.methods[0];
    EXPECT_EQ(m.name, "mine");
    EXPECT_FALSE(m.forSweep);
    ASSERT_EQ(m.clipFromWorld.size(), 2u);
    // Bit for bit what was written, row r column c at m[c][r].
    for (std::size_t l = 0; l < 2; ++l) EXPECT_EQ(m.clipFromWorld[l], ClipFor(scene.lights[l]));
    EXPECT_EQ(CaseMethodNames(scene, false), std::vector<std::string>{"mine"});
    EXPECT_TRUE(CaseMethodNames(scene, true).empty());
    // The matrix for light 1 of `lexel run`, by name among the selected methods.
    const auto given =
        spatial::GivenMatricesOf(scene.methods, std::vector<std::string>{"mine"}, false, 1);
    ASSERT_EQ(given.size(), 1u);
    EXPECT_EQ(given[0].clipFromWorld, ClipFor(scene.lights[1]));
    EXPECT_TRUE(
        spatial::GivenMatricesOf(scene.methods, std::vector<std::string>{"mine"}, true, 0).empty());
}

TEST(CaseMethods, CsvRowsAreTheSweepLights) {
    const auto dir = std::filesystem::temp_directory_path() / "lexel_case_methods_test";
    std::filesystem::create_directories(dir);
    const spatial::Scene plain = Load(nlohmann::json::parse(kCase));
    const std::vector<spatial::Light> sweep =
        spatial::SweepLights(*plain.lightSweep, plain.geometry.ComputeBounds().Center());
    std::ofstream csv(dir / "mine.csv");
    csv << "# one row per sweep light\n" << std::setprecision(17);
    for (const spatial::Light& light : sweep) {
        const glm::dmat4 m = ClipFor(light);
        for (int k = 0; k < 16; ++k) csv << (k ? ", " : "") << m[k % 4][k / 4];
        csv << "\n\n";
    }
    csv.close();
    nlohmann::json doc = nlohmann::json::parse(kCase);
    doc["methods"] = {{{"name", "mine"}, {"clip_from_world_csv", "mine.csv"}}};
    const spatial::Scene scene = Load(doc, dir);
    ASSERT_EQ(scene.methods.size(), 1u);
    EXPECT_TRUE(scene.methods[0].forSweep);
    ASSERT_EQ(scene.methods[0].clipFromWorld.size(), 3u);
    for (std::size_t l = 0; l < 3; ++l)
        EXPECT_EQ(scene.methods[0].clipFromWorld[l], ClipFor(sweep[l])) << "light " << l;
    // A sweep of 2 of those lights is served; 4 lights, or lights of the other type, are not.
    const std::vector<std::string> mine{"mine"};
    EXPECT_NO_THROW(CheckCaseMethodLights(scene, mine, true, {sweep[0], sweep[1]}));
    std::vector<spatial::Light> more = sweep;
    more.push_back(sweep[0]);
    EXPECT_THROW(CheckCaseMethodLights(scene, mine, true, more), InputError);
    std::vector<spatial::Light> directional{sweep[0]};
    directional[0].type = spatial::Light::Type::kDirectional;
    try {
        CheckCaseMethodLights(scene, mine, true, directional);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/methods/0: 'mine': the matrix for sweep light 0 "
                                              "does not project from its light",
                                              0),
                  0u)
            << e.what();
    }
    // `lexel run` does not take a sweep's method.
    EXPECT_EQ(
        [&] {
            try {
                CheckCaseMethodLights(scene, mine, false);
            } catch (const InputError& e) {
                return std::string(e.what());
            }
            return std::string("no error");
        }(),
        "/methods/0: 'mine' has one matrix per light of the light sweep (for lexel sweep), "
        "not per light of lexel run");

    // Bad rows name the file's line.
    std::ofstream(dir / "short.csv") << "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15\n";
    std::ofstream(dir / "word.csv") << "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,abc\n";
    std::ofstream(dir / "empty.csv") << "# nothing\n";
    const auto csvError = [&](const std::string& file) {
        nlohmann::json bad = nlohmann::json::parse(kCase);
        bad["methods"] = {{{"name", "mine"}, {"clip_from_world_csv", file}}};
        return ErrorOf(bad, dir);
    };
    EXPECT_EQ(csvError("short.csv"),
              "/methods/0/clip_from_world_csv: short.csv:1: has 15 numbers, expected 16 (a 4x4 "
              "clip matrix, row-major)");
    // The cell's position, not its text: the file may be any file (before: its first 32 bytes).
    EXPECT_EQ(csvError("word.csv"),
              "/methods/0/clip_from_world_csv: word.csv:1: cell 16 is not a finite number");
    // A UTF-8 byte order mark is skipped, as in JSON (before: cell 1 was refused).
    std::ofstream(dir / "bom.csv") << "\xEF\xBB\xBF"
                                      "1,2,3,4,5,6,7,8,9,10,11,12,13,14,15\n";
    EXPECT_EQ(csvError("bom.csv"),
              "/methods/0/clip_from_world_csv: bom.csv:1: has 15 numbers, expected 16 (a 4x4 "
              "clip matrix, row-major)");
    EXPECT_EQ(csvError("empty.csv"), "/methods/0/clip_from_world_csv: the file has no rows");
    EXPECT_EQ(csvError("none.csv"), "/methods/0/clip_from_world_csv: cannot read " +
                                        (dir / "none.csv").string() + ": not a regular file");
    std::filesystem::remove_all(dir);
}

TEST(CaseMethods, BadMethodsAreNamed) {
    const nlohmann::json good = FixedMatrices();
    EXPECT_EQ(ErrorOf(WithMethod("optimal", good)),
              "/methods/0/name: 'optimal' clashes with a built-in method of that name; give yours "
              "another");
    EXPECT_EQ(ErrorOf(WithMethod("my method", good)),
              "/methods/0/name: must be 1 to 64 of A-Z a-z 0-9 _ . + - (not starting with -), got "
              "'my method'");
    EXPECT_EQ(ErrorOf(WithMethod("mine", nlohmann::json::array({good[0]}))),
              "/methods/0/clip_from_world: has 1 matrices, expected one per light: 2 (the fixed "
              "lights, for lexel run) or 3 (light_sweep.count, for lexel sweep)");
    nlohmann::json shortRow = good;
    shortRow[1][2] = {1, 2, 3};
    EXPECT_EQ(ErrorOf(WithMethod("mine", shortRow)),
              "/methods/0/clip_from_world/1/2: must be a row of 4 numbers, got 3");
    nlohmann::json text = good;
    text[0][3][1] = "x";
    EXPECT_EQ(ErrorOf(WithMethod("mine", text)),
              "/methods/0/clip_from_world/0/3/1: must be a number, got a string");
    nlohmann::json singular = good;
    singular[1][2] = singular[1][3];  // depth row = w row
    EXPECT_EQ(ErrorOf(WithMethod("mine", singular))
                  .rfind("/methods/0/clip_from_world/1: the matrix for light 1 is singular", 0),
              0u);
    // Light 1's matrix for light 0, and the identity: neither projects from its light.
    nlohmann::json swapped = {good[1], good[0]};
    EXPECT_EQ(ErrorOf(WithMethod("mine", swapped))
                  .rfind("/methods/0/clip_from_world/0: the matrix for light 0 does not project "
                         "from its light: row 1 does not send the point light to infinity",
                         0),
              0u);
    // Negated, a matrix has the same projection but w < 0 in front of the light, where a
    // rasterizer clips everything (before: accepted and scored as the original).
    nlohmann::json negated = good;
    for (auto& row : negated[1])
        for (auto& value : row) value = -value.get<double>();
    EXPECT_EQ(ErrorOf(WithMethod("mine", negated)),
              "/methods/0/clip_from_world/1: the matrix for light 1 has clip w <= 0 at the "
              "scene's centre, which a rasterizer clips (negated? w must be > 0 in front of the "
              "light)");
    // Scaled by 1e76, the same map (before: refused as singular, with "nan" in the message).
    nlohmann::json scaled = good;
    for (auto& row : scaled[0])
        for (auto& value : row) value = value.get<double>() * 1e76;
    EXPECT_EQ(ErrorOf(WithMethod("mine", scaled)), "no error");
    nlohmann::json doc = WithMethod("mine", good);
    doc["methods"].push_back({{"name", "mine"}, {"clip_from_world", good}});
    EXPECT_EQ(ErrorOf(doc), "/methods/1/name: 'mine' names an earlier method too");
    doc = WithMethod("mine", good);
    doc["methods"][0]["clip_from_world_csv"] = "x.csv";
    EXPECT_EQ(ErrorOf(doc),
              "/methods/0: must have exactly one of clip_from_world, "
              "clip_from_world_csv");
    doc = WithMethod("mine", good);
    doc["methods"][0]["clip"] = 1;
    EXPECT_EQ(ErrorOf(doc).rfind("/methods/0/clip: unknown key", 0), 0u) << ErrorOf(doc);
}

}  // namespace
}  // namespace lexel::cases
