// A strict PLY reader (see mesh_ply_reader.h): the header is parsed into elements and typed
// properties, the declared counts are held against the body's size, and the body is read value by
// value (ASCII tokens or binary in either byte order), the vertex positions and face fans kept and
// every other value checked against its type and skipped.
#include "lexel/spatial/harness/mesh_ply_reader.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel::spatial {
namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct PlyTypeName {
    const char* name;
    const char* sizedName;
    PlyType type;
    std::size_t bytes;
};
constexpr PlyTypeName kTypes[] = {
    {"char", "int8", PlyType::kInt8, 1},        {"uchar", "uint8", PlyType::kUint8, 1},
    {"short", "int16", PlyType::kInt16, 2},     {"ushort", "uint16", PlyType::kUint16, 2},
    {"int", "int32", PlyType::kInt32, 4},       {"uint", "uint32", PlyType::kUint32, 4},
    {"float", "float32", PlyType::kFloat32, 4}, {"double", "float64", PlyType::kFloat64, 8}};

const PlyTypeName& TypeInfo(PlyType type) { return kTypes[static_cast<int>(type)]; }
bool IsInteger(PlyType type) { return type != PlyType::kFloat32 && type != PlyType::kFloat64; }

struct PlyProperty {
    std::string name;
    PlyType type;                      // the value's type, or a list's items' type
    std::optional<PlyType> countType;  // a list: the type of its length
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::kAscii;
    std::vector<PlyElement> elements;
    std::size_t bodyAt = 0;    // the first byte after the end_header line
    std::size_t bodyLine = 0;  // the body's first line (ASCII messages)
};

[[noreturn]] void Fail(const std::string& reason) { throw DomainError(Subject::kGeometry, reason); }

// A name or token of the file for a message: at most 32 bytes, bytes outside printable ASCII
// (a NUL would end the message, a control character act on a terminal) as '?'.
std::string Printable(std::string_view token) {
    std::string shown(token.substr(0, 32));
    for (char& c : shown)
        if (c < 0x20 || c > 0x7e) c = '?';
    return token.size() > 32 ? shown + "..." : shown;
}

// Printable(token) quoted. Appended, not "'" + Printable(token): GCC 12 warns -Wrestrict falsely
// on a literal prepended to a temporary string (GCC bug 105329).
std::string Shown(std::string_view token) {
    std::string shown = "'";
    shown += Printable(token);
    shown += '\'';
    return shown;
}

bool IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::vector<std::string_view> Tokens(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && IsBlank(line[at])) ++at;
        const std::size_t start = at;
        while (at < line.size() && !IsBlank(line[at])) ++at;
        if (at > start) tokens.push_back(line.substr(start, at - start));
    }
    return tokens;
}

std::optional<PlyType> ParseType(std::string_view token) {
    for (const PlyTypeName& t : kTypes)
        if (token == t.name || token == t.sizedName) return t.type;
    return std::nullopt;
}

PlyType RequireType(std::string_view token, const std::string& where) {
    if (const std::optional<PlyType> type = ParseType(token)) return *type;
    Fail(where + ": unknown property type " + Shown(token) +
         " (PLY types: char, uchar, short, ushort, int, uint, float, double, or int8 ... float64)");
}

PlyEncoding ParseFormat(const std::vector<std::string_view>& tokens, const std::string& where) {
    if (tokens.size() != 3) Fail(where + ": the format line is not 'format ENCODING 1.0'");
    if (tokens[2] != "1.0")
        Fail(where + ": PLY version " + Shown(tokens[2]) + " (lexel reads version 1.0)");
    if (tokens[1] == "ascii") return PlyEncoding::kAscii;
    if (tokens[1] == "binary_little_endian") return PlyEncoding::kBinaryLittleEndian;
    if (tokens[1] == "binary_big_endian") return PlyEncoding::kBinaryBigEndian;
    Fail(where + ": format " + Shown(tokens[1]) +
         " is not ascii, binary_little_endian or binary_big_endian");
}

PlyElement ParseElement(const std::vector<std::string_view>& tokens, const std::string& where) {
    if (tokens.size() != 3) Fail(where + ": the element line is not 'element NAME COUNT'");
    PlyElement element{std::string(tokens[1]), 0, {}};
    const std::string_view count = tokens[2];
    const auto [end, error] =
        std::from_chars(count.data(), count.data() + count.size(), element.count);
    if (error != std::errc() || end != count.data() + count.size())
        Fail(where + ": element count " + Shown(count) + " is not an integer from 0 to 2^64 - 1");
    return element;
}

