// glTF 2.0 through tinygltf (see mesh_gltf_reader.h). tinygltf's implementation is compiled here,
// once, with no image decoder (images are skipped), no file system of its own (the callbacks below
// open only the buffer files FindGltfBufferFiles counted) and no external images.
// The macros and <fstream> must precede tiny_gltf.h (its writers use std::ofstream, which
// TINYGLTF_NO_FS leaves undeclared).
// clang-format off
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <fstream>
#include <tiny_gltf.h>
// clang-format on

#include "lexel/spatial/harness/mesh_gltf_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_file_check.h"

namespace lexel::spatial {
namespace {

[[noreturn]] void Fail(const std::string& reason) { throw DomainError(Subject::kGeometry, reason); }

// tinygltf's messages span lines and quote the document's strings, which may hold any byte: one
// line of printable text (line ends as spaces, other control characters, NUL included, as '?').
std::string OneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r')
            c = ' ';
        else if ((c >= 0 && c < 0x20) || c == 0x7f)
            c = '?';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// The JSON of a .glb (its first chunk) or of a .gltf (all of it); a .glb whose header does not
// hold its chunk gives an empty view (tinygltf reports the header).
std::string_view GltfJson(std::string_view bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);  // little-endian, as glTF and x86-64
    if (length > bytes.size() - 20) return {};
    return bytes.substr(20, length);
}

// The deepest nesting of arrays and objects in JSON text (strings skipped).
int JsonDepth(std::string_view json) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

// What a path that is not a regular file is, for a message.
std::string NotRegular(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    switch (fs::status(path, error).type()) {
        case fs::file_type::regular:
            return {};
        case fs::file_type::not_found:
            return "is missing";
        case fs::file_type::directory:
            return "is a directory";
        case fs::file_type::fifo:
            return "is a FIFO (named pipe)";
        case fs::file_type::character:
            return "is a character device";
        case fs::file_type::block:
            return "is a block device";
        case fs::file_type::socket:
            return "is a socket";
        default:
            return "cannot be examined";
    }
}

// tinygltf's file system: only the counted buffer files exist, and they are read as regular files.
bool FileExists(const std::string& path, void* files) {
    const auto& paths = static_cast<const GltfBufferFiles*>(files)->paths;
    return std::find(paths.begin(), paths.end(), path) != paths.end();
}
std::string ExpandFilePath(const std::string& path, void*) { return path; }
bool ReadWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                   void* files) {
    if (!FileExists(path, files)) {
        *error = "not a buffer file of the document";
        return false;
    }
    try {
        const std::string bytes = ReadRegularFile(path, kMaxMeshFileBytes);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const DomainError& e) {
        *error = e.what();
        return false;
    }
}
bool WriteWholeFile(std::string* error, const std::string&, const std::vector<unsigned char>&,
                    void*) {
    *error = "lexel writes no glTF files";
    return false;
}
// Images are not read: geometry only.
bool SkipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

// Required extensions that change how geometry is stored or placed, which lexel does not decode;
// any other required extension (materials, textures, lights, techniques) leaves it as read.
bool ChangesGeometry(const std::string& extension) {
    for (const char* name :
         {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
          "KHR_mesh_quantization", "EXT_mesh_gpu_instancing"})
        if (extension == name) return true;
    return false;
}

template <class T>
const T& At(const std::vector<T>& items, long long index, const char* what) {
    if (index < 0 || static_cast<std::size_t>(index) >= items.size())
        Fail(std::string(what) + " " + std::to_string(index) + " does not exist (the file has " +
             std::to_string(items.size()) + ")");
    return items[static_cast<std::size_t>(index)];
}

// A node's matrix, or translation · rotation · scale; each value finite.
glm::dmat4 LocalMatrix(const tinygltf::Node& node, int index) {
    const std::string where = "node " + std::to_string(index);
    const auto check = [&](const std::vector<double>& values, std::size_t size, const char* name) {
        if (!values.empty() && values.size() != size)
            Fail(where + ": " + name + " has " + std::to_string(values.size()) + " numbers, not " +
                 std::to_string(size));
        for (const double v : values)
            if (!std::isfinite(v)) Fail(where + ": " + name + " holds a non-finite number");
    };
    check(node.matrix, 16, "matrix");
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    glm::dmat4 m(1.0);
    if (!node.matrix.empty()) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[4 * c + r];  // column-major
        return m;
    }
    if (!node.translation.empty())
        m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    if (!node.rotation.empty()) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length))
            Fail(where + ": rotation is not a unit quaternion");
        m = m * glm::dmat4(glm::mat3_cast(q / length));
    }
    if (!node.scale.empty())
        m = m *
            glm::dmat4(glm::dmat3(glm::dvec3(node.scale[0], 0, 0), glm::dvec3(0, node.scale[1], 0),
                                  glm::dvec3(0, 0, node.scale[2])));
    return m;
}

