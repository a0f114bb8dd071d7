// A 3D case's mesh entries: the file's up axis and units placed before the entry's transform, the
// entries as `lexel mesh-info --case` reads them, and one-line errors naming the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {
namespace {

// A Z-up tetrahedron in centimetres: its apex (0, 0, 300) is 3 m up. One file per test (CTest
// runs the tests of this file as parallel processes, and each removes its file at the end).
std::filesystem::path TetraPly() {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const auto path =
        std::filesystem::temp_directory_path() / ("lexel_mesh_entry_" + test + ".ply");
    std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty "
                           "float y\nproperty float z\nelement face 4\nproperty list uchar int "
                           "vertex_indices\nend_header\n0 0 0\n100 0 0\n0 200 0\n0 0 300\n"
                           "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    return path;
}

nlohmann::json Case(const std::string& meshEntry) {
    return nlohmann::json::parse(R"({
      "camera": {"position": [0, 1.7, -10], "target": [0, 1, 0], "fov_y_deg": 50,
                 "width": 64, "height": 48},
      "lights": [{"type": "directional", "direction": [0, -1, 0.2]}],
      "geometry": [{"primitive": "plane", "transform": {"scale": 20}}, )" +
                                 meshEntry + "]}");
}

std::string ErrorFor(const std::string& meshEntry) {
    try {
        SpatialSceneFromJson(Case(meshEntry), "x", std::filesystem::temp_directory_path());
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// World = T · R · S · SceneFromFile: (x, y, z) cm Z-up ↦ 0.01 · (x, z, −y), then scale 2 and a
// translation (5, 0, 0). The plane's 4 vertices come first.
TEST(SpatialCaseMeshEntry, PlacesUpAxisAndUnitsBeforeTheTransform) {
    const auto ply = TetraPly();
    const spatial::Scene scene = SpatialSceneFromJson(
        Case(R"({"mesh": ")" + ply.filename().string() +
             R"(", "up": "z", "units": "cm", "transform": {"scale": 2, "translate": [5, 0, 0]}})"),
        "x", ply.parent_path());
    ASSERT_EQ(scene.geometry.positions.size(), 8u);
    const glm::vec3 expected[] = {{5, 0, 0}, {7, 0, 0}, {5, 0, -4}, {5, 6, 0}};
    for (int v = 0; v < 4; ++v) {
        const glm::dvec3 p = scene.geometry.positions[4 + v];
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], expected[v][k], 1e-6) << v << " " << k;
    }
    // A number is scene units per file unit; "m" and 1 and the default are the same.
    const spatial::Scene numeric = SpatialSceneFromJson(
        Case(R"({"mesh": ")" + ply.string() + R"(", "units": 0.5})"), "x", ".");
    EXPECT_EQ(numeric.geometry.positions[7], glm::dvec3(0, 0, 150));
    std::filesystem::remove(ply);
}

TEST(SpatialCaseMeshEntry, RefusesBadUpAndUnitsNamingTheField) {
    const auto ply = TetraPly();
    const std::string mesh = R"({"mesh": ")" + ply.string() + R"(", )";
    EXPECT_EQ(ErrorFor(mesh + R"("up": "x"})"), "/geometry/1/up: must be y or z, got 'x'");
    EXPECT_EQ(ErrorFor(mesh + R"("units": "furlong"})"),
              "/geometry/1/units: must be one of m, cm, mm, km, in, ft or a positive number, got "
              "'furlong'");
    EXPECT_EQ(ErrorFor(mesh + R"("units": -1})"), "/geometry/1/units: must be in (0, inf), got -1");
    EXPECT_EQ(ErrorFor(mesh + R"("units": [1]})"),
              "/geometry/1/units: must be a unit (m, cm, mm, km, in, ft) or a positive number of "
              "scene units per file unit");
    EXPECT_EQ(ErrorFor(mesh + R"("units": 1e300})"),
              "/geometry/1/units: the mesh in these units reaches |x| = 3e+302, coordinates must "
              "be at most 1e+15");
    EXPECT_EQ(ErrorFor(mesh + R"("units": 1e-320})"),
              "/geometry/1/units: the mesh in these units collapses to one point (its float "
              "vertices coincide)");
    EXPECT_EQ(ErrorFor(R"({"primitive": "box", "up": "z"})"),
              "/geometry/1/up: only a mesh entry has a file whose axes and units it sets");
    std::filesystem::remove(ply);
}

TEST(SpatialCaseMeshEntry, ListsTheMeshEntriesOfACaseFile) {
    const auto dir = std::filesystem::temp_directory_path() / "lexel_mesh_entries";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "case.json")
        << Case(R"({"mesh": "a.ply", "up": "z", "units": "in"}, {"primitive": "box"},
                   {"mesh": "/abs/b.glb", "transform": {"translate": [1, 2, 3]}})")
               .dump();
    const std::vector<SpatialMeshEntry> entries = LoadSpatialMeshEntries(dir / "case.json");
    ASSERT_EQ(entries.size(), 2u);
    EXPECT_EQ(entries[0].pointer, "/geometry/1");
    EXPECT_EQ(entries[0].file, dir / "a.ply");
    EXPECT_EQ(entries[0].frame.up, spatial::UpAxis::kZ);
    EXPECT_EQ(entries[0].frame.unitScale, 0.0254);
    EXPECT_EQ(entries[1].pointer, "/geometry/3");
    EXPECT_EQ(entries[1].file, "/abs/b.glb");
    EXPECT_EQ(entries[1].transform.translate, glm::dvec3(1, 2, 3));
    std::ofstream(dir / "bad.json") << Case(R"({"mesh": "a.ply", "up": 3})").dump();
    try {
        LoadSpatialMeshEntries(dir / "bad.json");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "bad.json").string() +
                                             ": /geometry/1/up: must be a string, got an integer");
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lexel::cases
