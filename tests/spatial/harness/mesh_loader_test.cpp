// Mesh loading through Assimp, on the models of Debian's assimp-testmodels package.
#include "lexel/spatial/harness/mesh_loader.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_file_check.h"
#include "scratch_directory.h"

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
    for (const glm::dvec3& p : mesh.positions)
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
        {"OBJ/WusonOBJ.obj", 3700, 3800, 3.0, 3.5},
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

TEST(MeshLoader, WusonIsTheSameInObjAndStl) {
    if (!ModelsInstalled()) return;
    // Two exports of one model: the same triangles within the formats' float precision.
    const TriangleMesh obj = LoadMesh(kModels / "OBJ/WusonOBJ.obj");
    const TriangleMesh stl = LoadMesh(kModels / "STL/Wuson.stl");
    EXPECT_EQ(obj.triangles.size(), 3732u);
    EXPECT_EQ(stl.triangles.size(), obj.triangles.size());
    const Bounds objBounds = obj.ComputeBounds(), stlBounds = stl.ComputeBounds();
    EXPECT_NEAR(glm::distance(stlBounds.lo, objBounds.lo), 0.0, 1e-4);
    EXPECT_NEAR(glm::distance(stlBounds.hi, objBounds.hi), 0.0, 1e-4);
    // Wuson stands on y = 0 (its lowest point is 0.000566 below).
    EXPECT_NEAR(objBounds.lo.y, 0.0, 1e-3);
    EXPECT_NEAR(objBounds.hi.y, 1.51525, 1e-4);
}

TEST(MeshLoader, RejectsInvalidFilesNamingThem) {
    if (!ModelsInstalled()) return;
    std::vector<std::filesystem::path> invalid;
    for (const auto& entry : std::filesystem::directory_iterator(kModels / "invalid"))
        if (entry.path().extension() == ".obj" && entry.path().filename() != "malformed2.obj")
            invalid.push_back(entry.path());
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
    EXPECT_EQ(
        LoadError(std::filesystem::temp_directory_path()),
        std::filesystem::temp_directory_path().string() + ": is a directory, not a mesh file");
    const auto garbage = std::filesystem::temp_directory_path() / "lexel_mesh_loader_garbage.obj";
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
// 309 bytes) took gigabytes in seconds. The declared counts are held against the size.
TEST(MeshLoader, RefusesDeclaredCountsTheFileCannotHold) {
    if (!ModelsInstalled()) return;
    const auto oom = kModels / "invalid/OutOfMemory.off";
    EXPECT_EQ(LoadError(oom), oom.string() +
                                  ": declares 353535235358 vertices and 6 faces, more than its 309 "
                                  "bytes can hold (a truncated or corrupt file)");
    const auto dir = std::filesystem::temp_directory_path();
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
              threeDs.string() +
                  ": format '.3ds' is not read (mesh formats: obj, off, stl, ply, gltf, glb)");
    // A sparse file one byte over the cap: refused from its size, never read.
    const auto big = std::filesystem::temp_directory_path() / "lexel_mesh_check_big.obj";
    std::ofstream(big, std::ios::binary).close();
    std::filesystem::resize_file(big, kMaxMeshFileBytes + 1);
    EXPECT_EQ(LoadError(big),
              big.string() + ": is 67108865 bytes, larger than the 64 MiB a mesh file may be");
    std::filesystem::remove(big);
}

// PLY was refused while Assimp 5.2 read it: its PLY reader hung without end_header and aborted on
// a truncated file (tests/fuzz/seeds/mesh/regress_ply_*.ply), reserved 20 GB for a count after an
// element line without one and 7.6 GB for a face's list length. lexel's own reader reads the
// package's PLY files (mesh_ply_reader_test.cpp) and refuses the malformed ones in one line.
TEST(MeshLoader, ReadsPlyThroughItsOwnReader) {
    if (!ModelsInstalled()) return;
    EXPECT_EQ(LoadMesh(kModels / "PLY/cube_binary.ply").triangles.size(), 12u);
    const auto empty = kModels / "invalid/empty.ply";
    EXPECT_EQ(LoadError(empty),
              empty.string() + ": cannot read PLY: not a PLY file: its first line is not 'ply'");
}

// Found by mesh_fuzzer in the campaigns (tests/fuzz/seeds/mesh/regress_off_*.off): a count beyond
// what a 64-bit integer holds was converted to one (undefined behaviour), and counts Assimp reads
// where a line-by-line reading does not look let it allocate gigabytes.
TEST(MeshLoader, RefusesHugeOffCountsWhereAssimpReadsThem) {
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
    std::filesystem::remove(off);
}

