// Reading triangle meshes from model files (OBJ, OFF, STL through Assimp; PLY through lexel's
// reader; glTF 2.0 through tinygltf) for the `mesh` geometry entries of 3D case files
// (cases/README.md).
#pragma once

#include <filesystem>
#include <string>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// A mesh file as read: its triangles (in the file's own axes and units) and its format for
// people: "OBJ", "OFF", "STL", "PLY (ASCII)", "PLY (binary little-endian)", "PLY (binary
// big-endian)", "glTF 2.0 (JSON)" or "glTF 2.0 (binary)".
struct LoadedMesh {
    TriangleMesh mesh;
    std::string format;
};

// Loads every triangle of the file's scene, picking the reader by the extension (.obj, .off,
// .stl, .ply, .gltf, .glb; a glTF file is binary when it starts with "glTF", whichever of its two
// extensions it has). OBJ, OFF, STL: node transforms baked in (Assimp's
// aiProcess_PreTransformVertices), identical vertices joined, polygons triangulated, points and
// lines dropped. PLY: ReadPlyMesh (mesh_ply_reader.h). glTF: the default scene, ReadGltfMesh
// (mesh_gltf_reader.h). Only regular files are opened, the mesh file and those it names (an OBJ's
// material library, a glTF's buffer files): never a FIFO or a device. Throws DomainError
// (Subject::kGeometry), naming the file, when it fails CheckMeshFile (missing, not a regular file,
// too large, another format, counts its size cannot hold, OFF face indices that are no vertex),
// when a file it names is not a regular file, when reading it needs more than 64 MiB plus 64 bytes
// a file byte (a glTF's buffer files counted; ScopedAllocationCap), when its reader refuses it
// (the reader's reason, on one line: "FILE: cannot read PLY: ..."), when it holds no triangles,
// or when a coordinate is not finite. Prints nothing.
LoadedMesh LoadMeshFile(const std::filesystem::path& path);

// LoadMeshFile(path).mesh.
TriangleMesh LoadMesh(const std::filesystem::path& path);

}  // namespace lexel::spatial
