// glTF 2.0 through tinygltf: Khronos's samples in Debian's assimp-testmodels against Assimp's own
// glTF 2 importer, node transforms and instances against their closed forms, the default scene,
// strips, fans, sparse accessors, buffer files, and one-line refusals.
#include "lexel/spatial/harness/mesh_gltf_reader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_loader.h"

namespace lexel::spatial {
namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models/glTF2";

std::string Base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto byte = [&](std::size_t i) -> std::uint32_t {
        return i < bytes.size() ? std::uint8_t(bytes[i]) : 0;
    };
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
        const std::size_t have = std::min<std::size_t>(3, bytes.size() - i);
        for (std::size_t k = 0; k < 4; ++k)
            out += k <= have ? digits[(n >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// A glTF document of one buffer (embedded as a data: URI) holding `positions` then `indices`
// (unsigned int), one mesh of one primitive over them, and one node showing it; tests edit it.
struct Document {
    nlohmann::json json;
    std::string buffer;
};

Document OnePrimitive(const std::vector<glm::vec3>& positions,
                      const std::vector<std::uint32_t>& indices, int mode = 4) {
    Document d;
    d.buffer.resize(12 * positions.size() + 4 * indices.size());
    std::memcpy(d.buffer.data(), positions.data(), 12 * positions.size());
    if (!indices.empty())  // memcpy from an empty vector's null data is undefined
        std::memcpy(d.buffer.data() + 12 * positions.size(), indices.data(), 4 * indices.size());
    nlohmann::json primitive = {{"attributes", {{"POSITION", 0}}}, {"mode", mode}};
    nlohmann::json accessors = {{{"bufferView", 0},
                                 {"componentType", 5126},
                                 {"count", positions.size()},
                                 {"type", "VEC3"}}};
    nlohmann::json views = {
        {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 12 * positions.size()}}};
    if (!indices.empty()) {
        primitive["indices"] = 1;
        accessors.push_back({{"bufferView", 1},
                             {"componentType", 5125},
                             {"count", indices.size()},
                             {"type", "SCALAR"}});
        views.push_back({{"buffer", 0},
                         {"byteOffset", 12 * positions.size()},
                         {"byteLength", 4 * indices.size()}});
    }
    d.json = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"meshes", {{{"primitives", {primitive}}}}},
              {"accessors", accessors},
              {"bufferViews", views},
              {"buffers", {{{"byteLength", d.buffer.size()}}}}};
    return d;
}

std::string Text(const Document& d) {
    nlohmann::json json = d.json;
    if (!json["buffers"][0].contains("uri"))
        json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + Base64(d.buffer);
    return json.dump();
}

TriangleMesh Read(const Document& d) {
    const std::string text = Text(d);
    return ReadGltfMesh(text, false, "", FindGltfBufferFiles(text, false, ""));
}

std::string ReadError(const std::string& text, bool binary = false,
                      const std::filesystem::path& dir = "") {
    try {
        ReadGltfMesh(text, binary, dir, FindGltfBufferFiles(text, binary, dir));
    } catch (const DomainError& e) {
        return e.what();
    }
    return "no error";
}

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

void ExpectNear(const glm::dvec3& a, const glm::dvec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-6);
    EXPECT_NEAR(a.y, b.y, 1e-6);
    EXPECT_NEAR(a.z, b.z, 1e-6);
}

// Node a: translation (10, 0, 0) above node b: scale 2 and a quarter turn about +y (the quaternion
// (0, sin 45°, 0, cos 45°)) showing the mesh; node c: a column-major matrix translating by
// (0, 0, 5) showing it again. p ↦ T_a · R · S · p and p ↦ p + (0, 0, 5).
TEST(GltfReader, ComposesNodeTransformsAndPlacesEveryInstance) {
    Document d = OnePrimitive(kTriangle, {0, 1, 2});
    const double h = std::sqrt(0.5);
    d.json["scenes"][0]["nodes"] = {1, 2};
    d.json["nodes"] = {{{"mesh", 0}, {"scale", {2, 2, 2}}, {"rotation", {0, h, 0, h}}},
                       {{"translation", {10, 0, 0}}, {"children", {0}}},
                       {{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}}};
    const TriangleMesh mesh = Read(d);
    ASSERT_EQ(mesh.positions.size(), 6u);
    ASSERT_EQ(mesh.triangles.size(), 2u);
    // R_y(90°) takes +x to −z: (1, 0, 0) ↦ 2 · (0, 0, −1) + (10, 0, 0).
    ExpectNear(mesh.positions[0], {10, 0, 0});
    ExpectNear(mesh.positions[1], {10, 0, -2});
    ExpectNear(mesh.positions[2], {10, 2, 0});
    ExpectNear(mesh.positions[3], {0, 0, 5});
    ExpectNear(mesh.positions[4], {1, 0, 5});
    ExpectNear(mesh.positions[5], {0, 1, 5});
    EXPECT_EQ(mesh.triangles[1], glm::uvec3(3, 4, 5));
}

