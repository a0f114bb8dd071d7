// lexel's PLY reader: the same mesh in the three encodings, polygons, element orders, real files of
// Debian's assimp-testmodels against their OBJ twins, and one-line refusals of malformed headers
// and bodies (CGAL 5.5's reader crashed on three of them, see mesh_ply_reader.h).
#include "lexel/spatial/harness/mesh_ply_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_loader.h"
#include "lexel/spatial/harness/primitives.h"

namespace lexel::spatial {
namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models";

std::string PlyError(const std::string& bytes) {
    try {
        ReadPlyMesh(bytes);
    } catch (const DomainError& e) {
        return e.what();
    }
    return "no error";
}

// A tetrahedron with what the reader must skip: a normal, a colour, a list of texture
// coordinates per vertex, an `edge` element, and a face flag after the index list.
const std::vector<glm::vec3> kTetra = {{0, 0, 0}, {1.5f, 0, 0}, {0, 2.25f, 0}, {0, 0, -3}};
const std::vector<std::vector<int>> kTetraFaces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};

std::string TetraHeader(const char* format) {
    return std::string("ply\nformat ") + format +
           " 1.0\ncomment made by lexel's tests\nelement vertex 4\nproperty float x\nproperty "
           "float y\nproperty float z\nproperty float nx\nproperty uchar red\nproperty list "
           "uchar float uv\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nelement "
           "face 4\nproperty list uchar int vertex_indices\nproperty short flags\nend_header\n";
}

std::string TetraAscii() {
    std::string text = TetraHeader("ascii");
    for (const glm::vec3& p : kTetra)
        text += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) +
                " -1.0 255 2 0.5 0.25\n";
    text += "0 1\n";
    for (const auto& f : kTetraFaces)
        text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " +
                std::to_string(f[2]) + " -7\n";
    return text;
}

// Appends a value in the given byte order.
template <class T>
void Put(std::string& bytes, T value, bool bigEndian) {
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), &value, sizeof(T));
    if (bigEndian != (std::endian::native == std::endian::big))
        std::reverse(raw.begin(), raw.end());
    bytes.append(raw.data(), raw.size());
}

std::string TetraBinary(bool bigEndian) {
    std::string bytes = TetraHeader(bigEndian ? "binary_big_endian" : "binary_little_endian");
    for (const glm::vec3& p : kTetra) {
        for (int k = 0; k < 3; ++k) Put<float>(bytes, p[k], bigEndian);
        Put<float>(bytes, -1.0f, bigEndian);
        Put<std::uint8_t>(bytes, 255, bigEndian);
        Put<std::uint8_t>(bytes, 2, bigEndian);
        Put<float>(bytes, 0.5f, bigEndian);
        Put<float>(bytes, 0.25f, bigEndian);
    }
    Put<std::int32_t>(bytes, 0, bigEndian);
    Put<std::int32_t>(bytes, 1, bigEndian);
    for (const auto& f : kTetraFaces) {
        Put<std::uint8_t>(bytes, 3, bigEndian);
        for (const int v : f) Put<std::int32_t>(bytes, v, bigEndian);
        Put<std::int16_t>(bytes, -7, bigEndian);
    }
    return bytes;
}

void ExpectTetra(const TriangleMesh& mesh) {
    ASSERT_EQ(mesh.positions.size(), 4u);
    for (std::size_t v = 0; v < 4; ++v)
        EXPECT_EQ(mesh.positions[v], glm::dvec3(kTetra[v])) << "vertex " << v;
    ASSERT_EQ(mesh.triangles.size(), 4u);
    for (std::size_t t = 0; t < 4; ++t)
        EXPECT_EQ(mesh.triangles[t],
                  glm::uvec3(kTetraFaces[t][0], kTetraFaces[t][1], kTetraFaces[t][2]));
    // Outward winding: the volume of the tetrahedron 1.5 · 2.25 · 3 / 6.
    EXPECT_DOUBLE_EQ(SignedVolume(mesh), 1.6875);
}

