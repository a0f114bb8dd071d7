// Limits on the model files a 3D case may name, checked before Assimp reads a byte: Assimp
// allocates what a file's header declares (its own test file invalid/OutOfMemory.off declares
// 3.5e11 vertices in 309 bytes and takes gigabytes in seconds), so the declared counts are held
// against what the file's size can hold.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace lexel::spatial {

// The largest mesh file read (bytes). The meshes lexel ships or names are at most a few MiB;
// Assimp's memory grows with the file (about 10-30 bytes per byte of OBJ), so this bounds it.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{64} << 20;

// The formats read: OBJ, OFF and STL through Assimp, whose declared counts are checked here (OFF,
// binary STL) or that declare none (OBJ, ASCII STL), so memory stays proportional to the file; PLY
// through lexel's own reader (mesh_ply_reader.h: Assimp 5.2's PLY reader writes past its buffers on
// malformed files — a second vertex element overflows the vertex array, comment lines make it
// parse stale bytes of earlier lines as elements, a missing end_header makes it read without end);
// glTF 2.0 (.gltf, .glb) through tinygltf (mesh_gltf_reader.h).
inline constexpr const char* kMeshFormats = "obj, off, stl, ply, gltf, glb";

// Throws DomainError (Subject::kGeometry) naming the file and the reason when it is not a regular
// file (saying what it is: missing, a directory, a FIFO, a device, a socket; nothing is opened to
// find out), is larger than kMaxMeshFileBytes, has an extension outside kMeshFormats, starts with
// a UTF-16 or UTF-32 byte order mark, declares more vertices, faces or facets than its size can
// hold (the counts read where Assimp 5.2 reads them), or is an OFF file with a line of 4096 bytes
// or more (Assimp's line buffer) or a face whose vertex index is negative, missing or past the
// vertices (Assimp 5.2 reads "-1" as 0 and clamps a large index to the last vertex; the face and
// its line are named). Assimp picks its reader by the extension, so the checks do too. A PLY or
// glTF file gets the checks up to the extension's (its reader checks its counts itself).
void CheckMeshFile(const std::filesystem::path& path);

// What a file of mode `mode` (st_mode) that is not a regular file is, in words: "a directory",
// "a FIFO (named pipe)", "a character device", "a block device", "a socket".
std::string FileKind(::mode_t mode);

// All bytes of a regular file of at most maxBytes, opened without blocking (a FIFO put in its
// place after CheckMeshFile is refused, not waited on). Throws DomainError (Subject::kGeometry)
// "<path>: reason" when it cannot be opened, is not a regular file, is larger, or a read fails.
std::string ReadRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes);

}  // namespace lexel::spatial
