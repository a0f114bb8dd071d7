#include "lexel/cases/load/json_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "lexel/solvers/errors.h"

namespace lexel::cases {
namespace {

std::string ErrorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(JsonReader, ParseErrorsNameLineAndColumn) {
    const std::string text = "{\n  \"a\": 1,\n  \"b\": [1, 2,,]\n}";
    const std::string message = ErrorOf([&] { ParseJsonText(text, "case.json"); });
    EXPECT_EQ(message.rfind("case.json:3:14: invalid JSON: ", 0), 0u) << message;
}

// Nlohmann's lexer ends the input at a NUL byte, so `{...}\0 garbage` was read as
// `{...}`. A NUL anywhere is refused with its line and column.
TEST(JsonReader, NulBytesAreRefused) {
    using namespace std::string_literals;
    EXPECT_EQ(ErrorOf([] { ParseJsonText("{\"a\": 1}\0 garbage"s, "case.json"); }),
              "case.json:1:9: invalid JSON: a NUL byte (a case file is text)");
    EXPECT_EQ(ErrorOf([] { ParseJsonText("{\n  \"a\": \"x\0y\"\n}"s, "case.json"); }),
              "case.json:2:10: invalid JSON: a NUL byte (a case file is text)");
    EXPECT_EQ(ErrorOf([] { ParseJsonText("\0"s, "case.json"); }),
              "case.json:1:1: invalid JSON: a NUL byte (a case file is text)");
}

TEST(JsonReader, DuplicateKeysAreNamedByTheirPointer) {
    EXPECT_EQ(ErrorOf([] { ParseJsonText(R"({"name": "a", "name": "b"})", "case.json"); }),
              "case.json: /name: duplicate key (each key may appear once)");
    EXPECT_EQ(ErrorOf([] {
                  ParseJsonText(R"({"a": [1, {"b": 1, "c": [{"x": 1}, {"x": 2, "x": 3}]}]})",
                                "case.json");
              }),
              "case.json: /a/1/c/1/x: duplicate key (each key may appear once)");
    // The same key in different objects is fine; the pointer escapes "/" and "~" (RFC 6901).
    EXPECT_EQ(
        ErrorOf([] { ParseJsonText(R"({"a": {"x": 1}, "b": {"x": 2}, "x": [{"x": 1}]})", "c"); }),
        "no error");
    EXPECT_EQ(ErrorOf([] { ParseJsonText(R"({"a/b": {"~": 1, "~": 2}})", "c"); }),
              "c: /a~1b/~0: duplicate key (each key may appear once)");
}

TEST(JsonReader, ReadsOnlyRegularFilesOfBoundedSize) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("lexel_json_reader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    EXPECT_EQ(ErrorOf([] { ParseJsonFile("/dev/zero"); }),
              "/dev/zero: not a regular file (a case is a JSON file)");
    const auto fifo = dir / "fifo.json";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(ErrorOf([&] { ParseJsonFile(fifo); }),
              fifo.string() + ": not a regular file (a case is a JSON file)");
    EXPECT_EQ(ErrorOf([&] { ParseJsonFile(dir); }),
              dir.string() + ": not a regular file (a case is a JSON file)");
    EXPECT_EQ(ErrorOf([&] { ParseJsonFile(dir / "missing.json"); }),
              (dir / "missing.json").string() + ": cannot open the case file");
    const auto big = dir / "big.json";
    {
        std::ofstream out(big, std::ios::binary);
        out << "[" << std::string(kMaxCaseFileBytes, ' ') << "]";
    }
    EXPECT_EQ(ErrorOf([&] { ParseJsonFile(big); }),
              big.string() + ": larger than 16 MiB, the most a case file may be");
    std::filesystem::resize_file(big, kMaxCaseFileBytes - 1);  // "[" and spaces: cut, not too big
    EXPECT_NE(ErrorOf([&] { ParseJsonFile(big); }).find("invalid JSON"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(JsonReader, FieldsNameTheirPointer) {
    const auto doc = nlohmann::json::parse(R"({"camera": {"fov_deg": 190, "pixels": 2.5, "name": 3,
        "position": [1, "x"], "a/b": 1}, "list": [1, 2]})");
    const JsonField root(doc, "");
    EXPECT_EQ(ErrorOf([&] { root["camera"]["fov_deg"].NumberIn(0, 180, true, true); }),
              "/camera/fov_deg: must be in (0, 180), got 190");
    EXPECT_EQ(ErrorOf([&] { root["camera"]["pixels"].Integer(1, 100); }),
              "/camera/pixels: must be an integer, got 2.5");
    EXPECT_EQ(ErrorOf([&] { root["camera"]["name"].String(); }),
              "/camera/name: must be a string, got an integer");
    EXPECT_EQ(ErrorOf([&] { root["camera"]["position"].Vec2(); }),
              "/camera/position/1: must be a number, got a string");
    EXPECT_EQ(ErrorOf([&] { root["camera"]["missing"]; }),
              "/camera/missing: required key is missing");
    EXPECT_EQ(ErrorOf([&] { root["list"].Vec3(); }),
              "/list: must be an array of 3 numbers, got 2 elements");
    EXPECT_EQ(ErrorOf([&] {
                  root["camera"].ExpectObject({"fov_deg", "pixels", "name", "position"});
              }),
              "/camera/a~1b: unknown key (allowed here: fov_deg, pixels, name, position)");
    EXPECT_EQ(ErrorOf([&] { root["list"].ExpectObject({}); }),
              "/list: must be an object, got an array");
}

// Keys and values with control characters are quoted escaped, so every message is one line
// (found by tests/fuzz/flatland_case_fuzzer).
TEST(JsonReader, MessagesQuoteControlCharactersEscaped) {
    const auto doc = nlohmann::json::parse(R"({"a\nb": 1, "kind": "x\ty\u0001"})");
    const JsonField root(doc, "");
    EXPECT_EQ(ErrorOf([&] { root.ExpectObject({"kind"}); }),
              "/a\\nb: unknown key (allowed here: kind)");
    EXPECT_EQ(ErrorOf([&] { root["kind"].Fail("got '" + root["kind"].String() + "'"); }),
              "/kind: got 'x\\ty\\u0001'");
    EXPECT_EQ(ErrorOf([] { ParseJsonText("{\"a\\nb\": 1, \"a\\nb\": 2}", "c"); }),
              "c: /a\\nb: duplicate key (each key may appear once)");
}

TEST(JsonReader, NonFiniteNumbersAreRejected) {
    // JSON has no NaN literal (a parse error), and overflowing literals are refused.
    EXPECT_NE(ErrorOf([] { ParseJsonText(R"({"x": NaN})", "c.json"); }).find("c.json:1:"),
              std::string::npos);
    EXPECT_EQ(ErrorOf([] { ParseJsonText(R"({"x": 1e999})", "c.json"); }),
              "c.json:1:7: /x: number 1e999 does not fit a double (numbers must be finite)");
}

TEST(JsonReader, NumberOverflowNamesPointerLineAndColumn) {
    // The literal's own line and column, and the pointer of the value inside nested arrays and
    // objects; a string holding the same characters earlier is not mistaken for it.
    const std::string text =
        "{\n  \"description\": \"-1e400\",\n  \"geometry\": [[[0, 1], [2, 3]],\n"
        "               [[4, 5], [6, -1e400]]]\n}\n";
    EXPECT_EQ(ErrorOf([&] { ParseJsonText(text, "c.json"); }),
              "c.json:4:29: /geometry/1/1/1: number -1e400 does not fit a double (numbers must "
              "be finite)");
    EXPECT_EQ(ErrorOf([] { ParseJsonText("1e400", "c.json"); }),
              "c.json:1:1: /: number 1e400 does not fit a double (numbers must be finite)");
    EXPECT_EQ(ErrorOf([] { ParseJsonText(R"({"a": {"b": [1, {"c": 2E+309}]}})", "c.json"); }),
              "c.json:1:23: /a/b/1/c: number 2E+309 does not fit a double (numbers must be "
              "finite)");
    // A document built in memory can still hold infinity; the reader refuses it.
    nlohmann::json doc;
    doc["x"] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(ErrorOf([&] { JsonField(doc, "")["x"].Number(); }), "/x: must be finite, got inf");
}

}  // namespace
}  // namespace lexel::cases
