// Declared counts against file size (see mesh_file_check.h). Each element a header declares needs
// at least a few bytes in the body; a header declaring more than the body can hold is refused
// before Assimp reserves memory for it.
#include "lexel/spatial/harness/mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <string_view>
#include <system_error>
#include <utility>

#include "lexel/solvers/errors.h"

namespace lexel::spatial {
namespace {

// A binary STL's 80-byte header and 32-bit facet count, and the bytes read to tell an ASCII STL.
constexpr std::size_t kStlHeaderBytes = 84, kStlSniffBytes = 512;

// Fewest bytes one element can take in the body, so that a count above size / bytes cannot be
// the file's: an OFF vertex or face is a line ("0\n": Assimp reads missing coordinates as 0 and
// counts a face "0" it then drops), a binary STL facet exactly 50 bytes.
constexpr double kMinLineBytes = 2, kStlFacetBytes = 50;

// Assimp 5.2's OFF reader copies each body line into a 4096-byte buffer and then writes the
// terminating '\0' one past the line's last character: a line of 4096 bytes or more overflows it
// (GetNextLine in ParsingUtils.h).
constexpr std::size_t kOffLineBufferBytes = 4096;

// A declared count for messages: exact while it is an integer a double holds, else "%.3g".
std::string CountText(double count) {
    char text[32];
    std::snprintf(text, sizeof text, count < 0x1p53 ? "%.0f" : "%.3g", count);
    return text;
}

[[noreturn]] void Refuse(const std::filesystem::path& path, const std::string& reason) {
    throw DomainError(Subject::kGeometry, path.string() + ": " + reason);
}

// The first `bytes` bytes of the file (all of it for OFF: its counts can follow any number of
// comment lines, and every line's length is checked; the file is at most kMaxMeshFileBytes).
std::string ReadBytes(const std::filesystem::path& path, std::uintmax_t bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) Refuse(path, "cannot open the mesh file");
    std::string text(static_cast<std::size_t>(bytes), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
}

void CheckDeclared(const std::filesystem::path& path, double neededBytes, std::uintmax_t size,
                   const std::string& what) {
    if (neededBytes > static_cast<double>(size))
        Refuse(path, "declares " + what + ", more than its " + std::to_string(size) +
                         " bytes can hold (a truncated or corrupt file)");
}

// A number as Assimp's strtoul10 reads it at `at`: the leading decimal digits (none: 0), `at`
// moved past them. `wrapped` is Assimp's unsigned int (modulo 2^32), `value` the number the
// digits write (as a double, so none overflows; it is at least `wrapped`).
struct Digits {
    std::uint32_t wrapped = 0;
    double value = 0;
};
Digits ReadDigits(const std::string& text, std::size_t& at) {
    Digits digits;
    for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) {
        digits.wrapped = 10 * digits.wrapped + static_cast<std::uint32_t>(text[at] - '0');
        digits.value = 10 * digits.value + (text[at] - '0');
    }
    return digits;
}

// OFFLoader.cpp's NextToken (Assimp 5.2): blanks and line ends, then any '#' comment lines.
// `text` ends with the '\0' Assimp appends, which stops every loop.
void OffNextToken(const std::string& text, std::size_t& at) {
    const auto skipBlanks = [&] {
        while (text[at] == ' ' || text[at] == '\t' || text[at] == '\r' || text[at] == '\n') ++at;
    };
    skipBlanks();
    while (at < text.size() && text[at] == '#') {
        while (text[at] != '\r' && text[at] != '\n' && text[at] != '\0') ++at;
        skipBlanks();
    }
}

// The vertex and face counts Assimp 5.2's OFF reader takes from a file, followed statement by
// statement (OFFLoader.cpp, InternReadFile): the optional prefixes ST, C, N, 4 and n glued to
// "OFF", which the counts may follow without a blank ("OFF8 ..." declares 8 vertices); "n" puts
// a dimension before the counts. Empty where Assimp refuses the header before allocating.
struct OffCounts {
    Digits vertices, faces;
};
std::optional<OffCounts> AssimpOffCounts(std::string text) {
    text.push_back('\0');  // TextFileToBuffer's terminator; `end` is one past it
    const std::size_t end = text.size();
    std::size_t at = 0;
    const auto before = [&](std::size_t n) { return at + n < end; };  // Assimp's car < end - n
    OffNextToken(text, at);
    if (before(2) && text[at] == 'S' && text[at + 1] == 'T') at += 2;
    if (before(1) && text[at] == 'C') ++at;
    if (before(1) && text[at] == 'N') ++at;
    if (before(1) && text[at] == '4') ++at;
    const bool hasDimension = before(1) && text[at] == 'n';
    if (hasDimension) ++at;
    if (before(3) && text.compare(at, 3, "OFF") == 0) {
        at += 3;
        OffNextToken(text, at);
    } else {
        OffNextToken(text, at);
        if (!before(1) || text[at] < '0' || text[at] > '9') return std::nullopt;
    }
    if (hasDimension) {
        if (ReadDigits(text, at).wrapped > 3) return std::nullopt;
        OffNextToken(text, at);
    }
    OffCounts counts;
    OffNextToken(text, at);
    counts.vertices = ReadDigits(text, at);
    OffNextToken(text, at);
    counts.faces = ReadDigits(text, at);
    // Assimp refuses a count of 0; one that wraps to 0 is still checked, with the count written.
    if (counts.vertices.value == 0 || counts.faces.value == 0) return std::nullopt;
    return counts;
}

// The longest run of bytes between Assimp's line ends ('\r', '\n', '\f', '\0').
std::size_t LongestLine(std::string_view text) {
    std::size_t longest = 0, run = 0;
    for (const char c : text) {
        run = (c == '\r' || c == '\n' || c == '\f' || c == '\0') ? 0 : run + 1;
        longest = std::max(longest, run);
    }
    return longest;
}

void CheckOff(const std::filesystem::path& path, std::string text, std::uintmax_t size) {
    if (const std::size_t longest = LongestLine(text); longest >= kOffLineBufferBytes)
        Refuse(path, "has a line of " + std::to_string(longest) +
                         " bytes; Assimp 5.2 reads OFF lines of at most " +
                         std::to_string(kOffLineBufferBytes - 1));
    if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // TextFileToBuffer drops it too
    const std::optional<OffCounts> counts = AssimpOffCounts(std::move(text));
    if (!counts) return;  // Assimp reports the header's error
    const double vertices = counts->vertices.value, faces = counts->faces.value;
    CheckDeclared(path, (vertices + faces) * kMinLineBytes, size,
                  CountText(vertices) + " vertices and " + CountText(faces) + " faces");
}

// Binary STL: an 80-byte header, a 32-bit facet count, 50 bytes a facet. An ASCII STL ("solid"
// followed by text) declares nothing.
void CheckStl(const std::filesystem::path& path, const std::string& head, std::uintmax_t size) {
    const bool ascii =
        head.rfind("solid", 0) == 0 &&
        std::none_of(head.begin(), head.begin() + std::min(head.size(), kStlSniffBytes),
                     [](char c) { return c == '\0'; });
    if (ascii || head.size() < kStlHeaderBytes) return;  // Assimp reports a short file
    std::uint32_t facets = 0;
    std::memcpy(&facets, head.data() + 80, sizeof facets);  // little-endian on x86-64
    CheckDeclared(path, kStlHeaderBytes + kStlFacetBytes * facets, size,
                  std::to_string(facets) + " facets");
}

std::string LowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

// Assimp's TextFileToBuffer converts text marked as UTF-16 or UTF-32 (ConvertToUTF8), but 5.2
// discards what it converts and reads up to 3 bytes past the file doing so: such a file is
// refused. (A UTF-8 mark is dropped and read.)
bool StartsWithUtf16Or32Mark(std::string_view head) {
    using namespace std::string_view_literals;
    return head.starts_with("\xFF\xFE"sv) || head.starts_with("\xFE\xFF"sv) ||
           head.starts_with("\0\0\xFE\xFF"sv);
}

}  // namespace

