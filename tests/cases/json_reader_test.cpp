#include "lexel/cases/load/json_reader.h"

#include <gtest/gtest.h>

#include <limits>

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

TEST(JsonReader, NonFiniteNumbersAreRejected) {
    // JSON has no NaN literal (a parse error), and overflowing literals are refused.
    EXPECT_NE(ErrorOf([] { ParseJsonText(R"({"x": NaN})", "c.json"); }).find("c.json:1:"),
              std::string::npos);
    EXPECT_EQ(ErrorOf([] { ParseJsonText(R"({"x": 1e999})", "c.json"); }),
              "c.json: invalid JSON: number overflow parsing '1e999' (numbers must be finite)");
    // A document built in memory can still hold infinity; the reader refuses it.
    nlohmann::json doc;
    doc["x"] = std::numeric_limits<double>::infinity();
    EXPECT_EQ(ErrorOf([&] { JsonField(doc, "")["x"].Number(); }), "/x: must be finite, got inf");
}

}  // namespace
}  // namespace lexel::cases