PlyProperty ParseProperty(const std::vector<std::string_view>& tokens, const std::string& where) {
    PlyProperty property;
    if (tokens.size() == 5 && tokens[1] == "list") {
        property.countType = RequireType(tokens[2], where);
        if (!IsInteger(*property.countType))
            Fail(where + ": a list's length type must be an integer type, got " + Shown(tokens[2]));
        property.type = RequireType(tokens[3], where);
        property.name = tokens[4];
    } else if (tokens.size() == 3 && tokens[1] != "list") {
        property.type = RequireType(tokens[1], where);
        property.name = tokens[2];
    } else {
        Fail(where +
             ": the property line is not 'property TYPE NAME' or 'property list COUNT_TYPE "
             "ITEM_TYPE NAME'");
    }
    return property;
}

// What ParseHeader knows between lines: whether the format line came, and the property names of
// the last element (a hash set, so that a header of n properties is read in O(n), not O(n^2)).
struct HeaderState {
    bool formatSeen = false;
    std::unordered_set<std::string> propertyNames;
};

// One header line into `header`; false at end_header.
bool ParseHeaderLine(std::string_view line, std::size_t lineNumber, HeaderState& state,
                     PlyHeader& header) {
    bool& formatSeen = state.formatSeen;
    const std::string where = "header line " + std::to_string(lineNumber);
    const std::vector<std::string_view> tokens = Tokens(line);
    if (tokens.empty()) return true;
    const std::string_view keyword = tokens[0];
    if (keyword == "comment" || keyword == "obj_info") return true;
    if (keyword == "end_header") {
        if (!formatSeen) Fail("the header has no format line");
        return false;
    }
    if (keyword == "format") {
        if (formatSeen || !header.elements.empty())
            Fail(where + ": a format line must come once, before the elements");
        header.encoding = ParseFormat(tokens, where);
        formatSeen = true;
    } else if (keyword == "element") {
        if (!formatSeen) Fail(where + ": an element before the format line");
        header.elements.push_back(ParseElement(tokens, where));
        state.propertyNames.clear();
        const std::string& name = header.elements.back().name;
        if ((name == "vertex" || name == "face") &&
            std::count_if(header.elements.begin(), header.elements.end(),
                          [&](const PlyElement& e) { return e.name == name; }) > 1)
            Fail(where + ": a second '" + name + "' element (a PLY file has one)");
    } else if (keyword == "property") {
        if (header.elements.empty()) Fail(where + ": a property before any element");
        PlyElement& element = header.elements.back();
        element.properties.push_back(ParseProperty(tokens, where));
        if (!state.propertyNames.insert(element.properties.back().name).second)
            Fail(where + ": element " + Shown(element.name) + " declares property " +
                 Shown(element.properties.back().name) + " twice");
    } else if (!header.elements.empty()) {
        // Before the first element an unknown line cannot change the body's layout (Blender 2.4
        // wrote its comment without the keyword); after it, it could hide a property.
        Fail(where + ": unknown keyword " + Shown(keyword) +
             " (header lines: format, comment, obj_info, element, property, end_header)");
    }
    return true;
}

PlyHeader ParseHeader(std::string_view bytes) {
    PlyHeader header;
    std::size_t at = 0, lineNumber = 0;
    HeaderState state;
    for (;;) {
        const std::size_t end = bytes.find('\n', at);
        std::string_view line =
            bytes.substr(at, end == std::string_view::npos ? bytes.npos : end - at);
        ++lineNumber;
        at = end == std::string_view::npos ? bytes.size() : end + 1;
        if (lineNumber == 1) {
            const std::vector<std::string_view> tokens = Tokens(line);
            if (tokens.size() != 1 || tokens[0] != "ply")
                Fail("not a PLY file: its first line is not 'ply'");
        } else if (!ParseHeaderLine(line, lineNumber, state, header)) {
            break;
        }
        if (end == std::string_view::npos) Fail("the header has no end_header line");
    }
    header.bodyAt = at;
    header.bodyLine = lineNumber + 1;
    return header;
}

