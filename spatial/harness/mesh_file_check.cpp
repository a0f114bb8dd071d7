// Declared counts against file size (see mesh_file_check.h). Each element a header declares needs
// at least a few bytes in the body; a header declaring more than the body can hold is refused
// before Assimp reserves memory for it.
#include "lexel/spatial/harness/mesh_file_check.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
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
Digits ReadDigits(std::string_view text, std::size_t& at) {
    Digits digits;
    for (; at < text.size() && text[at] >= '0' && text[at] <= '9'; ++at) {
        digits.wrapped = 10 * digits.wrapped + static_cast<std::uint32_t>(text[at] - '0');
        digits.value = 10 * digits.value + (text[at] - '0');
    }
    return digits;
}

// OFFLoader.cpp's NextToken (Assimp 5.2): blanks and line ends, then any '#' comment lines.
// `text` ends with the '\0' Assimp appends, which stops every loop.
void OffNextToken(std::string_view text, std::size_t& at) {
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
// `text` ends with the '\0' TextFileToBuffer appends; `end` is one past it.
struct OffCounts {
    Digits vertices, faces;
    std::size_t bodyAt = 0;  // where the vertex lines begin (after the edge count)
};
std::optional<OffCounts> AssimpOffCounts(std::string_view text) {
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
    OffNextToken(text, at);
    ReadDigits(text, at);  // the edge count, unused
    OffNextToken(text, at);
    counts.bodyAt = std::min(at, text.size() - 1);
    // Assimp refuses a count of 0; one that wraps to 0 is still checked, with the count written.
    if (counts.vertices.value == 0 || counts.faces.value == 0) return std::nullopt;
    return counts;
}

// Line ends as Assimp's IsLineEnd has them.
bool IsOffLineEnd(char c) { return c == '\r' || c == '\n' || c == '\f' || c == '\0'; }

// Assimp 5.2's GetNextLine: the line at `at` (empty at the text's '\0': no line), `at` moved past
// it and past every line end after it, so blank lines are skipped.
std::optional<std::string_view> OffNextLine(std::string_view text, std::size_t& at) {
    if (at >= text.size() || text[at] == '\0') return std::nullopt;
    const std::size_t begin = at;
    while (!IsOffLineEnd(text[at])) ++at;
    const std::string_view line = text.substr(begin, at - begin);
    while (at < text.size() && IsOffLineEnd(text[at]) && text[at] != '\0') ++at;
    return line;
}

// The 1-based line number of byte `at`.
std::size_t LineNumber(std::string_view text, std::size_t at) {
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n'));
}

// Assimp 5.2 reads each OFF face's indices with strtoul10 and clamps one past the vertices to
// the last vertex, so "-1" (no digits: 0) and "7" of 4 vertices (clamped to 3) make wrong
// triangles in silence. A line whose count is 0 or more than 9 (a comment among the faces, say)
// it drops without counting it, one face fewer each time, so the faces after it are lost or, past
// the declared count, read beyond the face array. Follows the reader line by line (vertex lines,
// then face lines until the declared faces are read) and refuses the first such line or index.
void CheckOffFaces(const std::filesystem::path& path, std::string_view text,
                   const OffCounts& counts) {
    std::size_t at = counts.bodyAt;
    for (double v = 0; v < counts.vertices.value; ++v)
        if (!OffNextLine(text, at)) return;  // Assimp reports the missing lines
    for (std::size_t face = 0; face < static_cast<std::size_t>(counts.faces.value); ++face) {
        const std::size_t lineAt = at;
        const std::optional<std::string_view> line = OffNextLine(text, at);
        if (!line) return;  // too few faces: their empty slots are refused after reading
        std::string body(*line);
        body.push_back('\0');
        std::size_t p = 0;
        const auto skipSpaces = [&] {
            while (body[p] == ' ' || body[p] == '\t') ++p;
        };
        skipSpaces();
        const std::string where = "face " + std::to_string(face) + " (line " +
                                  std::to_string(LineNumber(text, lineAt)) + ")";
        const Digits corners = ReadDigits(body, p);
        if (corners.wrapped == 0 || corners.wrapped > 9)
            Refuse(path, where +
                             ": not a face of 1 to 9 vertices (Assimp 5.2 drops such a line "
                             "and miscounts the faces after it)");
        for (std::uint32_t m = 0; m < corners.wrapped; ++m) {
            skipSpaces();
            const std::size_t tokenAt = p;
            const Digits index = ReadDigits(body, p);
            if (p == tokenAt) {
                const char next = body[p];
                if (next == '\0' || next == '#')
                    Refuse(path, where + " lists " + std::to_string(m) + " of its " +
                                     std::to_string(corners.wrapped) + " vertex indices");
                Refuse(path, where + ": vertex index " + std::to_string(m) + " is " +
                                 (next == '-' ? std::string("negative")
                                              : "not a number ('" + std::string(1, next) + "')") +
                                 "; OFF indices count vertices from 0");
            }
            if (index.value >= counts.vertices.value)
                Refuse(path, where + ": vertex index " + std::to_string(m) + " is " +
                                 CountText(index.value) + ", past the file's " +
                                 CountText(counts.vertices.value) + " vertices (0 to " +
                                 CountText(counts.vertices.value - 1) + ")");
        }
    }
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
    text.push_back('\0');                                    // TextFileToBuffer's terminator
    const std::optional<OffCounts> counts = AssimpOffCounts(text);
    if (!counts) return;  // Assimp reports the header's error
    const double vertices = counts->vertices.value, faces = counts->faces.value;
    CheckDeclared(path, (vertices + faces) * kMinLineBytes, size,
                  CountText(vertices) + " vertices and " + CountText(faces) + " faces");
    CheckOffFaces(path, text, *counts);
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

// What the path names when it is not a regular file ("a directory", ...), or empty. Nothing is
// opened: opening a FIFO blocks until a writer comes, and opening a device can act on it.
std::string NotRegularFile(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    switch (status.type()) {
        case fs::file_type::regular:
            return {};
        case fs::file_type::directory:
            return "is a directory, not a mesh file";
        case fs::file_type::fifo:
            return "is a FIFO (named pipe), not a mesh file";
        case fs::file_type::character:
            return "is a character device, not a mesh file";
        case fs::file_type::block:
            return "is a block device, not a mesh file";
        case fs::file_type::socket:
            return "is a socket, not a mesh file";
        case fs::file_type::not_found:
            if (fs::is_symlink(fs::symlink_status(path, error)))
                return "is a dangling symbolic link (mesh file not found)";
            return "mesh file not found";
        default:
            return "cannot be examined (" + error.message() + ")";
    }
}

}  // namespace

void CheckMeshFile(const std::filesystem::path& path) {
    std::error_code error;
    if (const std::string problem = NotRegularFile(path); !problem.empty()) Refuse(path, problem);
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) Refuse(path, "cannot read the mesh file's size");
    if (size > kMaxMeshFileBytes)
        Refuse(path, "is " + std::to_string(size) + " bytes, larger than the " +
                         std::to_string(kMaxMeshFileBytes >> 20) + " MiB a mesh file may be");
    const std::string extension = LowerExtension(path);
    if (extension == ".ply" || extension == ".gltf" || extension == ".glb") return;
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

std::string FileKind(::mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string ReadRegularFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) Refuse(path, "cannot open the file");
    struct stat st {};
    std::string bytes;
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    const bool small = regular && static_cast<std::uintmax_t>(st.st_size) <= maxBytes;
    if (small) {
        bytes.resize(static_cast<std::size_t>(st.st_size));
        std::size_t done = 0;
        while (done < bytes.size()) {
            const ::ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            done += static_cast<std::size_t>(n);
        }
        bytes.resize(done);  // a file that shrank while read is read as it is now
    }
    ::close(fd);
    if (!regular) Refuse(path, "is not a regular file");
    if (!small)
        Refuse(path, "is " + std::to_string(st.st_size) + " bytes, more than the " +
                         std::to_string(maxBytes) + " read");
    return bytes;
}

}  // namespace lexel::spatial