TEST(GltfReader, ReadsTheDefaultSceneOnly) {
    Document d = OnePrimitive(kTriangle, {});
    d.json["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
    d.json["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 7, 0}}}};
    d.json["scene"] = 1;
    const TriangleMesh mesh = Read(d);
    ASSERT_EQ(mesh.positions.size(), 3u);
    ExpectNear(mesh.positions[2], {0, 8, 0});
    d.json.erase("scene");  // no default: scene 0
    EXPECT_EQ(Read(d).positions[2], glm::dvec3(0, 1, 0));
}

// glTF 2.0 §3.7.2.1: strip triangle i is (v_i, v_{i+1+i%2}, v_{i+2−i%2}), fan triangle i is
// (v_{i+1}, v_{i+2}, v_0); points and lines give none.
TEST(GltfReader, TurnsStripsAndFansIntoCounterClockwiseTriangles) {
    const std::vector<glm::vec3> five = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}};
    const std::vector<std::uint32_t> order = {0, 1, 2, 3, 4};
    const std::vector<glm::uvec3> strip = {{0, 1, 2}, {1, 3, 2}, {2, 3, 4}};
    EXPECT_EQ(Read(OnePrimitive(five, order, 5)).triangles, strip);
    const std::vector<glm::uvec3> fan = {{1, 2, 0}, {2, 3, 0}, {3, 4, 0}};
    EXPECT_EQ(Read(OnePrimitive(five, order, 6)).triangles, fan);
    for (const TriangleMesh& mesh : {Read(OnePrimitive(five, order, 5))})
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            EXPECT_GT(mesh.FaceNormal(t).z, 0.0) << "strip triangle " << t;
    for (int mode = 0; mode < 4; ++mode)
        EXPECT_EQ(ReadError(Text(OnePrimitive(five, order, mode))),
                  "its default scene holds no triangles")
            << "mode " << mode;
}

// glTF: a node whose global transform has a negative determinant has clockwise triangles, so the
// reader reverses them: the face normal stays +z under a mirror in x.
TEST(GltfReader, KeepsFacesCounterClockwiseUnderAMirroringNode) {
    Document d = OnePrimitive(kTriangle, {0, 1, 2});
    d.json["nodes"][0]["scale"] = {-1, 1, 1};
    const TriangleMesh mesh = Read(d);
    EXPECT_EQ(mesh.FaceNormal(0), glm::dvec3(0, 0, 1));
    EXPECT_EQ(mesh.triangles[0], glm::uvec3(0, 2, 1));
}

// glTF 2.0 §3.6.2.3: sparse values replace the dense ones at their indices.
TEST(GltfReader, AppliesSparseAccessors) {
    Document d = OnePrimitive(kTriangle, {});
    const glm::vec3 moved(0, 3, 4);
    const std::uint32_t index = 2;
    const std::size_t at = d.buffer.size();
    d.buffer.append(reinterpret_cast<const char*>(&index), 4);
    d.buffer.append(reinterpret_cast<const char*>(&moved), 12);
    d.json["buffers"][0]["byteLength"] = d.buffer.size();
    d.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 16}});
    d.json["accessors"][0]["sparse"] = {{"count", 1},
                                        {"indices", {{"bufferView", 1}, {"componentType", 5125}}},
                                        {"values", {{"bufferView", 1}, {"byteOffset", 4}}}};
    const TriangleMesh mesh = Read(d);
    EXPECT_EQ(mesh.positions[1], glm::dvec3(kTriangle[1]));
    EXPECT_EQ(mesh.positions[2], glm::dvec3(moved));
}