// The fewest body bytes one item of `element` takes: binary, its scalars and list lengths (every
// list empty); ASCII, one character and one separator per property (a list's length).
double MinItemBytes(const PlyElement& element, PlyEncoding encoding) {
    double bytes = 0;
    for (const PlyProperty& p : element.properties)
        bytes += encoding == PlyEncoding::kAscii
                     ? 2.0
                     : double(TypeInfo(p.countType.value_or(p.type)).bytes);
    return bytes;
}

// Refuses declared counts the body cannot hold (ASCII: the last token needs no separator).
void CheckCounts(const PlyHeader& header, std::size_t bodyBytes) {
    const double room = double(bodyBytes) + (header.encoding == PlyEncoding::kAscii ? 1.0 : 0.0);
    double needed = 0;
    for (const PlyElement& element : header.elements) {
        needed += double(element.count) * MinItemBytes(element, header.encoding);
        if (needed > room)
            Fail("element " + Shown(element.name) + " declares " + std::to_string(element.count) +
                 " items, more than the " + std::to_string(bodyBytes) +
                 " bytes after the header can hold (a truncated or corrupt file)");
    }
}

// Integer range of an integer type.
bool FitsType(std::int64_t value, PlyType type) {
    switch (type) {
        case PlyType::kInt8:
            return value >= -128 && value <= 127;
        case PlyType::kUint8:
            return value >= 0 && value <= 255;
        case PlyType::kInt16:
            return value >= -32768 && value <= 32767;
        case PlyType::kUint16:
            return value >= 0 && value <= 65535;
        case PlyType::kInt32:
            return value >= std::numeric_limits<std::int32_t>::min() &&
                   value <= std::numeric_limits<std::int32_t>::max();
        case PlyType::kUint32:
            return value >= 0 && value <= std::numeric_limits<std::uint32_t>::max();
        default:
            return false;
    }
}

// ASCII body: whitespace-separated tokens, each checked against its property's type.
class AsciiBody {
  public:
    AsciiBody(std::string_view bytes, std::size_t at, std::size_t line)
        : bytes_(bytes), at_(at), line_(line) {}

    std::int64_t Integer(PlyType type) {
        std::string_view token = Next();
        if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || !FitsType(value, type))
            Fail(Shown(token) + " is not an integer of type " + TypeInfo(type).name);
        return value;
    }

    double Number(PlyType type) {
        if (IsInteger(type)) return static_cast<double>(Integer(type));
        std::string_view token = Next();
        if (token.size() > 1 && token[0] == '+') token.remove_prefix(1);
        double value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size())
            Fail(Shown(token) + " is not a number of type " + TypeInfo(type).name);
        if (type == PlyType::kFloat32 && std::isfinite(value) &&
            std::abs(value) > std::numeric_limits<float>::max())
            Fail(Shown(token) + " is beyond the range of a float");
        return value;
    }

    void Skip(PlyType type) { Number(type); }

    std::string Where() const { return "line " + std::to_string(line_); }

    // Refuses anything but whitespace after the last element.
    void Finish() {
        SkipWhitespace();
        if (at_ < bytes_.size())
            Fail(Where() + ": data after the last element (" + Shown(Next()) +
                 "): the header does not describe the file");
    }

  private:
    void SkipWhitespace() {
        for (; at_ < bytes_.size() && (IsBlank(bytes_[at_]) || bytes_[at_] == '\n'); ++at_)
            if (bytes_[at_] == '\n') ++line_;
    }

    std::string_view Next() {
        SkipWhitespace();
        if (at_ >= bytes_.size()) Fail("the file ends here (a truncated file)");
        const std::size_t start = at_;
        while (at_ < bytes_.size() && !IsBlank(bytes_[at_]) && bytes_[at_] != '\n') ++at_;
        return bytes_.substr(start, at_ - start);
    }

    std::string_view bytes_;
    std::size_t at_, line_;
};

// Binary body in either byte order.
class BinaryBody {
  public:
    BinaryBody(std::string_view bytes, std::size_t at, bool bigEndian)
        : bytes_(bytes), at_(at), swap_(bigEndian != (std::endian::native == std::endian::big)) {}

