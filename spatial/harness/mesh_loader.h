// Reading triangle meshes from model files (OBJ, OFF, STL, through Assimp) for the `mesh`
// geometry entries of 3D case files (cases/README.md).
#pragma once

#include <filesystem>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// Loads every triangle of the file's scene, with node transforms baked in (Assimp's
// aiProcess_PreTransformVertices) and identical vertices joined; polygons are triangulated, and
// point and line primitives are dropped. Only regular files are opened, the mesh file and those it
// names (an OBJ's material library): never a FIFO or a device. Throws DomainError
// (Subject::kGeometry), naming the file, when it fails CheckMeshFile (missing, not a regular file,
// too large, another format, counts its size cannot hold, OFF face indices that are no vertex),
// when a file it names is not a regular file, when reading it needs more than 64 MiB plus 64 bytes
// a file byte (ScopedAllocationCap), when Assimp cannot read it (Assimp's reason, on one line),
// when it holds no triangles, or when a coordinate is not finite. Prints nothing.
TriangleMesh LoadMesh(const std::filesystem::path& path);

}  // namespace lexel::spatial
