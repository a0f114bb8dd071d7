// Model files (see mesh_loader.h): OBJ, OFF and STL through Assimp, PLY and glTF through their
// readers, each under an allocation cap. Assimp logs only through DefaultLogger, which we never
// create, so its NullLogger keeps stdout and stderr clean.
#include "lexel/spatial/harness/mesh_loader.h"

#include <assimp/DefaultIOStream.h>
#include <assimp/DefaultIOSystem.h>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/allocation_cap.h"
#include "lexel/spatial/harness/mesh_file_check.h"
#include "lexel/spatial/harness/mesh_gltf_reader.h"
#include "lexel/spatial/harness/mesh_ply_reader.h"

namespace lexel::spatial {
namespace {

// Assimp's and tinygltf's messages can span lines, and quote a file's bytes: error messages are one
// line of printable text (line ends as spaces, other control characters as '?').
std::string OneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r')
            c = ' ';
        else if ((c >= 0 && c < 0x20) || c == 0x7f)
            c = '?';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? std::string("unknown error") : text;
}

// An open regular file as Assimp reads it (DefaultIOStream's constructor is protected).
class RegularFileStream : public Assimp::DefaultIOStream {
  public:
    RegularFileStream(FILE* file, const std::string& name) : DefaultIOStream(file, name) {}
};

// The files Assimp opens for a mesh — the mesh file and those it names, such as an OBJ's mtllib
// or the <model>.mtl it falls back on — pass through this, and only regular files are opened,
// for reading: a FIFO would block Assimp's fopen until a writer came (an OBJ whose mtllib named
// one hung for ever), and opening a device can act on it. Each path is examined with stat before
// it is opened, and the opened file again with fstat (it may have been replaced meanwhile); the
// first refused path is kept for the error message. A path that resolves (links followed) outside
// `folder`, the mesh file's own, is absent to Assimp: a side file never comes from elsewhere (an
// mtllib naming /dev/zero, a system file or ../../x), whatever the mesh's path spelling, since
// Assimp is handed the mesh's canonical path and joins a side file's name to its folder.
class RegularFileSystem : public Assimp::DefaultIOSystem {
  public:
    explicit RegularFileSystem(std::filesystem::path folder) : folder_(std::move(folder)) {}

    bool Exists(const char* file) const override {
        return !Resolved(file).empty() && IsRegular(file);
    }

    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::string_view(mode).find_first_of("wa+") != std::string_view::npos) return nullptr;
        const std::filesystem::path resolved = Resolved(file);
        if (resolved.empty() || !IsRegular(file)) return nullptr;
        // The resolved path, its last part not followed: a link put there after Resolved is not.
        const int fd =
            ::open(resolved.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd < 0) return nullptr;
        struct stat st {};
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
            ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK) != 0) {
            Refuse(file, st.st_mode);
            ::close(fd);
            return nullptr;
        }
        FILE* stream = ::fdopen(fd, "rb");
        if (stream == nullptr) {
            ::close(fd);
            return nullptr;
        }
        return new RegularFileStream(stream, file);
    }

    // "<path>, a FIFO (named pipe)" for the first path refused, or empty.
    const std::string& Refused() const { return refused_; }

  private:
    // `file` with its links resolved when that lies in folder_ or below it, else empty.
    std::filesystem::path Resolved(const char* file) const {
        std::error_code error;
        std::filesystem::path resolved = std::filesystem::weakly_canonical(file, error);
        if (error) return {};
        const std::filesystem::path relative = resolved.lexically_relative(folder_);
        if (relative.empty() || *relative.begin() == "..") return {};
        return resolved;
    }
    // False for a missing path and (kept in refused_) for one that is not a regular file.
    bool IsRegular(const char* file) const {
        struct stat st {};
        if (::stat(file, &st) != 0) return false;
        if (S_ISREG(st.st_mode)) return true;
        Refuse(file, st.st_mode);
        return false;
    }
    void Refuse(const char* file, ::mode_t mode) const {
        if (refused_.empty()) refused_ = std::string(file) + ", " + FileKind(mode);
    }

    std::filesystem::path folder_;  // canonical
    mutable std::string refused_;
};

