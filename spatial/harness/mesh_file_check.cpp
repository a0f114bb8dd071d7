// Declared counts against file size (see mesh_file_check.h). Each element a header declares needs
// at least a few bytes in the body; a header declaring more than the body can hold is refused
// before Assimp reserves memory for it.
#include "lexel/spatial/harness/mesh_file_check.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "lexel/solvers/errors.h"

namespace lexel::spatial {
namespace {

// The header bytes inspected (PLY and OFF headers are a few hundred bytes).
constexpr std::size_t kHeaderBytes = 64 * 1024;

// Fewest bytes one ASCII element can take: a vertex "0 0 0\n" (6), an OFF face "3 0 1 2\n" (8), a
// PLY element of one property "0\n" (2). A binary PLY element takes at least 1 byte a property
// (char), a binary STL facet exactly 50.
constexpr double kMinOffVertexBytes = 6, kMinOffFaceBytes = 8, kMinPlyAsciiBytes = 2;
constexpr double kStlFacetBytes = 50, kStlHeaderBytes = 84;

// A declared count for messages: exact while it is an integer a double holds, else "%.3g".
std::string CountText(double count) {
    char text[32];
    std::snprintf(text, sizeof text, count < 0x1p53 ? "%.0f" : "%.3g", count);
    return text;
}

[[noreturn]] void Refuse(const std::filesystem::path& path, const std::string& reason) {
    throw DomainError(Subject::kGeometry, path.string() + ": " + reason);
}

std::string ReadHead(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) Refuse(path, "cannot open the mesh file");
    std::string head(kHeaderBytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

void CheckDeclared(const std::filesystem::path& path, double neededBytes, std::uintmax_t size,
                   const std::string& what) {
    if (neededBytes > static_cast<double>(size))
        Refuse(path, "declares " + what + ", more than its " + std::to_string(size) +
                         " bytes can hold (a truncated or corrupt file)");
}

// A count as Assimp reads it (strtoul10: the leading decimal digits, whatever follows them), as a
// double so no count overflows; -1 when the token starts with no digit (Assimp's own error then).
// A stream's >> double would refuse "36end_header" and miss the count Assimp takes from it.
double LeadingCount(const std::string& token) {
    double count = -1;
    for (const char c : token) {
        if (c < '0' || c > '9') break;
        count = (count < 0 ? 0 : 10 * count) + (c - '0');
    }
    return count;
}

// OFF: "[ST][C][N][4][n]OFF" then "vertices faces edges" as Assimp reads them: the next tokens
// after the keyword, across lines and past comment lines, each count its leading digits.
void CheckOff(const std::filesystem::path& path, const std::string& head, std::uintmax_t size) {
    std::istringstream lines(head);
    std::string line;
    std::vector<std::string> tokens;
    for (bool keywordLine = true; tokens.size() < 3 && std::getline(lines, line);) {
        const auto first = line.find_first_not_of(" \t\r");
        if (first != std::string::npos && line[first] == '#') continue;
        std::istringstream words(line);
        std::string word;
        if (keywordLine) words >> word;  // the keyword (Assimp also allows counts after it)
        keywordLine = false;
        while (tokens.size() < 3 && words >> word) tokens.push_back(word);
    }
    if (tokens.empty()) return;  // Assimp reports the missing counts
    const double vertices = LeadingCount(tokens[0]);
    const double faces = tokens.size() > 1 ? std::max(0.0, LeadingCount(tokens[1])) : 0.0;
    if (vertices < 0) return;
    CheckDeclared(path, vertices * kMinOffVertexBytes + faces * kMinOffFaceBytes, size,
                  CountText(vertices) + " vertices and " + CountText(faces) + " faces");
}

// PLY: "element NAME COUNT" lines up to "end_header"; each element has at least one property.
void CheckPly(const std::filesystem::path& path, const std::string& head, std::uintmax_t size) {
    std::istringstream lines(head);
    std::string line;
    bool ascii = false;
    double neededBytes = 0, elements = 0;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            std::string kind;
            words >> kind;
            ascii = kind == "ascii";
        } else if (word == "element") {
            std::string name, countToken;
            if (!(words >> name >> countToken)) return;  // Assimp's error then
            const double count = LeadingCount(countToken);
            if (count < 0) return;
            elements += count;
            neededBytes += count;  // binary: ≥ 1 byte each; ASCII adjusted below
        } else if (word == "end_header") {
            break;
        }
    }
    if (ascii) neededBytes = elements * kMinPlyAsciiBytes;
    CheckDeclared(path, neededBytes, size, CountText(elements) + " elements");
}

// Binary STL: an 80-byte header, a 32-bit facet count, 50 bytes a facet. An ASCII STL ("solid"
// followed by text) declares nothing.
void CheckStl(const std::filesystem::path& path, const std::string& head, std::uintmax_t size) {
    const bool ascii =
        head.rfind("solid", 0) == 0 &&
        std::none_of(head.begin(), head.begin() + std::min<std::size_t>(head.size(), 512),
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
    if (extension != ".obj" && extension != ".off" && extension != ".ply" && extension != ".stl")
        Refuse(path, "format '" + extension +
                         "' is not read (mesh formats: " + std::string(kMeshFormats) + ")");
    const std::string head = ReadHead(path);
    if (extension == ".off") CheckOff(path, head, size);
    if (extension == ".ply") CheckPly(path, head, size);
    if (extension == ".stl") CheckStl(path, head, size);
}

}  // namespace lexel::spatial
