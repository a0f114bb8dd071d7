// PLY meshes (Turk, "The PLY Polygon File Format", 1994; the format of the Stanford scans, read by
// pbrt-v4 and Mitsuba) for the `mesh` entries of 3D cases: a strict reader of lexel's own. Assimp
// 5.2's PLY reader overflows its buffers on malformed files and CGAL 5.5's CGAL::IO::read_PLY
// dereferences null on a property before any element or on integer coordinates, hangs on an
// element of no properties and a huge count, and throws std::length_error on a negative list
// length (cases/README.md, "Bad input, limits and output files"), so neither reads lexel's input.
#pragma once

#include <string>
#include <string_view>

#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial {

// How a PLY body is written: the header's `format` line.
enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

// "ASCII", "binary little-endian", "binary big-endian".
const char* PlyEncodingName(PlyEncoding encoding);

// The triangles of a PLY file's bytes (the whole file). The header is `ply`, a `format` line
// (ascii, binary_little_endian or binary_big_endian, version 1.0), `comment` and `obj_info` lines,
// `element NAME COUNT` lines each followed by its `property TYPE NAME` and `property list
// COUNT_TYPE ITEM_TYPE NAME` lines, and `end_header`; lines end in "\n" or "\r\n". Types are char,
// uchar, short, ushort, int, uint, float, double or their sized names (int8 ... float64). Lines
// before the first element that are none of these (Blender 2.4's exporter wrote its comment
// without the keyword) are skipped; any other unknown line is refused, since it could hide a
// property and shift every value after it.
//
// Read: element `vertex` (properties x, y, z of any numeric type; coordinates within float range)
// and element `face` (the list `vertex_indices` or `vertex_index` of an integer type, indices from
// 0 to the vertex count − 1). A face of n ≥ 3 indices becomes the fan (0, i, i+1), i = 1 … n−2;
// faces of fewer (points, lines) are dropped. Every other element and property is skipped by its
// declared type. ASCII values are whitespace-separated tokens; a binary body holds exactly the
// declared elements.
//
// Throws DomainError (Subject::kGeometry) with the reason, without the file's name (the caller
// adds it): not a PLY file, an unknown keyword, type or format, a property before any element, a
// vertex or face element declared twice or missing what is read, declared counts more than the
// body's bytes can hold, a value that is not a number of its type (ASCII; the line is named), a
// negative list length, an index that is negative or past the vertices, a non-finite coordinate,
// a body that ends inside an element or has data after the last one, more than 2^32 − 1 vertices,
// or no triangle at all. Memory is proportional to the file: nothing is reserved from a count the
// body's size has not bounded.
TriangleMesh ReadPlyMesh(std::string_view bytes);

// The encoding a PLY file's header declares, read from its first bytes; throws DomainError like
// ReadPlyMesh when the header is not one.
PlyEncoding ReadPlyEncoding(std::string_view bytes);

}  // namespace lexel::spatial