TEST(PlyReader, ReadsTheSameTetrahedronInEveryEncoding) {
    ExpectTetra(ReadPlyMesh(TetraAscii()));
    ExpectTetra(ReadPlyMesh(TetraBinary(false)));
    ExpectTetra(ReadPlyMesh(TetraBinary(true)));
    EXPECT_EQ(ReadPlyEncoding(TetraAscii()), PlyEncoding::kAscii);
    EXPECT_EQ(ReadPlyEncoding(TetraBinary(false)), PlyEncoding::kBinaryLittleEndian);
    EXPECT_EQ(ReadPlyEncoding(TetraBinary(true)), PlyEncoding::kBinaryBigEndian);
    // Windows line ends in the header and the body.
    std::string crlf;
    for (const char c : TetraAscii()) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    ExpectTetra(ReadPlyMesh(crlf));
}

TEST(PlyReader, FansPolygonsAndDropsPointsAndLines) {
    const TriangleMesh mesh = ReadPlyMesh(
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
        "property double z\nelement face 4\nproperty list uchar uint vertex_index\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 2 0\n4 0 1 2 3\n2 0 1\n1 4\n5 0 1 2 4 3\n");
    const std::vector<glm::uvec3> expected = {
        {0, 1, 2}, {0, 2, 3}, {0, 1, 2}, {0, 2, 4}, {0, 4, 3}};
    EXPECT_EQ(mesh.triangles, expected);
}

// CGAL's reader dereferenced null on integer coordinates; the face element may come first.
TEST(PlyReader, ReadsIntegerCoordinatesAndFacesBeforeVertices) {
    const TriangleMesh mesh = ReadPlyMesh(
        "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
        "element vertex 3\nproperty int x\nproperty short y\nproperty char z\nend_header\n"
        "3 0 1 2\n-5 0 0\n7 32767 0\n0 0 -128\n");
    ASSERT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.positions[0], glm::dvec3(-5, 0, 0));
    EXPECT_EQ(mesh.positions[1], glm::dvec3(7, 32767, 0));
    EXPECT_EQ(mesh.positions[2], glm::dvec3(0, 0, -128));
    EXPECT_EQ(mesh.triangles, std::vector<glm::uvec3>{glm::uvec3(0, 1, 2)});
}