// Khronos's samples: the box as .glb, with an embedded buffer and with a .bin beside it, read the
// same; the engine (28 nodes, instances, 121496 triangles) as Assimp's glTF 2 importer places it.
TEST(GltfReader, ReadsKhronosSamplesAsAssimpDoes) {
    ASSERT_TRUE(std::filesystem::is_directory(kModels)) << "install assimp-testmodels";
    const LoadedMesh glb = LoadMeshFile(kModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
    const LoadedMesh embedded =
        LoadMeshFile(kModels / "BoxTextured-glTF-Embedded/BoxTextured.gltf");
    const LoadedMesh external = LoadMeshFile(kModels / "BoxTextured-glTF/BoxTextured.gltf");
    EXPECT_EQ(glb.format, "glTF 2.0 (binary)");
    EXPECT_EQ(external.format, "glTF 2.0 (JSON)");
    EXPECT_EQ(glb.mesh.triangles.size(), 12u);
    for (const LoadedMesh* other : {&embedded, &external}) {
        EXPECT_EQ(other->mesh.positions, glb.mesh.positions);
        EXPECT_EQ(other->mesh.triangles, glb.mesh.triangles);
    }

    const auto engine = kModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    const TriangleMesh mesh = LoadMesh(engine);
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(engine.string(), aiProcess_Triangulate | aiProcess_PreTransformVertices);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    std::size_t triangles = 0;
    Bounds assimpBounds;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& in = *scene->mMeshes[m];
        for (unsigned f = 0; f < in.mNumFaces; ++f) {
            if (in.mFaces[f].mNumIndices != 3) continue;
            ++triangles;
            for (int k = 0; k < 3; ++k) {
                const aiVector3D& p = in.mVertices[in.mFaces[f].mIndices[k]];
                assimpBounds.Add({p.x, p.y, p.z});
            }
        }
    }
    EXPECT_EQ(mesh.triangles.size(), 121496u);
    EXPECT_EQ(mesh.triangles.size(), triangles);
    const Bounds bounds = mesh.ComputeBounds();
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(bounds.lo[k], assimpBounds.lo[k], 1e-3) << "axis " << k;
        EXPECT_NEAR(bounds.hi[k], assimpBounds.hi[k], 1e-3) << "axis " << k;
    }
    EXPECT_NEAR(bounds.hi.x - bounds.lo.x, 743.384, 1e-3);
}

std::string LoadError(const std::filesystem::path& path) {
    try {
        LoadMesh(path);
    } catch (const DomainError& e) {
        return e.what();
    }
    return "no error";
}

// The package's broken samples, each in one line naming the file.
TEST(GltfReader, RefusesTheBrokenSamplesInOneLine) {
    ASSERT_TRUE(std::filesystem::is_directory(kModels)) << "install assimp-testmodels";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"RecursiveNodes/RecursiveNodes.gltf",
         "node 0 is reached twice from the scene: glTF nodes form trees (one parent each, none its "
         "own ancestor)"},
        {"IndexOutOfRange/IndexOutOfRange.gltf",
         "mesh 0 primitive 0: index 255 is past its 24 vertices"},
        {"IncorrectVertexArrays/Cube.gltf",
         "mesh 1 primitive 0: its 35 TRIANGLES indices are not a multiple of 3"},
        {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",
         "mesh 0 primitive 0: POSITION accessor 2: position 0 is not finite"},
        {"TestNoRootNode/NoScene.gltf", "it has no scene (its 'scenes' list is empty)"},
    };
    for (const auto& [file, reason] : cases)
        EXPECT_EQ(LoadError(kModels / file),
                  (kModels / file).string() + ": cannot read glTF: " + reason);
    // The Draco sample: the documented refusal, not tinygltf's "accessor[0] invalid bufferView".
    const auto draco = kModels / "draco/2CylinderEngine.gltf";
    EXPECT_EQ(LoadError(draco),
              draco.string() +
                  ": cannot read glTF: it requires the extension 'KHR_draco_mesh_compression' "
                  "(compressed, quantized or GPU-instanced geometry), which lexel does not read: "
                  "write the file without it");
    const auto missing = kModels / "MissingBin/BoxTextured.gltf";
    EXPECT_EQ(LoadError(missing), missing.string() + ": cannot read glTF: buffer 0's file " +
                                      (kModels / "MissingBin").string() +
                                      "/BoxTextured0.bin is missing (buffer files are regular "
                                      "files)");
}

