// A 3D case's own methods (see case_methods.h and cases/README.md).
#include "lexel/cases/load/case_methods.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/light_space.h"

namespace lexel::cases {
namespace {

// A row-major 4×4 (4 arrays of 4 numbers) as glm's column-major m[c][r].
glm::dmat4 ReadMatrix(const JsonField& field) {
    const auto rows = field.Array();
    if (rows.size() != 4)
        field.Fail("must be a 4x4 matrix as 4 rows of 4 numbers, got " +
                   std::to_string(rows.size()) + " rows");
    glm::dmat4 m(0.0);
    for (int r = 0; r < 4; ++r) {
        const auto row = rows[r].Array();
        if (row.size() != 4)
            rows[r].Fail("must be a row of 4 numbers, got " + std::to_string(row.size()));
        for (int c = 0; c < 4; ++c) m[c][r] = row[c].Number();
    }
    return m;
}

std::string Trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t\r");
    return std::string(text.substr(first, last - first + 1));
}

// One CSV row of 16 numbers (row-major), or the reason it is not one.
std::optional<glm::dmat4> ParseCsvRow(const std::string& line, std::string* failure) {
    std::vector<double> numbers;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
        const std::string token = Trimmed(cell);
        double v = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (token.empty() || error != std::errc() || end != token.data() + token.size() ||
            !std::isfinite(v)) {
            // Its position, not its text: the file may be any file a case names.
            *failure = "cell " + std::to_string(numbers.size() + 1) + " is not a finite number";
            return std::nullopt;
        }
        numbers.push_back(v);
    }
    if (!line.empty() && line.back() == ',') numbers.push_back(0.0);  // counted as a 17th cell
    if (numbers.size() != 16) {
        *failure = "has " + std::to_string(numbers.size()) +
                   " numbers, expected 16 (a 4x4 clip matrix, row-major)";
        return std::nullopt;
    }
    glm::dmat4 m(0.0);
    for (int k = 0; k < 16; ++k) m[k % 4][k / 4] = numbers[k];
    return m;
}

// The matrices of a clip_from_world_csv file; blank lines and lines starting with '#' are skipped.
void ReadCsvMatrices(const JsonField& field, const std::filesystem::path& baseDir,
                     CaseMethodEntry* entry) {
    const std::filesystem::path given = field.String();
    if (given.empty()) field.Fail("must be a file path, got an empty string");
    const std::filesystem::path path = given.is_absolute() ? given : baseDir / given;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        field.Fail("cannot read " + path.string() + ": not a regular file");
    const auto bytes = std::filesystem::file_size(path, error);
    if (error || bytes > kMaxClipCsvBytes)
        field.Fail(path.string() + " is larger than " + std::to_string(kMaxClipCsvBytes >> 20) +
                   " MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) field.Fail("cannot read " + path.string());
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        // A UTF-8 byte order mark (spreadsheets write one) is skipped, as the JSON reader does.
        if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
        const std::string text = Trimmed(line);
        if (text.empty() || text.front() == '#') continue;
        const std::string where = path.filename().string() + ":" + std::to_string(number);
        std::string failure;
        const std::optional<glm::dmat4> m = ParseCsvRow(text, &failure);
        if (!m) field.Fail(where + ": " + failure);
        entry->method.clipFromWorld.push_back(*m);
        entry->where.push_back(field.Pointer() + ": " + where);
    }
}

// Which lights the matrices are for, by their count (see ReadCaseMethods).
void AssignLights(const JsonField& field, const spatial::Scene& scene, CaseMethodEntry* entry) {
    const std::size_t count = entry->method.clipFromWorld.size();
    if (!scene.lights.empty() && count == scene.lights.size()) return;
    if (scene.lightSweep && count == static_cast<std::size_t>(scene.lightSweep->count)) {
        entry->method.forSweep = true;
        return;
    }
    std::string expected;
    if (!scene.lights.empty())
        expected = std::to_string(scene.lights.size()) + " (the fixed lights, for lexel run)";
    if (scene.lightSweep)
        expected += (expected.empty() ? "" : " or ") + std::to_string(scene.lightSweep->count) +
                    " (light_sweep.count, for lexel sweep)";
    field.Fail("has " + std::to_string(count) + " matrices, expected one per light: " + expected);
}

}  // namespace