// CGAL's reader looped for ever over an element of no properties and a huge count; nothing of such
// an element is written, so it is passed over at once.
TEST(PlyReader, PassesOverAnElementWithoutPropertiesAtOnce) {
    std::string text = TetraAscii();
    text.insert(text.find("element face"), "element nothing 18446744073709551615\n");
    const auto start = std::chrono::steady_clock::now();
    ExpectTetra(ReadPlyMesh(text));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// A header of `properties` properties on one element (and a tetrahedron after it): its reading
// time. Before: each property was compared with every earlier one, O(n^2) (200k properties: 67 s).
double HeaderSeconds(std::size_t properties) {
    std::string text = "ply\nformat ascii 1.0\nelement extra 0\n";
    for (std::size_t p = 0; p < properties; ++p)
        text += "property float p" + std::to_string(p) + "\n";
    const std::string tetra = TetraAscii();
    text += tetra.substr(tetra.find("element"));
    // This thread's CPU time, not the wall clock: other work on the machine (the suite runs two
    // tests at once on two cores) does not count.
    const auto cpuSeconds = [] {
        timespec t{};
        ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    };
    const double start = cpuSeconds();
    ExpectTetra(ReadPlyMesh(text));
    return cpuSeconds() - start;
}

// Ten times the properties take ten times as long and more (the larger header's strings no
// longer fit the caches): under 30 times on an idle machine, 31 to 35 beside three busy processes
// on two cores, the least of five tries each in CPU time. Quadratic growth takes a hundred times
// as long (the reader before: 0.67 s and 67 s).
TEST(PlyReader, ReadsAHeaderInTimeLinearInItsProperties) {
    double small = 1e9, large = 1e9;
    for (int trial = 0; trial < 5; ++trial) {
        small = std::min(small, HeaderSeconds(20000));
        large = std::min(large, HeaderSeconds(200000));
    }
    EXPECT_LT(large / small, 60.0)
        << "20000 properties " << small << " s, 200000 " << large << " s";
}

struct BadPly {
    const char* what;
    std::string bytes;
    std::string error;
};

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";
const std::string kFace = "element face 1\nproperty list uchar int vertex_indices\n";
const std::string kAsciiHead = "ply\nformat ascii 1.0\nelement vertex 3\n" + kXyz;

TEST(PlyReader, RefusesMalformedHeadersInOneLine) {
    const std::vector<BadPly> cases = {
        {"no magic", "solid x\n", "not a PLY file: its first line is not 'ply'"},
        {"no format", "ply\nelement vertex 1\n",
         "header line 2: an element before the format line"},
        {"format", "ply\nformat utf8 1.0\n",
         "header line 2: format 'utf8' is not ascii, binary_little_endian or binary_big_endian"},
        {"version", "ply\nformat ascii 2.0\n",
         "header line 2: PLY version '2.0' (lexel reads version 1.0)"},
        // CGAL's reader crashed on this one (the back of an empty vector).
        {"property first", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\n",
         "header line 3: a property before any element"},
        {"type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty int64 x\n",
         "header line 4: unknown property type 'int64' (PLY types: char, uchar, short, ushort, "
         "int, uint, float, double, or int8 ... float64)"},
        {"list length type",
         "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n",
         "header line 4: a list's length type must be an integer type, got 'float'"},
        {"second vertex element", kAsciiHead + "element vertex 3\n",
         "header line 7: a second 'vertex' element (a PLY file has one)"},
        {"property twice", kAsciiHead + "property float x\n",
         "header line 7: element 'vertex' declares property 'x' twice"},
        {"unknown keyword", kAsciiHead + "propety float w\n",
         "header line 7: unknown keyword 'propety' (header lines: format, comment, obj_info, "
         "element, property, end_header)"},
        {"count", "ply\nformat ascii 1.0\nelement vertex -1\n",
         "header line 3: element count '-1' is not an integer from 0 to 2^64 - 1"},
        {"no end_header", kAsciiHead + kFace, "the header has no end_header line"},
        {"counts", kAsciiHead + kFace + "end_header\n0 0 0\n",
         "element 'vertex' declares 3 items, more than the 6 bytes after the header can hold "
         "(a truncated or corrupt file)"},
        {"no z",
         "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n" + kFace +
             "end_header\n0 0\n3 0 0 0\n",
         "element 'vertex' has no property 'z'"},
        {"no indices",
         kAsciiHead + "element face 1\nproperty int n\nend_header\n0 0 0 0 0 0 0 0 0 1\n",
         "element 'face' has no list property 'vertex_indices' or 'vertex_index'"},
        {"float indices",
         kAsciiHead + "element face 1\nproperty list uchar float vertex_indices\nend_header\n" +
             "0 0 0 1 0 0 0 1 0 3 0 1 2\n",
         "face property 'vertex_indices' must be a list of an integer type (property list uchar "
         "int vertex_indices)"},
        {"no vertex", "ply\nformat ascii 1.0\nend_header\n", "the file has no vertex element"},
    };
    for (const BadPly& c : cases) EXPECT_EQ(PlyError(c.bytes), c.error) << c.what;
}

TEST(PlyReader, RefusesMalformedBodiesInOneLine) {
    const std::string head = kAsciiHead + kFace + "end_header\n";
    const std::string little =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz +
        "element face 1\nproperty list char int vertex_indices\nend_header\n";
    std::string vertices;
    for (int k = 0; k < 9; ++k) Put<float>(vertices, float(k % 4 == 0), false);
    std::string negative = little + vertices;
    Put<std::int8_t>(negative, -1, false);
    negative += std::string(12, '\0');
    std::string truncated = little + vertices;
    Put<std::int8_t>(truncated, 3, false);
    Put<std::int32_t>(truncated, 0, false);
    std::string trailing = little + vertices;
    Put<std::int8_t>(trailing, 3, false);
    for (int v = 0; v < 3; ++v) Put<std::int32_t>(trailing, v, false);
    trailing += "junk";
    const std::vector<BadPly> cases = {
        {"not a number", head + "0 0 0\n1 0 0\n0 abc 0\n3 0 1 2\n",
         "vertex 2 of 3, property 'y' (line 12): 'abc' is not a number of type float"},
        {"not an integer", head + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n",
         "face 0 of 1, property 'vertex_indices' (line 13): '1.5' is not an integer of type int"},
        {"index past", head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
         "face 0 of 1, property 'vertex_indices' (line 13): vertex index 3 is past the file's 3 "
         "vertices"},
        {"index negative", head + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
         "face 0 of 1, property 'vertex_indices' (line 13): vertex index -1 is negative"},
        {"uchar range", head + "0 0 0\n1 0 0\n0 1 0\n256 0 1 2\n",
         "face 0 of 1, property 'vertex_indices' (line 13): '256' is not an integer of type uchar"},
        {"nan", head + "0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n",
         "vertex 2 of 3, property 'x' (line 12): the coordinate is nan, not a finite float"},
        {"beyond float", head + "0 0 0\n1 0 0\n1e39 1 0\n3 0 1 2\n",
         "vertex 2 of 3, property 'x' (line 12): '1e39' is beyond the range of a float"},
        {"ascii trailing", head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n4\n",
         "line 14: data after the last element ('4'): the header does not describe the file"},
        {"ascii truncated", head + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
         "face 0 of 1, property 'vertex_indices' (line 14): the file ends here (a truncated "
         "file)"},
        // CGAL's reader threw std::length_error for this one (the length cast to size_t).
        {"negative length", negative,
         "face 0 of 1, property 'vertex_indices' (byte 205): its index list has the negative "
         "length -1"},
        {"binary truncated", truncated,
         "face 0 of 1, property 'vertex_indices' (byte 209): the file ends here (a truncated "
         "file)"},
        {"binary trailing", trailing,
         "4 bytes follow the last element: the header does not describe the file"},
        // Found by ply_fuzzer: a NUL in a name ended the message (what() is a C string), and
        // the loader, finding it empty, took the refusal for running out of memory.
        {"name with NUL",
         kAsciiHead + std::string("element \0\x1b 1\nproperty int n\n", 28) +
             "end_header\n0 0 0\n1 0 0\n0 1 0\nx\n",
         "?? 0 of 1, property 'n' (line 13): 'x' is not an integer of type int"},
        {"no triangles", head + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
         "it holds no triangles (no face of 3 or more vertices)"},
    };
    for (const BadPly& c : cases) EXPECT_EQ(PlyError(c.bytes), c.error) << c.what;
}

// Each triangle as its three corners, turned to start at the smallest (winding kept), sorted.
std::vector<std::array<float, 9>> CanonicalTriangles(const TriangleMesh& mesh) {
    std::vector<std::array<float, 9>> out;
    for (const glm::uvec3& t : mesh.triangles) {
        // Compared in float: Assimp reads OBJ positions as float.
        std::array<glm::vec3, 3> c = {glm::vec3(mesh.positions[t.x]),
                                      glm::vec3(mesh.positions[t.y]),
                                      glm::vec3(mesh.positions[t.z])};
        const auto less = [](const glm::vec3& a, const glm::vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        };
        std::rotate(c.begin(), std::min_element(c.begin(), c.end(), less), c.end());
        out.push_back({c[0].x, c[0].y, c[0].z, c[1].x, c[1].y, c[1].z, c[2].x, c[2].y, c[2].z});
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Wuson as Blender 2.47 wrote it in PLY (whose comment line lacks the keyword) and as OBJ, read by
// Assimp: the same 3732 triangles, corner for corner.
TEST(PlyReader, WusonMatchesItsObjTwinReadByAssimp) {
    ASSERT_TRUE(std::filesystem::is_directory(kModels)) << "install assimp-testmodels";
    const LoadedMesh ply = LoadMeshFile(kModels / "PLY/Wuson.ply");
    const TriangleMesh obj = LoadMesh(kModels / "OBJ/WusonOBJ.obj");
    EXPECT_EQ(ply.format, "PLY (ASCII)");
    ASSERT_EQ(ply.mesh.triangles.size(), 3732u);
    // Both files print 6 decimals; lexel parses them correctly rounded (std::from_chars), Assimp's
    // fast_atof is off by one float step in places (1.2e-7 at these magnitudes, below 2).
    const auto plyTriangles = CanonicalTriangles(ply.mesh), objTriangles = CanonicalTriangles(obj);
    ASSERT_EQ(plyTriangles.size(), objTriangles.size());
    double worst = 0;
    for (std::size_t t = 0; t < plyTriangles.size(); ++t)
        for (int k = 0; k < 9; ++k)
            worst = std::max(worst, double(std::abs(plyTriangles[t][k] - objTriangles[t][k])));
    EXPECT_LE(worst, 0x1p-23);
}

// VCGLib's binary cube: closed and outward, volume 1.
TEST(PlyReader, VcgBinaryCubeIsTheUnitCube) {
    ASSERT_TRUE(std::filesystem::is_directory(kModels)) << "install assimp-testmodels";
    const LoadedMesh cube = LoadMeshFile(kModels / "PLY/cube_binary.ply");
    EXPECT_EQ(cube.format, "PLY (binary little-endian)");
    EXPECT_EQ(cube.mesh.triangles.size(), 12u);
    const Bounds bounds = cube.mesh.ComputeBounds();
    EXPECT_EQ(bounds.lo, glm::dvec3(0.0));
    EXPECT_EQ(bounds.hi, glm::dvec3(1.0));
    EXPECT_DOUBLE_EQ(SignedVolume(cube.mesh), 1.0);
}

std::string LoadError(const std::filesystem::path& path) {
    try {
        LoadMesh(path);
    } catch (const DomainError& e) {
        return e.what();
    }
    return "no error";
}

// The package's malformed PLY files, and the inputs on which Assimp's PLY reader failed (the
// mesh_fuzzer seeds): each refused in one line naming the file.
TEST(PlyReader, RefusesMalformedFilesInOneLineNamingThem) {
    ASSERT_TRUE(std::filesystem::is_directory(kModels)) << "install assimp-testmodels";
    const auto issue623 = kModels / "PLY/issue623.ply";
    EXPECT_EQ(LoadError(issue623), issue623.string() +
                                       ": cannot read PLY: vertex 0 of 24, property "
                                       "'vertex_indices' (line 14): '7.941797' is not an "
                                       "integer of type uchar");
    const auto pond = kModels / "PLY/pond.0.ply";  // 69 bytes short of its 70051 vertices
    EXPECT_EQ(LoadError(pond), pond.string() +
                                   ": cannot read PLY: element 'vertex' declares 70051 items, "
                                   "more than the 2171512 bytes after the header can hold (a "
                                   "truncated or corrupt file)");
    const std::filesystem::path seeds =
        std::filesystem::path(LEXEL_CASES_DIR) / "../tests/fuzz/seeds/mesh";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
        if (entry.path().extension() != ".ply" || entry.path().stem() == "tetra") continue;
        const std::string error = LoadError(entry.path());
        EXPECT_TRUE(error.starts_with(entry.path().string() + ": cannot read PLY: ")) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        ++files;
    }
    EXPECT_EQ(files, 9);
}

}  // namespace
}  // namespace lexel::spatial