TEST(GltfReader, RefusesBadAccessorsAndDocumentsInOneLine) {
    Document past = OnePrimitive(kTriangle, {0, 1, 2});
    past.json["accessors"][0]["count"] = 4;
    EXPECT_EQ(ReadError(Text(past)),
              "mesh 0 primitive 0: POSITION accessor 0: buffer view 0: 4 elements of 12 bytes "
              "every 12 from byte 0 reach past its 36 bytes");
    // A count far past the data is refused from the view's bounds, before 12 GB are allocated.
    past.json["accessors"][0]["count"] = 1000000000;
    EXPECT_EQ(ReadError(Text(past)),
              "mesh 0 primitive 0: POSITION accessor 0: buffer view 0: 1000000000 elements of 12 "
              "bytes every 12 from byte 0 reach past its 36 bytes");
    Document stride = OnePrimitive(kTriangle, {});
    stride.json["bufferViews"][0]["byteStride"] = 8;
    EXPECT_EQ(ReadError(Text(stride)),
              "mesh 0 primitive 0: POSITION accessor 0: buffer view 0: byteStride 8 is less than "
              "an element's 12 bytes");
    Document type = OnePrimitive(kTriangle, {});
    type.json["accessors"][0]["componentType"] = 5123;
    EXPECT_EQ(ReadError(Text(type)),
              "mesh 0 primitive 0: POSITION accessor 0: it is not VEC3 of FLOAT (quantized "
              "positions are not read)");
    Document draco = OnePrimitive(kTriangle, {});
    draco.json["extensionsUsed"] = {"KHR_draco_mesh_compression", "KHR_materials_unlit"};
    draco.json["extensionsRequired"] = {"KHR_materials_unlit", "KHR_draco_mesh_compression"};
    EXPECT_EQ(ReadError(Text(draco)),
              "it requires the extension 'KHR_draco_mesh_compression' (compressed, quantized or "
              "GPU-instanced geometry), which lexel does not read: write the file without it");
    // Integers tinygltf keeps in an int: before, 2^40 was read as 0 and a scene of -1 as none.
    Document scene = OnePrimitive(kTriangle, {});
    scene.json["scene"] = 1099511627776LL;
    EXPECT_EQ(ReadError(Text(scene)), "its \"scene\" is 1099511627776, not 0 to 2^31 - 1");
    scene.json["scene"] = -1;
    EXPECT_EQ(ReadError(Text(scene)), "its \"scene\" is -1, not 0 to 2^31 - 1");
    Document sparse = OnePrimitive(kTriangle, {});
    sparse.json["accessors"][0]["sparse"] = {
        {"count", 1099511627776LL},
        {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
        {"values", {{"bufferView", 0}}}};
    EXPECT_EQ(ReadError(Text(sparse)),
              "accessor 0's sparse count is 1099511627776, not 1 to 2^31 - 1");
    Document node = OnePrimitive(kTriangle, {});
    node.json["scenes"][0]["nodes"] = {3};
    EXPECT_EQ(ReadError(Text(node)), "node 3 does not exist (the file has 1)");
    // tinygltf copies `extras` recursively: nesting past 100 levels is refused before it reads.
    Document deep = OnePrimitive(kTriangle, {});
    std::string text = Text(deep);
    text.insert(text.size() - 1, ",\"extras\":" + std::string(5000, '[') + std::string(5000, ']'));
    EXPECT_EQ(ReadError(text),
              "its JSON nests arrays and objects 5001 deep, more than the 100 read");
    EXPECT_EQ(ReadError("{\"asset\": "),
              "[json.exception.parse_error.101] parse error at line 1, column 11: syntax error "
              "while parsing value - unexpected end of input; expected '[', '{', or a literal");
    EXPECT_EQ(ReadError("glTF\x02\0\0\0\xff\xff\xff\xff", true),
              "Too short data size for glTF Binary.");
}

// A buffer file beside the document is read; a FIFO in its place is refused without being opened
// (opening it would wait for a writer), and nothing outside the counted files is opened.
TEST(GltfReader, ReadsBufferFilesAndRefusesFifos) {
    const auto dir = std::filesystem::temp_directory_path() / "lexel_gltf_buffers";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    Document d = OnePrimitive(kTriangle, {0, 1, 2});
    d.json["buffers"][0]["uri"] = "tri%20angle.bin";  // percent-decoded, as tinygltf does
    std::ofstream(dir / "tri angle.bin", std::ios::binary) << d.buffer;
    std::ofstream(dir / "scene.gltf") << Text(d);
    EXPECT_EQ(LoadMesh(dir / "scene.gltf").positions,
              std::vector<glm::dvec3>(kTriangle.begin(), kTriangle.end()));

    d.json["buffers"][0]["uri"] = "pipe.bin";
    std::ofstream(dir / "pipe.gltf") << Text(d);
    ASSERT_EQ(::mkfifo((dir / "pipe.bin").c_str(), 0600), 0);
    EXPECT_EQ(LoadError(dir / "pipe.gltf"),
              (dir / "pipe.gltf").string() + ": cannot read glTF: buffer 0's file " + dir.string() +
                  "/pipe.bin is a FIFO (named pipe) (buffer files "
                  "are regular files)");
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lexel::spatial