void CheckMeshFile(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) Refuse(path, "mesh file not found");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) Refuse(path, "cannot read the mesh file's size");
    if (size > kMaxMeshFileBytes)
        Refuse(path, "is " + std::to_string(size) + " bytes, larger than the " +
                         std::to_string(kMaxMeshFileBytes >> 20) + " MiB a mesh file may be");
    const std::string extension = LowerExtension(path);
    if (extension == ".ply")
        Refuse(path,
               "PLY is not read: Assimp 5.2's PLY reader overflows its buffers on malformed "
               "files (convert the mesh to OBJ, OFF or STL)");
    if (extension != ".obj" && extension != ".off" && extension != ".stl")
        Refuse(path, "format '" + extension +
                         "' is not read (mesh formats: " + std::string(kMeshFormats) + ")");
    // One read: all of an OFF file, the head of the others.
    std::string text = ReadBytes(path, extension == ".off" ? size : kStlSniffBytes);
    if (StartsWithUtf16Or32Mark(text))
        Refuse(path,
               "is UTF-16 or UTF-32 text, which Assimp 5.2 does not read (save it as ASCII "
               "or UTF-8)");
    if (extension == ".off") CheckOff(path, std::move(text), size);
    if (extension == ".stl") CheckStl(path, text, size);
}

}  // namespace lexel::spatial