// Found by review of Assimp 5.2 (ParsingUtils.h, BaseImporter.cpp): the OFF reader's line buffer
// holds 4095 bytes and a longer line overflows it by one; text marked as UTF-16 or UTF-32 is
// converted into a buffer Assimp then discards, reading up to 3 bytes past the file.
TEST(MeshLoader, RefusesLongOffLinesAndUtf16Or32Text) {
    const auto dir = std::filesystem::temp_directory_path();
    const auto off = dir / "lexel_mesh_long_line.off";
    const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2";
    std::ofstream(off) << "OFF\n3 1 0\n" << body << std::string(4095 - 7, ' ') << "\n";
    EXPECT_EQ(LoadError(off), "no error");  // a line of 4095 bytes is read
    std::ofstream(off) << "OFF\n3 1 0\n" << body << std::string(4096 - 7, ' ') << "\n";
    EXPECT_EQ(LoadError(off), off.string() +
                                  ": has a line of 4096 bytes; Assimp 5.2 reads OFF lines of at "
                                  "most 4095");
    std::filesystem::remove(off);
    using namespace std::string_literals;
    const std::pair<std::string, std::string> marked[] = {
        {"lexel_mesh_utf16le.off", "\xFF\xFEO\0F\0F\0\n\0"s},
        {"lexel_mesh_utf16be.stl", "\xFE\xFF\0s\0o\0l\0i\0d"s},
        {"lexel_mesh_utf32le.obj", "\xFF\xFE\0\0v\0\0\0"s},
        {"lexel_mesh_utf32be.off", "\0\0\xFE\xFF\0\0\0O"s},
    };
    for (const auto& [name, text] : marked) {
        const auto path = dir / name;
        std::ofstream(path, std::ios::binary) << text;
        EXPECT_EQ(LoadError(path), path.string() +
                                       ": is UTF-16 or UTF-32 text, which Assimp 5.2 does not "
                                       "read (save it as ASCII or UTF-8)");
        std::filesystem::remove(path);
    }
}

// A fresh directory for one test, removed afterwards.
struct ScratchDirectory : test::ScratchDirectory {
    ScratchDirectory() : test::ScratchDirectory("lexel_mesh_paths") {}
};

// A mesh path that is not a regular file says what it is (before: "mesh file not
// found" for all of them), and nothing is opened to find out.
TEST(MeshLoader, RefusesPathsThatAreNotRegularFilesSayingWhatTheyAre) {
    const ScratchDirectory scratch;
    ASSERT_FALSE(scratch.Path().empty());
    const auto dir = scratch.Path() / "model.obj";
    std::filesystem::create_directory(dir);
    const auto fifo = scratch.Path() / "pipe.obj";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto dangling = scratch.Path() / "dangling.obj";
    std::filesystem::create_symlink(scratch.Path() / "gone.obj", dangling);
    EXPECT_EQ(LoadError(dir), dir.string() + ": is a directory, not a mesh file");
    EXPECT_EQ(LoadError(fifo), fifo.string() + ": is a FIFO (named pipe), not a mesh file");
    EXPECT_EQ(LoadError("/dev/null"), "/dev/null: is a character device, not a mesh file");
    EXPECT_EQ(LoadError(dangling),
              dangling.string() + ": is a dangling symbolic link (mesh file not found)");
}

// A side file outside the mesh's folder (an absolute mtllib, "../", a system file) is absent to
// the reader whatever the mesh's path spelling. Before: with a bare file name Assimp opened the
// absolute mtllib itself (a FIFO refused the mesh, a system file's first line reached the error
// message), while "./x.obj" or an absolute path joined it to the folder and loaded the mesh.
TEST(MeshLoader, ASideFileOutsideTheMeshsFolderIsAbsentWhateverThePathSpelling) {
    const ScratchDirectory scratch;
    ASSERT_FALSE(scratch.Path().empty());
    const auto folder = scratch.Path() / "model";
    std::filesystem::create_directories(folder);
    const auto fifo = scratch.Path() / "pipe.mtl";  // outside the model's folder
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const char* triangle = "v -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(folder / "absolute.obj") << "mtllib " << fifo.string() << "\n" << triangle;
    std::ofstream(folder / "parent.obj") << "mtllib ../pipe.mtl\n" << triangle;
    std::ofstream(folder / "system.obj") << "mtllib /etc/passwd\n" << triangle;
    const std::filesystem::path before = std::filesystem::current_path();
    std::filesystem::current_path(folder);
    for (const char* name : {"absolute.obj", "parent.obj", "system.obj"})
        for (const std::filesystem::path& spelling :
             {std::filesystem::path(name), std::filesystem::path(".") / name, folder / name})
            EXPECT_EQ(LoadError(spelling), "no error") << spelling;
    std::filesystem::current_path(before);
}