// What Assimp's post-processing would trip over in an importer's scene, or empty: more vertices
// and faces than the file has bytes (each takes at least one), a face without indices, an index
// past its mesh's vertices, or a mesh marked as holding polygons (more than three corners) that
// holds none.
std::string ImporterSceneError(const aiScene& scene, std::uintmax_t fileBytes) {
    std::uintmax_t elements = 0;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        elements += std::uintmax_t{scene.mMeshes[m]->mNumVertices} + scene.mMeshes[m]->mNumFaces;
    if (elements > fileBytes)
        return "it holds " + std::to_string(elements) + " vertices and faces, more than its " +
               std::to_string(fileBytes) + " bytes can (a corrupt file)";
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& in = *scene.mMeshes[m];
        bool polygons = false;
        for (unsigned f = 0; f < in.mNumFaces; ++f) {
            const aiFace& face = in.mFaces[f];
            if (face.mNumIndices == 0 || face.mIndices == nullptr)
                return "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                       " has no vertices";
            for (unsigned i = 0; i < face.mNumIndices; ++i)
                if (face.mIndices[i] >= in.mNumVertices)
                    return "face " + std::to_string(f) + " of mesh " + std::to_string(m) +
                           " refers to vertex " + std::to_string(face.mIndices[i]) + " of " +
                           std::to_string(in.mNumVertices);
            polygons = polygons || face.mNumIndices > 3;
        }
        if ((in.mPrimitiveTypes & aiPrimitiveType_POLYGON) && !polygons)
            return "mesh " + std::to_string(m) + " is marked as polygons but has none";
    }
    return {};
}

// The bytes Assimp may hold while it reads and post-processes a file: kReadBaseBytes and
// kReadBytesPerFileByte for each byte of the file (4.06 GiB for the largest file). Files take
// about 30 bytes a byte at most (an OFF of 64 MB with normals, colours and texture coordinates
// 1.7 GB; a 54 MB OBJ of 1.6 million triangles 0.94 GB); a file that needs more declares counts
// its data do not fill.
constexpr std::uintmax_t kReadBaseBytes = std::uintmax_t{64} << 20, kReadBytesPerFileByte = 64;

// Assimp's scene of the file, read, validated, checked (ImporterSceneError) and post-processed
// under one ScopedAllocationCap, so a count in the body that no header check sees is one error
// instead of gigabytes. Throws DomainError.
const aiScene* ReadScene(Assimp::Importer& importer, const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code canonicalError;
    const std::filesystem::path canonical = std::filesystem::canonical(path, canonicalError);
    if (canonicalError)
        throw DomainError(Subject::kGeometry,
                          name + ": cannot read mesh: " + canonicalError.message());
    auto* files = new RegularFileSystem(canonical.parent_path());  // the importer deletes it
    importer.SetIOHandler(files);
    const std::uintmax_t fileBytes = std::filesystem::file_size(path);
    const std::uintmax_t capBytes = kReadBaseBytes + kReadBytesPerFileByte * fileBytes;
    const aiScene* scene = nullptr;
    std::string error;
    bool refused = false;
    {
        const ScopedAllocationCap cap(capBytes);
        try {
            // The post-processing steps assume a scene that is valid as Assimp defines it, and
            // Debian's Assimp aborts the process on a failed check inside them (a truncated PLY
            // file gave a mesh marked as polygons without one: tests/fuzz/seeds/mesh/
            // regress_ply_truncated.ply). So the file is read and validated first, its faces
            // checked, and only then post-processed.
            scene = importer.ReadFile(canonical.string(), aiProcess_ValidateDataStructure);
            if (scene != nullptr) error = ImporterSceneError(*scene, fileBytes);
            if (scene != nullptr && error.empty())
                scene = importer.ApplyPostProcessing(
                    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                    aiProcess_PreTransformVertices | aiProcess_SortByPType);
        } catch (const std::bad_alloc&) {
            scene = nullptr;  // refused again while Assimp handled a refusal
        }
        refused = cap.Refused();
    }
    if (!files->Refused().empty())
        throw DomainError(Subject::kGeometry, name + ": cannot read mesh: reading it would open " +
                                                  files->Refused() +
                                                  "; only regular files are read");
    if (refused)
        throw DomainError(Subject::kGeometry,
                          name + ": cannot read mesh: reading it needs more than " +
                              std::to_string(capBytes >> 20) +
                              " MiB (a count in the file larger than its data)");
    if (!error.empty())
        throw DomainError(Subject::kGeometry, name + ": cannot read mesh: " + error);
    if (scene == nullptr)
        throw DomainError(Subject::kGeometry,
                          name + ": cannot read mesh: " + OneLine(importer.GetErrorString()));
    return scene;
}