struct Instance {
    int mesh;
    glm::dmat4 sceneFromMesh;
};

// Every mesh instance under the default scene's roots, visiting each node once (a node met again
// has two parents or is its own ancestor, which glTF forbids).
std::vector<Instance> SceneInstances(const tinygltf::Model& model) {
    if (model.scenes.empty()) Fail("it has no scene (its 'scenes' list is empty)");
    const int sceneIndex = model.defaultScene < 0 ? 0 : model.defaultScene;
    const tinygltf::Scene& scene = At(model.scenes, sceneIndex, "the default scene");
    std::vector<char> visited(model.nodes.size(), 0);
    std::vector<std::pair<int, glm::dmat4>> stack;
    for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it)
        stack.emplace_back(*it, glm::dmat4(1.0));
    std::vector<Instance> instances;
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = At(model.nodes, index, "node");
        if (visited[index])
            Fail("node " + std::to_string(index) +
                 " is reached twice from the scene: glTF nodes form trees (one parent each, none "
                 "its own ancestor)");
        visited[index] = 1;
        const glm::dmat4 sceneFromNode = parent * LocalMatrix(node, index);
        if (node.mesh >= 0 || node.mesh < -1) {
            At(model.meshes, node.mesh, "mesh");
            instances.push_back({node.mesh, sceneFromNode});
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            stack.emplace_back(*it, sceneFromNode);
    }
    return instances;
}

// Bytes of an accessor's elements: element i at data + i · stride, each `elementBytes` long, all
// inside the buffer view and the view inside its buffer; data is null without a buffer view.
struct ElementBytes {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
};

const unsigned char* CheckedView(const tinygltf::Model& model, int viewIndex, std::size_t offset,
                                 std::size_t count, std::size_t stride, std::size_t elementBytes,
                                 std::size_t* viewStride) {
    const tinygltf::BufferView& view = At(model.bufferViews, viewIndex, "buffer view");
    const tinygltf::Buffer& buffer = At(model.buffers, view.buffer, "buffer");
    const std::string where = "buffer view " + std::to_string(viewIndex);
    if (view.byteLength > buffer.data.size() ||
        view.byteOffset > buffer.data.size() - view.byteLength)
        Fail(where + " (bytes " + std::to_string(view.byteOffset) + " + " +
             std::to_string(view.byteLength) + ") reaches past its buffer's " +
             std::to_string(buffer.data.size()) + " bytes");
    if (stride == 0) stride = view.byteStride != 0 ? view.byteStride : elementBytes;
    if (stride < elementBytes)
        Fail(where + ": byteStride " + std::to_string(stride) + " is less than an element's " +
             std::to_string(elementBytes) + " bytes");
    if (viewStride != nullptr) *viewStride = stride;
    if (count == 0) return buffer.data.data() + view.byteOffset;
    if (offset > view.byteLength || elementBytes > view.byteLength - offset ||
        count - 1 > (view.byteLength - offset - elementBytes) / stride)
        Fail(where + ": " + std::to_string(count) + " elements of " + std::to_string(elementBytes) +
             " bytes every " + std::to_string(stride) + " from byte " + std::to_string(offset) +
             " reach past its " + std::to_string(view.byteLength) + " bytes");
    return buffer.data.data() + view.byteOffset + offset;
}

std::size_t ComponentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return 4;
        default:
            return 0;
    }
}

