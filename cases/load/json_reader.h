// Strict reading of case files: every value is reached through a JsonField that knows its JSON
// pointer, so every error names the field and the reason in one line, e.g.
//     /camera/fov_deg: must be in (0, 180), got 190
// Unknown keys, missing keys, wrong types, non-finite numbers and out-of-range values are errors.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace lexel::cases {

// The largest case file read (bytes): the shipped cases are a few KiB; meshes are separate files.
inline constexpr std::size_t kMaxCaseFileBytes = std::size_t{16} << 20;

// Reads and parses a JSON file. Throws InputError "FILE:LINE:COLUMN: reason" on a syntax error
// or a NUL byte, "FILE: POINTER: duplicate key ..." for a key repeated in one object, and
// "FILE: reason" when it cannot be read, is not a regular file, or is larger than
// kMaxCaseFileBytes.
nlohmann::json ParseJsonFile(const std::filesystem::path& path);
nlohmann::json ParseJsonText(const std::string& text, const std::string& sourceName);

// A case file read and parsed once (ParseJsonFile's checks and errors): the commands hand it on
// to the loaders rather than reading the file again.
struct CaseFile {
    std::filesystem::path path;
    std::string text;  // the bytes read (a sweep's identity hashes them)
    nlohmann::json document;
};
CaseFile ReadCaseFile(const std::filesystem::path& path);

class JsonField {
  public:
    JsonField(const nlohmann::json& value, std::string pointer)
        : value_(&value), pointer_(std::move(pointer)) {}

    const std::string& Pointer() const { return pointer_; }
    [[noreturn]] void Fail(const std::string& reason) const;

    // Requires an object whose keys are all in required ∪ optional and that has every required key.
    void ExpectObject(std::initializer_list<std::string_view> required,
                      std::initializer_list<std::string_view> optional = {}) const;
    // The same for keys known only at run time: an object with exactly these keys.
    void ExpectKeys(const std::vector<std::string>& keys) const;
    bool Has(std::string_view key) const;
    JsonField operator[](std::string_view key) const;

    std::vector<JsonField> Array(std::size_t minSize = 0) const;
    double Number() const;  // finite
    // lo/hi bounds; open bounds exclude the endpoint. Message: "must be in (lo, hi], got x".
    double NumberIn(double lo, double hi, bool loOpen, bool hiOpen) const;
    double Positive() const;  // (0, ∞)
    long long Integer(long long lo, long long hi) const;
    std::string String() const;
    Eigen::Vector2d Vec2() const;
    Eigen::Vector3d Vec3() const;

  private:
    const nlohmann::json* value_;
    std::string pointer_;
};

std::string FormatNumber(double value);  // shortest round-trip-ish form for messages

}  // namespace lexel::cases