// Runs `read` under a ScopedAllocationCap of capBytes: a refusal becomes the one-line error
// ReadScene gives, any other failure "<name>: cannot read <format>: <reason>".
template <class T, class Read>
T ReadUnderCap(const std::string& name, const char* format, std::uintmax_t capBytes, Read read) {
    std::optional<T> result;
    std::optional<std::string> error;
    bool refused = false;
    {
        const ScopedAllocationCap cap(capBytes);
        try {
            result.emplace(read());
        } catch (const std::bad_alloc&) {
            // the cap refused, or the machine: told apart below
        } catch (const std::exception& e) {  // DomainError, or a library's own (length_error)
            error = e.what();
        }
        refused = cap.Refused();
    }
    if (refused)
        throw DomainError(Subject::kGeometry,
                          name + ": cannot read mesh: reading it needs more than " +
                              std::to_string(capBytes >> 20) +
                              " MiB (a count in the file larger than its data)");
    if (error)
        throw DomainError(Subject::kGeometry,
                          name + ": cannot read " + format + ": " + OneLine(*error));
    if (!result) throw std::bad_alloc();
    return std::move(*result);
}

std::uintmax_t ReadCapBytes(std::uintmax_t bytes) {
    return kReadBaseBytes + kReadBytesPerFileByte * bytes;
}

TriangleMesh LoadAssimpMesh(const std::filesystem::path& path) {
    const std::string name = path.string();
    Assimp::Importer importer;
    // Points and lines are removed by aiProcess_SortByPType rather than kept as degenerate meshes.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const aiScene* scene = ReadScene(importer, path);

    TriangleMesh mesh;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* in = scene->mMeshes[m];
        if (!(in->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const auto offset = static_cast<unsigned long long>(mesh.positions.size());
        if (offset + in->mNumVertices > std::numeric_limits<unsigned>::max())
            throw DomainError(Subject::kGeometry, name + ": too many vertices");
        for (unsigned v = 0; v < in->mNumVertices; ++v) {
            const aiVector3D& p = in->mVertices[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw DomainError(Subject::kGeometry, name + ": vertex " + std::to_string(v) +
                                                          " of mesh " + std::to_string(m) +
                                                          " has a non-finite coordinate");
            mesh.positions.push_back({p.x, p.y, p.z});
        }
        for (unsigned f = 0; f < in->mNumFaces; ++f) {
            const aiFace& face = in->mFaces[f];
            if (face.mNumIndices != 3) continue;  // stray points or lines in a mixed mesh
            mesh.triangles.push_back(
                glm::uvec3(face.mIndices[0], face.mIndices[1], face.mIndices[2]) +
                glm::uvec3(static_cast<unsigned>(offset)));
        }
    }
    if (mesh.triangles.empty())
        throw DomainError(Subject::kGeometry, name + ": the file holds no triangles");
    return mesh;
}

// glTF in two passes, each under its cap: the buffer files found and sized first, then the
// document and its buffers read under a cap that counts them too.
LoadedMesh LoadGltfMesh(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = ReadRegularFile(path, kMaxMeshFileBytes);
    const bool binary = IsBinaryGltf(bytes);
    const std::filesystem::path directory = path.parent_path();
    const GltfBufferFiles files = ReadUnderCap<GltfBufferFiles>(
        name, "glTF", ReadCapBytes(bytes.size()),
        [&] { return FindGltfBufferFiles(bytes, binary, directory); });
    return {
        ReadUnderCap<TriangleMesh>(name, "glTF", ReadCapBytes(bytes.size() + files.bytes),
                                   [&] { return ReadGltfMesh(bytes, binary, directory, files); }),
        binary ? "glTF 2.0 (binary)" : "glTF 2.0 (JSON)"};
}

LoadedMesh LoadPlyMesh(const std::filesystem::path& path) {
    const std::string bytes = ReadRegularFile(path, kMaxMeshFileBytes);
    LoadedMesh loaded{ReadUnderCap<TriangleMesh>(path.string(), "PLY", ReadCapBytes(bytes.size()),
                                                 [&] { return ReadPlyMesh(bytes); }),
                      {}};
    loaded.format = std::string("PLY (") + PlyEncodingName(ReadPlyEncoding(bytes)) + ")";
    return loaded;
}

}  // namespace

LoadedMesh LoadMeshFile(const std::filesystem::path& path) {
    CheckMeshFile(path);  // size, format and declared counts, before Assimp allocates for them
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (extension == ".PLY") return LoadPlyMesh(path);
    if (extension == ".GLTF" || extension == ".GLB") return LoadGltfMesh(path);
    return {LoadAssimpMesh(path), extension.substr(1)};  // OBJ, OFF, STL
}

TriangleMesh LoadMesh(const std::filesystem::path& path) { return LoadMeshFile(path).mesh; }

}  // namespace lexel::spatial