std::vector<CaseMethodEntry> ReadCaseMethods(const JsonField& methods, const spatial::Scene& scene,
                                             const std::filesystem::path& baseDir) {
    std::vector<CaseMethodEntry> entries;
    for (const JsonField& item : methods.Array()) {
        item.ExpectObject({"name"}, {"description", "clip_from_world", "clip_from_world_csv"});
        if (item.Has("description")) item["description"].String();
        CaseMethodEntry entry;
        const JsonField name = item["name"];
        entry.method.name = name.String();
        if (!spatial::IsValidMethodName(entry.method.name))
            name.Fail("must be 1 to 64 of A-Z a-z 0-9 _ . + - (not starting with -), got '" +
                      entry.method.name.substr(0, 64) + "'");
        if (spatial::IsSpatialMethod(entry.method.name))
            name.Fail("'" + entry.method.name +
                      "' clashes with a built-in method of that name; give yours another");
        for (const CaseMethodEntry& earlier : entries)
            if (earlier.method.name == entry.method.name)
                name.Fail("'" + entry.method.name + "' names an earlier method too");
        if (item.Has("clip_from_world") == item.Has("clip_from_world_csv"))
            item.Fail("must have exactly one of clip_from_world, clip_from_world_csv");
        const JsonField source =
            item[item.Has("clip_from_world") ? "clip_from_world" : "clip_from_world_csv"];
        if (item.Has("clip_from_world")) {
            for (const JsonField& matrix : source.Array(1)) {
                entry.method.clipFromWorld.push_back(ReadMatrix(matrix));
                entry.where.push_back(matrix.Pointer());
            }
        } else {
            ReadCsvMatrices(source, baseDir, &entry);
            if (entry.method.clipFromWorld.empty()) source.Fail("the file has no rows");
        }
        AssignLights(source, scene, &entry);
        entries.push_back(std::move(entry));
    }
    return entries;
}

namespace {

// The reason `clipFromWorld` cannot be light `light`'s map in this scene, or empty.
std::string MatrixFailure(const glm::dmat4& clipFromWorld, const spatial::Light& light,
                          const spatial::Scene& scene, const spatial::Bounds& wsBounds) {
    // In the scene's unit frame, so that the test means the same at any scale and offset.
    const glm::dmat4 clipFromUnit = clipFromWorld * spatial::UnitFrameOf(wsBounds).WorldFromUnit();
    // |det| over the rows' lengths' product, ≤ 1 (Hadamard): the determinant of the rows made
    // unit, so that no scale of the matrix overflows it (before: 1e76 times a map gave NaN).
    glm::dmat4 unitRows = clipFromUnit;
    for (int r = 0; r < 4; ++r) {
        const glm::dvec4 row(clipFromUnit[0][r], clipFromUnit[1][r], clipFromUnit[2][r],
                             clipFromUnit[3][r]);
        const double largest =
            std::max({std::abs(row.x), std::abs(row.y), std::abs(row.z), std::abs(row.w)});
        const double length = largest > 0.0 ? largest * glm::length(row / largest) : 0.0;
        for (int c = 0; c < 4; ++c) unitRows[c][r] = length > 0.0 ? row[c] / length : 0.0;
    }
    const double ratio = std::abs(glm::determinant(unitRows));
    if (!(ratio >= 1e-12))
        return "is singular (|det| is " + FormatNumber(ratio) +
               " of its rows' lengths' product in the scene's unit frame, must be at least 1e-12)";
    // A rasterizer clips what has w <= 0: a matrix with w < 0 at the scene's centre (a negated
    // one, say) draws nothing there, though it has the same projection.
    if (!((clipFromWorld * glm::dvec4(wsBounds.Center(), 1.0)).w > 0.0))
        return "has clip w <= 0 at the scene's centre, which a rasterizer clips (negated? w must "
               "be > 0 in front of the light)";
    try {
        const spatial::LightSpace lightSpace(light, wsBounds);
        std::string failure;
        if (!spatial::LightMatrixFromClip(lightSpace, clipFromWorld, scene.shadowMap,
                                          wsBounds.Center(), &failure))
            return "does not project from its light: " + failure +
                   " (clip x, y and w must vanish at a point light, and along a directional "
                   "light's direction)";
    } catch (const DomainError& e) {
        return std::string("its light: ") + e.what();
    }
    return {};
}

std::vector<spatial::Light> CaseSweepLights(const spatial::Scene& scene,
                                            const spatial::Bounds& wsBounds) {
    return spatial::SweepLights(*scene.lightSweep, wsBounds.Center());
}

}  // namespace