    std::int64_t Integer(PlyType type) {
        switch (type) {
            case PlyType::kInt8:
                return static_cast<std::int8_t>(Raw<std::uint8_t>());
            case PlyType::kUint8:
                return Raw<std::uint8_t>();
            case PlyType::kInt16:
                return static_cast<std::int16_t>(Raw<std::uint16_t>());
            case PlyType::kUint16:
                return Raw<std::uint16_t>();
            case PlyType::kInt32:
                return static_cast<std::int32_t>(Raw<std::uint32_t>());
            case PlyType::kUint32:
                return Raw<std::uint32_t>();
            default:
                Fail(std::string("a ") + TypeInfo(type).name + " where an integer is read");
        }
    }

    double Number(PlyType type) {
        if (type == PlyType::kFloat32) return std::bit_cast<float>(Raw<std::uint32_t>());
        if (type == PlyType::kFloat64) return std::bit_cast<double>(Raw<std::uint64_t>());
        return static_cast<double>(Integer(type));
    }

    void Skip(PlyType type) {
        Need(TypeInfo(type).bytes);
        at_ += TypeInfo(type).bytes;
    }

    std::string Where() const { return "byte " + std::to_string(at_); }

    void Finish() const {
        if (at_ < bytes_.size())
            Fail(std::to_string(bytes_.size() - at_) +
                 " bytes follow the last element: the header does not describe the file");
    }

  private:
    void Need(std::size_t bytes) const {
        if (bytes_.size() - at_ < bytes) Fail("the file ends here (a truncated file)");
    }

    template <class T>
    T Raw() {
        Need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        if (!swap_) return value;
        if constexpr (sizeof(T) == 2) return __builtin_bswap16(value);
        if constexpr (sizeof(T) == 4) return __builtin_bswap32(value);
        if constexpr (sizeof(T) == 8) return __builtin_bswap64(value);
        return value;
    }

    std::string_view bytes_;
    std::size_t at_;
    bool swap_;
};

// What each property of an element is read for.
enum class Role { kSkip, kX, kY, kZ, kIndices };

std::vector<Role> VertexRoles(const PlyElement& element) {
    std::vector<Role> roles(element.properties.size(), Role::kSkip);
    const char* axes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        const auto it = std::find_if(element.properties.begin(), element.properties.end(),
                                     [&](const PlyProperty& p) { return p.name == axes[axis]; });
        if (it == element.properties.end())
            Fail(std::string("element 'vertex' has no property '") + axes[axis] + "'");
        if (it->countType) Fail(std::string("vertex property '") + axes[axis] + "' is a list");
        roles[it - element.properties.begin()] = static_cast<Role>(1 + axis);
    }
    return roles;
}

std::vector<Role> FaceRoles(const PlyElement& element) {
    std::vector<Role> roles(element.properties.size(), Role::kSkip);
    for (const char* name : {"vertex_indices", "vertex_index"}) {
        const auto it = std::find_if(element.properties.begin(), element.properties.end(),
                                     [&](const PlyProperty& p) { return p.name == name; });
        if (it == element.properties.end()) continue;
        if (!it->countType || !IsInteger(it->type))
            Fail(std::string("face property '") + name +
                 "' must be a list of an integer type (property list uchar int " + name + ")");
        roles[it - element.properties.begin()] = Role::kIndices;
        return roles;
    }
    Fail("element 'face' has no list property 'vertex_indices' or 'vertex_index'");
}

// Reads one face's index list into fan triangles, each index checked against the vertices.
template <class Body>
void ReadFace(Body& body, const PlyProperty& list, std::uint64_t vertexCount,
              std::vector<glm::uvec3>& triangles) {
    const std::int64_t length = body.Integer(*list.countType);
    if (length < 0) Fail("its index list has the negative length " + std::to_string(length));
    std::uint32_t first = 0, previous = 0;
    for (std::int64_t k = 0; k < length; ++k) {
        const std::int64_t index = body.Integer(list.type);
        if (index < 0 || static_cast<std::uint64_t>(index) >= vertexCount)
            Fail("vertex index " + std::to_string(index) +
                 (index < 0 ? " is negative"
                            : " is past the file's " + std::to_string(vertexCount) + " vertices"));
        const auto vertex = static_cast<std::uint32_t>(index);
        if (k == 0) first = vertex;
        if (k >= 2) triangles.push_back({first, previous, vertex});
        previous = vertex;
    }
}