std::uint32_t UnsignedAt(const unsigned char* p, std::size_t bytes) {
    if (bytes == 1) return p[0];
    if (bytes == 2) {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// An accessor's elements decoded by `decode(bytes)`, dense values then sparse substitutions
// (glTF 2.0 §3.6.2.3); an accessor without a buffer view starts from zeros.
template <class T, class Decode>
std::vector<T> ReadAccessor(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                            std::size_t elementBytes, Decode decode) {
    if (accessor.count > std::numeric_limits<std::uint32_t>::max())
        Fail("its count " + std::to_string(accessor.count) + " is more than 2^32 - 1");
    if (accessor.bufferView < 0 && !accessor.sparse.isSparse)
        Fail("it has neither a buffer view nor sparse values");
    std::size_t stride = 0;  // the dense values' bounds are checked before anything is allocated
    const unsigned char* data = accessor.bufferView < 0
                                    ? nullptr
                                    : CheckedView(model, accessor.bufferView, accessor.byteOffset,
                                                  accessor.count, 0, elementBytes, &stride);
    std::vector<T> values(accessor.count);
    if (data != nullptr)
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = decode(data + i * stride);
    if (!accessor.sparse.isSparse) return values;
    const auto& sparse = accessor.sparse;
    if (sparse.count < 0 || static_cast<std::size_t>(sparse.count) > accessor.count)
        Fail("its sparse count " + std::to_string(sparse.count) + " is not 0 to its count " +
             std::to_string(accessor.count));
    const std::size_t indexBytes = ComponentBytes(sparse.indices.componentType);
    if (indexBytes == 0) Fail("its sparse indices are not unsigned byte, short or int");
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        Fail("a sparse byteOffset is negative");
    const auto count = static_cast<std::size_t>(sparse.count);
    const unsigned char* indices =
        CheckedView(model, sparse.indices.bufferView, std::size_t(sparse.indices.byteOffset), count,
                    indexBytes, indexBytes, nullptr);
    const unsigned char* replacements =
        CheckedView(model, sparse.values.bufferView, std::size_t(sparse.values.byteOffset), count,
                    elementBytes, elementBytes, nullptr);
    for (std::size_t j = 0; j < count; ++j) {
        const std::uint32_t at = UnsignedAt(indices + j * indexBytes, indexBytes);
        if (at >= values.size())
            Fail("sparse index " + std::to_string(at) + " is past its " +
                 std::to_string(values.size()) + " elements");
        values[at] = decode(replacements + j * elementBytes);
    }
    return values;
}

std::vector<glm::vec3> ReadPositions(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& accessor = At(model.accessors, index, "accessor");
    if (accessor.type != TINYGLTF_TYPE_VEC3 ||
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        Fail("it is not VEC3 of FLOAT (quantized positions are not read)");
    std::vector<glm::vec3> positions =
        ReadAccessor<glm::vec3>(model, accessor, 12, [](const unsigned char* p) {
            glm::vec3 v;
            std::memcpy(&v[0], p, 12);
            return v;
        });
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) ||
            !std::isfinite(positions[i].z))
            Fail("position " + std::to_string(i) + " is not finite");
    return positions;
}

std::vector<std::uint32_t> ReadIndices(const tinygltf::Model& model, int index) {
    const tinygltf::Accessor& accessor = At(model.accessors, index, "accessor");
    const std::size_t bytes = ComponentBytes(accessor.componentType);
    if (accessor.type != TINYGLTF_TYPE_SCALAR || bytes == 0)
        Fail("it is not a SCALAR of unsigned byte, short or int");
    return ReadAccessor<std::uint32_t>(
        model, accessor, bytes, [bytes](const unsigned char* p) { return UnsignedAt(p, bytes); });
}

// The triangles of one primitive's index sequence (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN; glTF
// 2.0 §3.7.2.1), counter-clockwise.
void AppendTriangles(int mode, const std::vector<std::uint32_t>& v, std::uint32_t offset,
                     std::vector<glm::uvec3>& triangles) {
    const std::size_t n = v.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            Fail("its " + std::to_string(n) + " TRIANGLES indices are not a multiple of 3");
        for (std::size_t i = 0; i + 2 < n; i += 3)
            triangles.push_back(glm::uvec3(v[i], v[i + 1], v[i + 2]) + offset);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i)
            triangles.push_back(glm::uvec3(v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]) + offset);
    } else {
        for (std::size_t i = 1; i + 1 < n; ++i)
            triangles.push_back(glm::uvec3(v[i], v[i + 1], v[0]) + offset);
    }
}

