// Mesh loading through Assimp, on the models of Debian's assimp-testmodels package.
#include "lexel/spatial/harness/mesh_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_file_check.h"

namespace lexel::spatial {
namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models";

// The package is a test dependency: its absence is a failure, not a skip.
bool ModelsInstalled() {
    if (std::filesystem::is_directory(kModels)) return true;
    ADD_FAILURE() << kModels << " is missing: install the Debian package assimp-testmodels "
                  << "(apt-get install assimp-testmodels)";
    return false;
}

std::string LoadError(const std::filesystem::path& path) {
    try {
        LoadMesh(path);
    } catch (const DomainError& e) {
        return e.what();
    }
    return "no error";
}

void ExpectSane(const TriangleMesh& mesh) {
    for (const glm::vec3& p : mesh.positions)
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ASSERT_LT(t[k], mesh.positions.size());
}

TEST(MeshLoader, BoxObjHasExactBounds) {
    if (!ModelsInstalled()) return;
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    const TriangleMesh box = LoadMesh(kModels / "OBJ/box.obj");
    // Assimp must stay silent: lexel's stdout carries reports.
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    ExpectSane(box);
    // Six quads, triangulated; identical vertices joined per mesh.
    EXPECT_EQ(box.triangles.size(), 12u);
    const Bounds b = box.ComputeBounds();
    EXPECT_EQ(b.lo, glm::dvec3(-0.5));
    EXPECT_EQ(b.hi, glm::dvec3(0.5));
}

TEST(MeshLoader, LoadsRealModels) {
    if (!ModelsInstalled()) return;
    struct Expectation {
        const char* file;
        std::size_t minTriangles, maxTriangles;
        double minExtent, maxExtent;  // largest side of the bounds
    };
    // Assimp 5.2 (Debian 12) reads 1368 and 3732 triangles; the ranges leave room for other
    // versions' triangulation. The spider's OBJ is about 200 units across, its STL export 8.
    const Expectation models[] = {
        {"OBJ/spider.obj", 1300, 1400, 150.0, 250.0},
        {"STL/Spider_binary.stl", 1300, 1400, 7.0, 9.0},
        {"PLY/Wuson.ply", 3700, 3800, 3.0, 3.5},
        {"OBJ/box.obj", 12, 12, 1.0, 1.0},
    };
    for (const Expectation& e : models) {
        SCOPED_TRACE(e.file);
        testing::internal::CaptureStdout();
        testing::internal::CaptureStderr();
        const TriangleMesh mesh = LoadMesh(kModels / e.file);
        EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
        EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
        ExpectSane(mesh);
        EXPECT_GE(mesh.triangles.size(), e.minTriangles);
        EXPECT_LE(mesh.triangles.size(), e.maxTriangles);
        const Bounds b = mesh.ComputeBounds();
        ASSERT_FALSE(b.Empty());
        const glm::dvec3 size = b.hi - b.lo;
        const double extent = std::max({size.x, size.y, size.z});
        EXPECT_GE(extent, e.minExtent);
        EXPECT_LE(extent, e.maxExtent);
    }
}

TEST(MeshLoader, WusonIsTheSameInPlyObjAndStl) {
    if (!ModelsInstalled()) return;
    // Three exports of one model: the same triangles within the formats' float precision.
    const TriangleMesh ply = LoadMesh(kModels / "PLY/Wuson.ply");
    const Bounds plyBounds = ply.ComputeBounds();
    for (const char* other : {"OBJ/WusonOBJ.obj", "STL/Wuson.stl"}) {
        SCOPED_TRACE(other);
        const TriangleMesh mesh = LoadMesh(kModels / other);
        EXPECT_EQ(mesh.triangles.size(), ply.triangles.size());
        const Bounds b = mesh.ComputeBounds();
        EXPECT_NEAR(glm::distance(b.lo, plyBounds.lo), 0.0, 1e-4);
        EXPECT_NEAR(glm::distance(b.hi, plyBounds.hi), 0.0, 1e-4);
    }
    // Wuson stands on y = 0 (its lowest point is 0.000566 below).
    EXPECT_NEAR(plyBounds.lo.y, 0.0, 1e-3);
    EXPECT_NEAR(plyBounds.hi.y, 1.51525, 1e-4);
}

TEST(MeshLoader, RejectsInvalidFilesNamingThem) {
    if (!ModelsInstalled()) return;
    std::vector<std::filesystem::path> invalid;
    for (const auto& entry : std::filesystem::directory_iterator(kModels / "invalid"))
        if (entry.path().extension() == ".obj" && entry.path().filename() != "malformed2.obj")
            invalid.push_back(entry.path());
    invalid.push_back(kModels / "invalid/empty.ply");
    // Only points or only lines: nothing to cast a shadow.
    invalid.push_back(kModels / "OBJ/testpoints.obj");
    invalid.push_back(kModels / "OBJ/testline.obj");
    ASSERT_GE(invalid.size(), 4u);
    for (const auto& path : invalid) {
        SCOPED_TRACE(path.string());
        testing::internal::CaptureStdout();
        testing::internal::CaptureStderr();
        const std::string message = LoadError(path);
        EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
        EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
        EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(MeshLoader, ToleratesTheMissingMaterialOfMalformed2) {
    if (!ModelsInstalled()) return;
    // invalid/malformed2.obj is the unit box with a missing material and one empty `f` line
    // (Assimp's regression test for the material). Materials do not matter to shadows, and its
    // five well-formed quads are real geometry, so it loads as 10 triangles, like Assimp does.
    const TriangleMesh mesh = LoadMesh(kModels / "invalid/malformed2.obj");
    EXPECT_EQ(mesh.triangles.size(), 10u);
    EXPECT_EQ(mesh.ComputeBounds().hi, glm::dvec3(0.5));
}

TEST(MeshLoader, MissingFileAndGarbage) {
    EXPECT_EQ(LoadError("/nonexistent-dir/model.obj"),
              "/nonexistent-dir/model.obj: mesh file not found");
    EXPECT_EQ(LoadError(std::filesystem::temp_directory_path()),
              std::filesystem::temp_directory_path().string() + ": mesh file not found");
    const auto garbage = std::filesystem::temp_directory_path() / "lexel_mesh_loader_garbage.ply";
    std::ofstream(garbage) << "this is not a model\nat all\n";
    const std::string message = LoadError(garbage);
    EXPECT_EQ(message.rfind(garbage.string() + ": cannot read mesh: ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    std::filesystem::remove(garbage);
}

TEST(MeshLoader, RejectsNonFiniteCoordinates) {
    const auto dir = std::filesystem::temp_directory_path();
    // An overflowing OBJ literal becomes +inf; ASCII STL reads "nan" as NaN.
    const std::pair<const char*, const char*> files[] = {
        {"lexel_mesh_loader_inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1e999 1\nf 1 2 3\n"},
        {"lexel_mesh_loader_nan.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
         "vertex 0 nan 0\nendloop\nendfacet\nendsolid x\n"},
    };
    for (const auto& [name, text] : files) {
        const auto path = dir / name;
        std::ofstream(path) << text;
        EXPECT_EQ(LoadError(path),
                  path.string() + ": vertex 2 of mesh 0 has a non-finite coordinate");
        std::filesystem::remove(path);
    }
}

// Assimp allocates what a header declares: its own invalid/OutOfMemory.off (3.5e11 vertices in
// 309 bytes) took gigabytes in seconds (issue 16). The declared counts are held against the size.
TEST(MeshLoader, RefusesDeclaredCountsTheFileCannotHold) {
    if (!ModelsInstalled()) return;
    const auto oom = kModels / "invalid/OutOfMemory.off";
    EXPECT_EQ(LoadError(oom), oom.string() +
                                  ": declares 353535235358 vertices and 6 faces, more than its 309 "
                                  "bytes can hold (a truncated or corrupt file)");
    const auto dir = std::filesystem::temp_directory_path();
    const std::pair<const char*, std::string> files[] = {
        {"lexel_mesh_check.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
         "end_header\n0000"},
        {"lexel_mesh_check_ascii.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nelement face 1000\n"
         "property list uchar int vertex_indices\nend_header\n0\n0\n0\n3 0 1 2\n"},
    };
    const std::string reasons[] = {"declares 4000000000 elements, more than its 94 bytes",
                                   "declares 1003 elements, more than its 137 bytes"};
    for (int k = 0; k < 2; ++k) {
        const auto path = dir / files[k].first;
        std::ofstream(path, std::ios::binary) << files[k].second;
        EXPECT_EQ(LoadError(path).rfind(path.string() + ": " + reasons[k], 0), 0u)
            << LoadError(path);
        std::filesystem::remove(path);
    }
    // A binary STL whose facet count (at byte 80) is 10^9 with one facet's bytes.
    std::string stl(84 + 50, '\0');
    const std::uint32_t facets = 1000000000;
    std::memcpy(stl.data() + 80, &facets, sizeof facets);
    const auto stlPath = dir / "lexel_mesh_check.stl";
    std::ofstream(stlPath, std::ios::binary) << stl;
    EXPECT_EQ(LoadError(stlPath), stlPath.string() +
                                      ": declares 1000000000 facets, more than its 134 bytes can "
                                      "hold (a truncated or corrupt file)");
    std::filesystem::remove(stlPath);
}

TEST(MeshLoader, RefusesOtherFormatsAndOversizedFiles) {
    if (!ModelsInstalled()) return;
    const auto threeDs = kModels / "invalid/empty.3ds";
    EXPECT_EQ(LoadError(threeDs),
              threeDs.string() + ": format '.3ds' is not read (mesh formats: obj, off, ply, stl)");
    // A sparse file one byte over the cap: refused from its size, never read.
    const auto big = std::filesystem::temp_directory_path() / "lexel_mesh_check_big.obj";
    std::ofstream(big, std::ios::binary).close();
    std::filesystem::resize_file(big, kMaxMeshFileBytes + 1);
    EXPECT_EQ(LoadError(big),
              big.string() + ": is 67108865 bytes, larger than the 64 MiB a mesh file may be");
    std::filesystem::remove(big);
}

// Two PLY files Assimp 5.2 cannot take (found by tests/fuzz/mesh_fuzzer; the inputs are
// tests/fuzz/seeds/mesh/regress_ply_*.ply): without end_header its reader never returns, and a
// file that ends before its faces made it abort the process. Both are one-line errors.
TEST(MeshLoader, RefusesBrokenPlyWithoutHangingOrAborting) {
    const auto dir = std::filesystem::temp_directory_path();
    const char* header =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nelement face 4\nproperty list uchar int vertex_indices\n";
    const std::pair<std::string, std::string> files[] = {
        {"lexel_mesh_loader_no_end.ply", std::string(header) + "0 0 0\n1 0 0\n"},
        {"lexel_mesh_loader_truncated.ply", std::string(header) + "end_header\n0 0 0\n"},
    };
    const std::string reasons[] = {"PLY header without an end_header line",
                                   "face 0 of mesh 0 has no vertices"};
    for (int k = 0; k < 2; ++k) {
        const auto path = dir / files[k].first;
        std::ofstream(path) << files[k].second;
        EXPECT_EQ(LoadError(path), path.string() + ": cannot read mesh: " + reasons[k]);
        std::filesystem::remove(path);
    }
}

// Found by mesh_fuzzer in the campaign (tests/fuzz/seeds/mesh/regress_off_huge_count.off and
// regress_ply_end_header_vtab.ply): a count beyond what a 64-bit integer holds was converted to
// one (undefined behaviour), and "end_header" followed by a vertical tab, which Assimp does not
// take for the token's end, made Assimp read without end.
TEST(MeshLoader, RefusesHugeCountsAndAnEndHeaderAssimpDoesNotSee) {
    const auto dir = std::filesystem::temp_directory_path();
    const auto off = dir / "lexel_mesh_huge.off";
    std::ofstream(off) << "OFF\n4" << std::string(41, '0') << " 1\n0 0 0\n";
    EXPECT_EQ(LoadError(off), off.string() +
                                  ": declares 4e+41 vertices and 1 faces, more than its "
                                  "55 bytes can hold (a truncated or corrupt file)");
    // Assimp reads "36end_header" as 36 (its strtoul10 stops at the first non-digit); the check
    // must too (campaign finding regress_off_count_glued_to_text.off: 2.4 GB allocated).
    const auto glued = dir / "lexel_mesh_glued.off";
    std::ofstream(glued) << "OFF\n402402360 36end_header\n";
    EXPECT_EQ(LoadError(glued), glued.string() +
                                    ": declares 402402360 vertices and 36 faces, more than its 27 "
                                    "bytes can hold (a truncated or corrupt file)");
    std::filesystem::remove(glued);
    // The counts on two lines, and counts glued to the keyword: Assimp reads "OFF8" as the
    // keyword and 8 vertices (campaign findings regress_off_counts_on_two_lines.off and
    // regress_off_count_after_keyword.off, which made Assimp allocate 44 GB).
    const std::pair<std::string, std::string> split[] = {
        {"OFF\n4000000000\n36 0\n", "4000000000 vertices and 36 faces, more than its 20 bytes"},
        {"OFF8\n4000000000 ~00\n", "8 vertices and 4000000000 faces, more than its 20 bytes"},
        {"OFF8000240236 02des [1", "8000240236 vertices and 2 faces, more than its 22 bytes"},
        {"\xEF\xBB\xBF# a comment\nCOFF 900000000 1 0\n",
         "900000000 vertices and 1 faces, more than its 34 bytes"}};
    for (const auto& [text, reason] : split) {
        std::ofstream(glued) << text;
        EXPECT_EQ(LoadError(glued).rfind(glued.string() + ": declares " + reason, 0), 0u)
            << LoadError(glued);
        std::filesystem::remove(glued);
    }
    const auto ply = dir / "lexel_mesh_vtab.ply";
    std::ofstream(ply, std::ios::binary)
        << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\v\n0\n0\n0\n";
    EXPECT_EQ(LoadError(ply),
              ply.string() + ": cannot read mesh: PLY header without an end_header line");
    std::filesystem::remove(off);
    std::filesystem::remove(ply);
}

// Found by mesh_fuzzer in the second campaign, and by reading Assimp 5.2 after it: an element
// line whose count is no number ended the PLY check early, so a count after it went unread
// (regress_ply_count_after_bad_element.ply: 20 GB allocated); a "PLY" magic (Assimp takes any
// case) without end_header, and an end_header after "\r\r" (Assimp skips from the second line
// end to the next '\n'), made Assimp read without end; a UTF-16 OFF file is converted by Assimp
// and is refused here rather than read without its counts checked.
TEST(MeshLoader, ChecksEveryPlyElementAndTheHeaderEndAssimpSees) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string vertices = "element vertex 3\nproperty float x\n";
    const std::pair<std::string, std::string> files[] = {
        {"ply\nformat ascii 1.0\n" + vertices + "element ertex t:ertex 12\n" +
             "element ertex 4000000000\nproperty float y\nend_header\n0\n0\n0\n",
         "declares 4000000015 elements, more than its 139 bytes can hold"},
        {"PLY\nformat ascii 1.0\n" + vertices + "0\n0\n0\n",
         "cannot read mesh: PLY header without an end_header line"},
        {"ply\nformat ascii 1.0\n" + vertices + "comment a\r\rend_header\n0\n0\n0\n",
         "cannot read mesh: PLY header without an end_header line"},
    };
    const auto ply = dir / "lexel_mesh_elements.ply";
    for (const auto& [text, reason] : files) {
        std::ofstream(ply, std::ios::binary) << text;
        EXPECT_EQ(LoadError(ply).rfind(ply.string() + ": " + reason, 0), 0u) << LoadError(ply);
    }
    std::filesystem::remove(ply);
    // With Windows line ends ("\r\n") the header's end is seen and the file read.
    std::ofstream(ply, std::ios::binary)
        << "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y"
           "\r\nproperty float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
           "comment a\r\nend_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
    EXPECT_EQ(LoadMesh(ply).triangles.size(), 1u);
    std::filesystem::remove(ply);
    const auto off = dir / "lexel_mesh_utf16.off";
    std::ofstream(off, std::ios::binary) << std::string("\xFF\xFEO\0F\0F\0\n\0", 10);
    EXPECT_EQ(LoadError(off),
              off.string() + ": is UTF-16 or UTF-32 text (OFF files are read as ASCII or UTF-8)");
    std::filesystem::remove(off);
}

// Found by mesh_fuzzer in the second campaign (regress_ply_list_length.ply): a face whose list
// length reads 1888...8 made Assimp 5.2 reserve 7.6 GB before reading the list, a count in the
// body that no header check sees. Assimp reads under a cap of 64 MiB + 64 bytes a file byte.
TEST(MeshLoader, RefusesABodyCountPastTheReadingCap) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n";
    const auto ply = std::filesystem::temp_directory_path() / "lexel_mesh_list_length.ply";
    std::ofstream(ply, std::ios::binary) << header << "1888888888 0 1 2\n";
    EXPECT_EQ(LoadError(ply), ply.string() +
                                  ": cannot read mesh: reading it needs more than 64 MiB (a "
                                  "count in the file larger than its data)");
    std::ofstream(ply, std::ios::binary) << header << "3 0 1 2\n";
    EXPECT_EQ(LoadMesh(ply).triangles.size(), 1u);
    std::filesystem::remove(ply);
}

}  // namespace
}  // namespace lexel::spatial
