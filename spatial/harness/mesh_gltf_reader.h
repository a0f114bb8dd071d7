// glTF 2.0 meshes (Khronos, "glTF 2.0 Specification", 2021; the format engines and asset stores
// ship, Filament's own) for the `mesh` entries of 3D cases, through tinygltf (Debian's
// libtinygltf-dev, compiled into this file without image decoding or a file system of its own),
// with every accessor read by lexel under checked bounds. Assimp 5.2's glTF 2 importer is not used:
// tinygltf parses the JSON into plain records and touches no buffer data, so every byte lexel reads
// is a checked one, and it is instrumented with lexel's code under the fuzzer.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// The deepest nesting of JSON arrays and objects read (tinygltf copies `extras` and `extensions`
// recursively, so a deeper document could exhaust the stack). glTF's own structure is 6 deep.
inline constexpr int kMaxGltfJsonDepth = 100;

// Whether glTF bytes are a binary .glb (they start with the magic "glTF") rather than JSON; the
// loader tells the two apart by this, not by the extension.
bool IsBinaryGltf(std::string_view bytes);

// The external buffer files a glTF file names (`buffers[].uri` that are not data: URIs), resolved
// as tinygltf resolves them: the URI percent-decoded and joined to the file's directory.
struct GltfBufferFiles {
    std::vector<std::string> paths;
    std::uintmax_t bytes = 0;  // their sizes added up
};

// The first pass over a glTF file's bytes (the whole .gltf, or the .glb with its JSON chunk): the
// JSON's nesting is checked and its external buffer files found, each a regular file of at most
// kMaxMeshFileBytes, together at most kMaxMeshFileBytes, so the caller can size the reading's
// allocation cap before tinygltf reads them. `directory` is the file's. Throws DomainError
// (Subject::kGeometry) with the reason (no file name): JSON nested deeper than kMaxGltfJsonDepth,
// a buffer file that is missing or not a regular file (saying what it is) or too large. Malformed
// JSON is left to ReadGltfMesh, which reports it.
GltfBufferFiles FindGltfBufferFiles(std::string_view bytes, bool binary,
                                    const std::filesystem::path& directory);

// The triangles of the file's default scene (`scene`, else scene 0) in its space (glTF: +y up,
// metres): every node reached from the scene's roots, each node's matrix or translation · rotation
// · scale composed with its parents', every instance of a mesh (one mesh under several nodes)
// placed by its node; of every primitive of mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN the
// POSITION accessor (VEC3 of FLOAT, sparse or not) and the indices (unsigned byte, short or int),
// or the vertices in order without them. Points and lines are dropped; a node whose transform has a
// negative determinant has its triangles' winding reversed (glTF's rule), so faces stay
// counter-clockwise. Skins, morph targets, materials, textures and images are not read (images are
// not decoded). Only the files in `files` (FindGltfBufferFiles) are opened.
//
// Throws DomainError (Subject::kGeometry) with the reason (tinygltf's on one line for a document it
// cannot parse: bad JSON, a missing required property, a buffer whose size is not its byteLength,
// a bad .glb header or chunk): a required extension that changes geometry (Draco or meshopt
// compression, quantization, GPU instancing; others, such as materials, are ignored), no scene or a
// default scene that does not exist, a node or mesh index out of range, a node reached twice (nodes
// form trees), a transform with a non-finite or malformed value, an accessor of the wrong type or
// component type, one that reaches past its buffer view or a view past its buffer, an index past
// the vertices, a TRIANGLES index count not a multiple of 3, a non-finite position or one beyond
// float range once placed, more than 2^32 − 1 vertices, or no triangle.
TriangleMesh ReadGltfMesh(std::string_view bytes, bool binary,
                          const std::filesystem::path& directory, const GltfBufferFiles& files);

}  // namespace lexel::spatial