// A primitive's triangles appended to `mesh` (in the mesh's space); points and lines, and a
// primitive without positions (glTF: not rendered), add nothing.
void AppendPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                     TriangleMesh& mesh) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode > TINYGLTF_MODE_TRIANGLE_FAN)
        Fail("mode " + std::to_string(mode) + " is not a glTF primitive mode (0 to 6)");
    const auto position = primitive.attributes.find("POSITION");
    if (mode < TINYGLTF_MODE_TRIANGLES || position == primitive.attributes.end()) return;
    std::vector<glm::vec3> positions;
    try {
        positions = ReadPositions(model, position->second);
    } catch (const DomainError& e) {
        Fail("POSITION accessor " + std::to_string(position->second) + ": " + e.what());
    }
    std::vector<std::uint32_t> indices;
    if (primitive.indices >= 0) {
        try {
            indices = ReadIndices(model, primitive.indices);
        } catch (const DomainError& e) {
            Fail("indices accessor " + std::to_string(primitive.indices) + ": " + e.what());
        }
        for (const std::uint32_t i : indices)
            if (i >= positions.size())
                Fail("index " + std::to_string(i) + " is past its " +
                     std::to_string(positions.size()) + " vertices");
    } else {
        indices.resize(positions.size());
        for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
    }
    if (mesh.positions.size() + positions.size() > std::numeric_limits<std::uint32_t>::max())
        Fail("more than 2^32 - 1 vertices");
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), positions.begin(), positions.end());
    AppendTriangles(mode, indices, offset, mesh.triangles);
}

TriangleMesh MeshTriangles(const tinygltf::Model& model, int meshIndex) {
    TriangleMesh mesh;
    const tinygltf::Mesh& in = model.meshes[static_cast<std::size_t>(meshIndex)];
    for (std::size_t p = 0; p < in.primitives.size(); ++p) {
        try {
            AppendPrimitive(model, in.primitives[p], mesh);
        } catch (const DomainError& e) {
            Fail("mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p) + ": " +
                 e.what());
        }
    }
    return mesh;
}

// One instance of a mesh placed in the scene; a mirroring placement reverses the winding.
void AppendInstance(const TriangleMesh& mesh, const glm::dmat4& sceneFromMesh, TriangleMesh& out) {
    if (out.positions.size() + mesh.positions.size() > std::numeric_limits<std::uint32_t>::max())
        Fail("its instances hold more than 2^32 - 1 vertices");
    const auto offset = static_cast<std::uint32_t>(out.positions.size());
    for (const glm::dvec3& p : mesh.positions) {
        const glm::dvec3 q(sceneFromMesh * glm::dvec4(p, 1.0));
        const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
        if (!(largest <= std::numeric_limits<float>::max()))
            Fail("a vertex placed by its node's transform is not a finite float");
        out.positions.emplace_back(q);
    }
    const bool mirrored = glm::determinant(glm::dmat3(sceneFromMesh)) < 0.0;
    for (const glm::uvec3& t : mesh.triangles)
        out.triangles.push_back(mirrored ? glm::uvec3(t.x, t.z, t.y) + offset : t + offset);
}

// The documented refusal of a required extension that changes geometry (ChangesGeometry).
void FailOnGeometryExtension(const std::string& extension) {
    if (ChangesGeometry(extension))
        Fail("it requires the extension '" + extension +
             "' (compressed, quantized or GPU-instanced geometry), which lexel does not "
             "read: write the file without it");
}

// What tinygltf would misread in the document, checked on its JSON first: a required extension
// that changes geometry (tinygltf may refuse its buffers with a message of its own first), and
// the integers it keeps in an int, "scene" and a sparse accessor's "count", which it would
// truncate (2^40 read as 0) or take below their minimum (a scene of -1 read as none).
void CheckDocument(const nlohmann::json& document) {
    if (!document.is_object()) return;  // ReadGltfMesh reports what tinygltf finds wrong
    if (const auto required = document.find("extensionsRequired");
        required != document.end() && required->is_array())
        for (const nlohmann::json& extension : *required)
            if (extension.is_string()) FailOnGeometryExtension(extension.get<std::string>());
    const auto checkInt = [](const nlohmann::json& value, long long least,
                             const std::string& what) {
        constexpr long long kMost = std::numeric_limits<std::int32_t>::max();
        if (!value.is_number_integer() && !value.is_number_unsigned())
            Fail(what + " is not an integer");
        const bool inRange =
            value.is_number_unsigned()
                ? value.get<std::uint64_t>() <= std::uint64_t(kMost) &&
                      value.get<std::uint64_t>() >= std::uint64_t(least)
                : value.get<long long>() >= least && value.get<long long>() <= kMost;
        if (!inRange)
            Fail(what + " is " + value.dump() + ", not " + std::to_string(least) + " to 2^31 - 1");
    };
    if (const auto scene = document.find("scene"); scene != document.end())
        checkInt(*scene, 0, "its \"scene\"");
    const auto accessors = document.find("accessors");
    if (accessors == document.end() || !accessors->is_array()) return;
    for (std::size_t a = 0; a < accessors->size(); ++a) {
        const nlohmann::json& accessor = (*accessors)[a];
        if (!accessor.is_object()) continue;
        const auto sparse = accessor.find("sparse");
        if (sparse == accessor.end() || !sparse->is_object()) continue;
        if (const auto count = sparse->find("count"); count != sparse->end())
            checkInt(*count, 1, "accessor " + std::to_string(a) + "'s sparse count");
    }
}

