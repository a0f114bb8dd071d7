// A case's name is the stem of its output files: names that would leave --out, hide a
// NUL or a newline, or exceed kMaxCaseNameBytes are refused by both loaders with "/name: ...".
#include "lexel/cases/load/case_name.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {
namespace {

const char* kFlat = R"({
  "camera":   {"position": [0, 2], "direction": [2, -0.5], "fov_deg": 60, "pixels": 100},
  "light":    {"position": [-3, 10]},
  "lexels":   100,
  "geometry": [ [[-50, 0], [200, 0]] ]
})";

const char* kSpatial = R"({
  "camera": {"position": [0, 1.7, -10], "target": [0, 1, 0], "fov_y_deg": 50,
             "width": 64, "height": 48, "near": 0.5, "far": 80},
  "lights": [{"type": "point", "position": [3, 20, -4]}],
  "geometry": [{"primitive": "plane", "transform": {"scale": [20, 1, 20]}}]
})";

// The loader's error for `name` given as /name (or, when absent, as the file stem).
std::string FlatError(const std::optional<std::string>& name, const std::string& stem = "x") {
    nlohmann::json doc = nlohmann::json::parse(kFlat);
    if (name) doc["name"] = *name;
    try {
        return FlatSceneFromJson(doc, stem).name == (name ? *name : stem) ? "ok" : "wrong name";
    } catch (const InputError& e) {
        return e.what();
    }
}

std::string SpatialError(const std::optional<std::string>& name, const std::string& stem = "x") {
    nlohmann::json doc = nlohmann::json::parse(kSpatial);
    if (name) doc["name"] = *name;
    try {
        return SpatialSceneFromJson(doc, stem, ".").name == (name ? *name : stem) ? "ok"
                                                                                  : "wrong name";
    } catch (const InputError& e) {
        return e.what();
    }
}

TEST(CaseName, AcceptsPlainStems) {
    for (const std::string name : {"single_plane", "a.b", "Straße-2 (copy)", ".hidden", "x"}) {
        EXPECT_EQ(CaseNameProblem(name), std::nullopt) << name;
        EXPECT_EQ(FlatError(name), "ok") << name;
        EXPECT_EQ(SpatialError(name), "ok") << name;
    }
    EXPECT_EQ(FlatError(std::string(kMaxCaseNameBytes, 'n')), "ok");
}

TEST(CaseName, RefusesNamesThatLeaveTheOutputDirectory) {
    for (auto* error : {&FlatError, &SpatialError}) {
        EXPECT_EQ((*error)("../x", "x"), "/name: not a safe file stem: contains '/'");
        EXPECT_EQ((*error)("/tmp/abs", "x"), "/name: not a safe file stem: contains '/'");
        EXPECT_EQ((*error)("a\\b", "x"), "/name: not a safe file stem: contains '\\'");
        EXPECT_EQ((*error)("..", "x"), "/name: not a safe file stem: contains '..'");
        EXPECT_EQ((*error)("a..b", "x"), "/name: not a safe file stem: contains '..'");
    }
}

TEST(CaseName, RefusesControlCharactersEmptyAndOverlongNames) {
    for (auto* error : {&FlatError, &SpatialError}) {
        EXPECT_EQ((*error)(std::string("a\0b", 3), "x"),
                  "/name: not a safe file stem: contains the control character U+0000");
        EXPECT_EQ((*error)("a\nb", "x"),
                  "/name: not a safe file stem: contains the control character U+000A");
        EXPECT_EQ((*error)("a\x7f", "x"),
                  "/name: not a safe file stem: contains the control character U+007F");
        EXPECT_EQ((*error)("", "x"), "/name: not a safe file stem: empty");
        EXPECT_EQ((*error)(std::string(kMaxCaseNameBytes + 1, 'n'), "x"),
                  "/name: not a safe file stem: 101 bytes, at most 100");
        EXPECT_EQ((*error)(std::string(300, 'n'), "x"),
                  "/name: not a safe file stem: 300 bytes, at most 100");
    }
}

TEST(CaseName, TheFileStemFallbackObeysTheSameRule) {
    for (auto* error : {&FlatError, &SpatialError}) {
        EXPECT_EQ((*error)(std::nullopt, "stem"), "ok");
        EXPECT_EQ((*error)(std::nullopt, "a..b"),
                  "/name: absent, and the file's stem is not a safe file stem: contains '..'");
        EXPECT_EQ((*error)(std::nullopt, "a\tb"),
                  "/name: absent, and the file's stem is not a safe file stem: contains the "
                  "control character U+0009");
    }
}

// A file stem of Latin-1 bytes ("caf\xE9") without /name passed, and the JSON report
// then failed after computing with nlohmann's "[json.exception.type_error.316]" (exit 1). Names
// must be UTF-8 (a /name string always is: the JSON parser checks it).
TEST(CaseName, RefusesNamesThatAreNotUtf8) {
    EXPECT_EQ(CaseNameProblem("caf\xC3\xA9"), std::nullopt);                    // é
    EXPECT_EQ(CaseNameProblem("\xE2\x82\xAC \xF0\x9F\x98\x80"), std::nullopt);  // € and U+1F600
    const std::pair<std::string, std::string> refused[] = {
        {"caf\xE9", "byte 0xE9 at offset 3"},           // Latin-1 é: a lead byte without its tail
        {"a\xC3", "byte 0xC3 at offset 1"},             // cut short
        {"\xC0\xAF", "byte 0xC0 at offset 0"},          // overlong '/'
        {"\xED\xA0\x80", "byte 0xED at offset 0"},      // a surrogate, U+D800
        {"\xF4\x90\x80\x80", "byte 0xF4 at offset 0"},  // past U+10FFFF
        {"ok\x80", "byte 0x80 at offset 2"},            // a lone continuation byte
    };
    for (const auto& [name, where] : refused)
        EXPECT_EQ(CaseNameProblem(name), "not a safe file stem: not UTF-8 (" + where + ")");
    for (auto* error : {&FlatError, &SpatialError})
        EXPECT_EQ((*error)(std::nullopt, "caf\xE9"),
                  "/name: absent, and the file's stem is not a safe file stem: not UTF-8 (byte "
                  "0xE9 at offset 3)");
}

}  // namespace
}  // namespace lexel::cases