void CheckCaseMethodMatrices(const std::vector<CaseMethodEntry>& entries,
                             const spatial::Scene& scene, const spatial::Bounds& wsBounds) {
    std::vector<spatial::Light> sweepLights;
    for (const CaseMethodEntry& entry : entries) {
        const spatial::CaseMethod& m = entry.method;
        if (m.forSweep && sweepLights.empty()) sweepLights = CaseSweepLights(scene, wsBounds);
        const std::vector<spatial::Light>& lights = m.forSweep ? sweepLights : scene.lights;
        for (std::size_t k = 0; k < m.clipFromWorld.size(); ++k) {
            const std::string failure =
                MatrixFailure(m.clipFromWorld[k], lights[k], scene, wsBounds);
            if (!failure.empty())
                throw InputError(entry.where[k] + ": the matrix for " +
                                 (m.forSweep ? "sweep light " : "light ") + std::to_string(k) +
                                 " " + failure);
        }
    }
}

std::vector<std::string> CaseMethodNames(const spatial::Scene& scene, bool forSweep) {
    std::vector<std::string> names;
    for (const spatial::CaseMethod& m : scene.methods)
        if (m.forSweep == forSweep) names.push_back(m.name);
    return names;
}

void CheckCaseMethodLights(const spatial::Scene& scene, const std::vector<std::string>& methods,
                           bool forSweep, const std::vector<spatial::Light>& lights) {
    const spatial::Bounds wsBounds = scene.geometry.ComputeBounds();
    for (std::size_t i = 0; i < scene.methods.size(); ++i) {
        const spatial::CaseMethod& m = scene.methods[i];
        if (std::find(methods.begin(), methods.end(), m.name) == methods.end()) continue;
        const std::string field = "/methods/" + std::to_string(i);
        if (m.forSweep != forSweep)
            throw InputError(field + ": '" + m.name + "' has one matrix per " +
                             (m.forSweep ? "light of the light sweep (for lexel sweep)"
                                         : "fixed light (for lexel run)") +
                             ", not per light of lexel " + (forSweep ? "sweep" : "run"));
        if (!forSweep) continue;  // the fixed lights' matrices were checked as the case was read
        if (m.clipFromWorld.size() < lights.size())
            throw InputError(field + ": '" + m.name + "' has " +
                             std::to_string(m.clipFromWorld.size()) + " matrices, the sweep has " +
                             std::to_string(lights.size()) + " lights (--lights)");
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const std::string failure =
                MatrixFailure(m.clipFromWorld[k], lights[k], scene, wsBounds);
            if (!failure.empty())
                throw InputError(field + ": '" + m.name + "': the matrix for sweep light " +
                                 std::to_string(k) + " " + failure + " (--light-type?)");
        }
    }
}

}  // namespace lexel::cases