tinygltf::Model ParseModel(std::string_view bytes, bool binary,
                           const std::filesystem::path& directory, const GltfBufferFiles& files) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&SkipImage, nullptr);
    loader.SetFsCallbacks({&FileExists, &ExpandFilePath, &ReadWholeFile, &WriteWholeFile,
                           const_cast<GltfBufferFiles*>(&files)});
    tinygltf::Model model;
    std::string error, warning;
    const std::string baseDir = directory.empty() ? std::string(".") : directory.string();
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned>(bytes.size()), baseDir)
               : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                            static_cast<unsigned>(bytes.size()), baseDir);
    if (!ok) Fail(OneLine(error.empty() ? std::string("tinygltf refused it") : error));
    for (const std::string& extension : model.extensionsRequired)
        FailOnGeometryExtension(extension);
    return model;
}

}  // namespace

bool IsBinaryGltf(std::string_view bytes) { return bytes.starts_with("glTF"); }

GltfBufferFiles FindGltfBufferFiles(std::string_view bytes, bool binary,
                                    const std::filesystem::path& directory) {
    const std::string_view json = GltfJson(bytes, binary);
    if (const int depth = JsonDepth(json); depth > kMaxGltfJsonDepth)
        Fail("its JSON nests arrays and objects " + std::to_string(depth) +
             " deep, more than the " + std::to_string(kMaxGltfJsonDepth) + " read");
    GltfBufferFiles files;
    const nlohmann::json document = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    CheckDocument(document);
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array())
        return files;  // ReadGltfMesh reports what tinygltf finds wrong
    const std::string baseDir = directory.empty() ? std::string(".") : directory.string();
    const nlohmann::json& buffers = document["buffers"];
    for (std::size_t k = 0; k < buffers.size(); ++k) {
        if (!buffers[k].is_object() || !buffers[k].contains("uri")) continue;
        const nlohmann::json& uri = buffers[k]["uri"];
        if (!uri.is_string() || tinygltf::IsDataURI(uri.get<std::string>())) continue;
        const std::string path =
            tinygltf::JoinPath(baseDir, tinygltf::dlib::urldecode(uri.get<std::string>()));
        const std::string where = "buffer " + std::to_string(k) + "'s file " + OneLine(path);
        if (const std::string problem = NotRegular(path); !problem.empty())
            Fail(where + " " + problem + " (buffer files are regular files)");
        std::error_code error;
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        if (error) Fail(where + ": cannot read its size");
        files.bytes += size;
        if (files.bytes > kMaxMeshFileBytes)
            Fail("its buffer files hold more than the " + std::to_string(kMaxMeshFileBytes >> 20) +
                 " MiB read (" + where + " is " + std::to_string(size) + " bytes)");
        files.paths.push_back(path);
    }
    return files;
}

TriangleMesh ReadGltfMesh(std::string_view bytes, bool binary,
                          const std::filesystem::path& directory, const GltfBufferFiles& files) {
    const tinygltf::Model model = ParseModel(bytes, binary, directory, files);
    const std::vector<Instance> instances = SceneInstances(model);
    std::vector<std::optional<TriangleMesh>> meshes(model.meshes.size());
    TriangleMesh out;
    for (const Instance& instance : instances) {
        std::optional<TriangleMesh>& mesh = meshes[static_cast<std::size_t>(instance.mesh)];
        if (!mesh) mesh = MeshTriangles(model, instance.mesh);
        AppendInstance(*mesh, instance.sceneFromMesh, out);
    }
    if (out.triangles.empty()) Fail("its default scene holds no triangles");
    return out;
}

}  // namespace lexel::spatial