// A coordinate for a message.
std::string NumberText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// One property of an item: the face's index list, a coordinate, or a value checked and skipped.
template <class Body>
void ReadProperty(Body& body, const PlyProperty& p, Role role, std::uint64_t vertexCount,
                  glm::dvec3& position, TriangleMesh& mesh) {
    if (role == Role::kIndices) {
        ReadFace(body, p, vertexCount, mesh.triangles);
    } else if (p.countType) {
        const std::int64_t length = body.Integer(*p.countType);
        if (length < 0) Fail("the list has the negative length " + std::to_string(length));
        for (std::int64_t j = 0; j < length; ++j) body.Skip(p.type);
    } else if (role == Role::kSkip) {
        body.Skip(p.type);
    } else {
        const int axis = static_cast<int>(role) - 1;
        position[axis] = body.Number(p.type);
        if (!std::isfinite(position[axis]) ||
            std::abs(position[axis]) > std::numeric_limits<float>::max())
            Fail("the coordinate is " + NumberText(position[axis]) + ", not a finite float");
    }
}

// One item of an element; a vertex's position is appended to the mesh.
template <class Body>
void ReadItem(Body& body, const PlyElement& element, const std::vector<Role>& roles, bool isVertex,
              std::uint64_t vertexCount, TriangleMesh& mesh) {
    glm::dvec3 position(0.0);
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
        try {
            ReadProperty(body, element.properties[k], roles[k], vertexCount, position, mesh);
        } catch (const DomainError& e) {
            Fail("property " + Shown(element.properties[k].name) + " (" + body.Where() +
                 "): " + e.what());
        }
    }
    if (isVertex) mesh.positions.emplace_back(position);
}

template <class Body>
void ReadBody(const PlyHeader& header, Body& body, TriangleMesh& mesh) {
    std::uint64_t vertexCount = 0;
    for (const PlyElement& element : header.elements)
        if (element.name == "vertex") vertexCount = element.count;
    mesh.positions.reserve(vertexCount);  // bounded by the body's size (CheckCounts)
    for (const PlyElement& element : header.elements) {
        const bool isVertex = element.name == "vertex";
        const std::vector<Role> roles = isVertex ? VertexRoles(element)
                                        : element.name == "face"
                                            ? FaceRoles(element)
                                            : std::vector<Role>(element.properties.size());
        if (element.properties.empty()) continue;  // nothing of it is written, whatever its count
        for (std::uint64_t item = 0; item < element.count; ++item) {
            try {
                ReadItem(body, element, roles, isVertex, vertexCount, mesh);
            } catch (const DomainError& e) {
                Fail(Printable(element.name) + " " + std::to_string(item) + " of " +
                     std::to_string(element.count) + ", " + e.what());
            }
        }
    }
    body.Finish();
}

}  // namespace

const char* PlyEncodingName(PlyEncoding encoding) {
    switch (encoding) {
        case PlyEncoding::kAscii:
            return "ASCII";
        case PlyEncoding::kBinaryLittleEndian:
            return "binary little-endian";
        case PlyEncoding::kBinaryBigEndian:
            return "binary big-endian";
    }
    return "unknown";
}

PlyEncoding ReadPlyEncoding(std::string_view bytes) { return ParseHeader(bytes).encoding; }

TriangleMesh ReadPlyMesh(std::string_view bytes) {
    const PlyHeader header = ParseHeader(bytes);
    CheckCounts(header, bytes.size() - header.bodyAt);
    const auto vertex = std::find_if(header.elements.begin(), header.elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    if (vertex == header.elements.end()) Fail("the file has no vertex element");
    VertexRoles(*vertex);  // x, y and z before a vertex is reserved for
    if (vertex->count > std::numeric_limits<std::uint32_t>::max())
        Fail("it declares " + std::to_string(vertex->count) + " vertices, more than 2^32 - 1");
    TriangleMesh mesh;
    if (header.encoding == PlyEncoding::kAscii) {
        AsciiBody body(bytes, header.bodyAt, header.bodyLine);
        ReadBody(header, body, mesh);
    } else {
        BinaryBody body(bytes, header.bodyAt, header.encoding == PlyEncoding::kBinaryBigEndian);
        ReadBody(header, body, mesh);
    }
    if (mesh.triangles.empty()) Fail("it holds no triangles (no face of 3 or more vertices)");
    return mesh;
}

}  // namespace lexel::spatial