// An OBJ whose mtllib names a FIFO hung for ever (Assimp's default file system opened
// it and waited for a writer). Now only regular files are opened, and the mesh is refused naming
// what it would have opened. A watchdog opens the FIFO's write end after 10 s, which would free a
// loader blocked on it, so the old behaviour fails the test instead of hanging it.
TEST(MeshLoader, NeverOpensAFifoOrDirectoryAnObjNames) {
    const ScratchDirectory scratch;
    ASSERT_FALSE(scratch.Path().empty());
    const auto fifo = scratch.Path() / "pipe.mtl";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::filesystem::create_directory(scratch.Path() / "folder.mtl");
    const char* triangle = "v -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const auto obj = scratch.Path() / "names_fifo.obj";
    std::ofstream(obj) << "mtllib pipe.mtl\n" << triangle;
    const auto objDir = scratch.Path() / "names_folder.obj";
    std::ofstream(objDir) << "mtllib folder.mtl\n" << triangle;

    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::thread watchdog([&] {
        std::unique_lock lock(mutex);
        if (finished.wait_for(lock, std::chrono::seconds(10), [&] { return done; })) return;
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) ::close(fd);
    });
    const std::string fifoError = LoadError(obj);
    {
        const std::lock_guard lock(mutex);
        done = true;
    }
    finished.notify_all();
    watchdog.join();
    EXPECT_EQ(fifoError, obj.string() + ": cannot read mesh: reading it would open " +
                             fifo.string() + ", a FIFO (named pipe); only regular files are read");
    EXPECT_EQ(LoadError(objDir), objDir.string() + ": cannot read mesh: reading it would open " +
                                     (scratch.Path() / "folder.mtl").string() +
                                     ", a directory; only regular files are read");
    // A missing material library is no error (Assimp uses a default material).
    const auto objMissing = scratch.Path() / "names_missing.obj";
    std::ofstream(objMissing) << "mtllib missing.mtl\n" << triangle;
    EXPECT_EQ(LoadError(objMissing), "no error");
}

// Assimp 5.2 reads an OFF face's indices with strtoul10 and clamps the ones past the
// vertices, so "-1" became vertex 0 and "7" of 3 vertices the last one, silently (the same in OBJ
// is refused). Now each is refused naming the face, its line and the index.
TEST(MeshLoader, RefusesOffFaceIndicesThatAreNoVertex) {
    const ScratchDirectory scratch;
    ASSERT_FALSE(scratch.Path().empty());
    // Line 1 OFF, 2 a comment, 3 the counts, 4-6 vertices (a blank line between), then faces.
    const std::string head = "OFF\n# a triangle\n3 2 0\n0 0 0\n1 0 0\n\n0 1 0\n";
    const std::pair<std::string, std::string> refused[] = {
        {"3 0 1 2\n3 0 1 7\n",
         "face 1 (line 9): vertex index 2 is 7, past the file's 3 vertices "
         "(0 to 2)"},
        {"3 0 -1 2\n3 0 1 2\n",
         "face 0 (line 8): vertex index 1 is negative; OFF indices count vertices from 0"},
        {"3 0 1 2\n3 0 1\n", "face 1 (line 9) lists 2 of its 3 vertex indices"},
        {"3 0 1 2\n3 0 1 # 2\n", "face 1 (line 9) lists 2 of its 3 vertex indices"},
        {"3 0 x 2\n3 0 1 2\n",
         "face 0 (line 8): vertex index 1 is not a number ('x'); OFF indices count vertices from "
         "0"},
        // Assimp's unsigned int wraps 4294967296 to 0.
        {"3 0 1 2\n3 4294967296 1 2\n",
         "face 1 (line 9): vertex index 0 is 4294967296, past the file's 3 vertices (0 to 2)"},
    };
    const auto off = scratch.Path() / "faces.off";
    for (const auto& [faces, reason] : refused) {
        SCOPED_TRACE(faces);
        std::ofstream(off) << head << faces;
        EXPECT_EQ(LoadError(off), off.string() + ": " + reason);
    }
    // Lines Assimp drops among the faces, miscounting them (its 5.2 lost the face after a
    // comment line, and the file read as 0 faces when the dropped lines followed the last one).
    const std::string dropped =
        ": not a face of 1 to 9 vertices (Assimp 5.2 drops such a line and miscounts the faces "
        "after it)";
    for (const char* faces :
         {"# a comment\n3 0 1 2\n3 0 2 1\n", "3 0 1 2\n0\n", "3 0 1 2\n10 0 1 2 0 1 2 0 1 2 0\n"}) {
        SCOPED_TRACE(faces);
        std::ofstream(off) << head << faces;
        EXPECT_EQ(LoadError(off), off.string() + ": face " +
                                      (faces[0] == '#' ? "0 (line 8)" : "1 (line 9)") + dropped);
    }
    // Extra numbers after the indices (colours) and lines after the declared faces are no error.
    std::ofstream(off) << head << "3 0 1 2 255 0 0\n3 0 2 1\n# the end\n";
    EXPECT_EQ(LoadError(off), "no error");
}

}  // namespace
}  // namespace lexel::spatial
