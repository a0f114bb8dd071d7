#include "lexel/cases/load/flatland_case.h"

#include <gtest/gtest.h>

#include "lexel/cases/load/json_reader.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {
namespace {

const char* kGood = R"({
  "name": "single_plane",
  "camera":   {"position": [0, 2], "direction": [2, -0.5], "fov_deg": 60, "pixels": 1000},
  "light":    {"position": [-3, 10]},
  "lexels":   1000,
  "geometry": [ [[-50, 0], [200, 0]],  [[6, 0], [6, 2], [8, 2.5]] ],
  "decision_pixels": 100,
  "frusta": {"max": 8, "budget": 3, "metric": "l2"}
})";

std::string ErrorFor(const std::string& pointerPatch) {
    nlohmann::json doc = nlohmann::json::parse(kGood);
    doc = doc.patch(nlohmann::json::parse(pointerPatch));
    try {
        FlatSceneFromJson(doc, "x");
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// 10^8 camera pixels with a second decision pass of 9·10^7 need
// 32 (10^8 + 9·10^7) + max(32·9·10^7, 16·9·10^7 + 8·10^8, 24·10^8) + 1 MiB ≈ 8.35 GiB
// (flatland/memory.h): refused before anything is allocated, naming the larger pixel count.
TEST(FlatlandCase, RefusesPixelsOverTheMemoryBudget) {
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/pixels", "value": 100000000},
                          {"op": "replace", "path": "/decision_pixels", "value": 90000000}])"),
              "/camera/pixels: needs about 8.35 GiB (100000000 camera pixels and 90000000 "
              "decision pixels in a second pass, 32 bytes per pass pixel and up to 32 more at the "
              "peak), above lexel's memory budget of 8 GiB");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/pixels", "value": 90000000},
                          {"op": "replace", "path": "/decision_pixels", "value": 100000000}])")
                  .substr(0, 40),
              "/decision_pixels: needs about 8.64 GiB (");
}

// The schema's largest camera, one pass (no decision_pixels): 64 · 10^8 bytes ≈ 5.96 GiB fits.
TEST(FlatlandCase, AcceptsTheLargestCameraInOnePass) {
    nlohmann::json doc = nlohmann::json::parse(kGood);
    doc["camera"]["pixels"] = kMaxPixels;
    doc.erase("decision_pixels");
    EXPECT_NO_THROW(FlatSceneFromJson(doc, "x"));
    doc["decision_pixels"] = kMaxPixels;  // the same pass
    EXPECT_NO_THROW(FlatSceneFromJson(doc, "x"));
}

TEST(FlatlandCase, LoadsEveryField) {
    const auto scene = FlatSceneFromJson(nlohmann::json::parse(kGood), "fallback");
    EXPECT_EQ(scene.name, "single_plane");
    EXPECT_NEAR(scene.camera.wsDirection.norm(), 1.0, 1e-15);
    EXPECT_NEAR(scene.camera.wsDirection.x(), 2 / std::sqrt(4.25), 1e-15);
    EXPECT_EQ(scene.camera.pixels, 1000);
    EXPECT_EQ(scene.lexels, 1000);
    EXPECT_EQ(scene.geometry.size(), 2u);
    EXPECT_EQ(scene.geometry[1].size(), 3u);
    EXPECT_EQ(scene.DecisionPixels(), 100);
    ASSERT_TRUE(scene.frusta.has_value());
    EXPECT_EQ(scene.frusta->max, 8);
    EXPECT_EQ(scene.frusta->budget, 3);
    EXPECT_EQ(scene.frusta->metric, Metric::kL2);
}

TEST(FlatlandCase, BadFieldsAreNamed) {
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/fov_deg", "value": 190}])"),
              "/camera/fov_deg: must be in (0, 180), got 190");
    EXPECT_EQ(ErrorFor(R"([{"op": "add", "path": "/camera/zoom", "value": 2}])"),
              "/camera/zoom: unknown key (allowed here: position, direction, fov_deg, pixels, "
              "near, far)");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/direction", "value": [0, 0]}])"),
              "/camera/direction: must be a non-zero vector");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/lexels", "value": 0}])"),
              "/lexels: must be in [1, 1000000000], got 0");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/geometry/1", "value": [[1, 1]]}])"),
              "/geometry/1: must have at least 2 elements, got 1");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/geometry/1", "value": [[1, 1], [1, 1]]}])"),
              "/geometry/1/0: zero-length segment (points 0 and 1 coincide)");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/light/position", "value": [10, 0]}])"),
              "/light/position: the light lies on segment 0 of polyline 0 (/geometry/0/0)");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/frusta/budget", "value": 9}])"),
              "/frusta/budget: must be in [1, 8], got 9");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/frusta/metric", "value": "linf"}])"),
              "/frusta/metric: must be one of l1, l2, got 'linf'");
    EXPECT_EQ(
        ErrorFor(
            R"([{"op": "add", "path": "/camera/far", "value": 1}, {"op": "add", "path": "/camera/near", "value": 2}])"),
        "/camera/far: must be greater than near (2), got 1");
    EXPECT_EQ(ErrorFor(R"([{"op": "remove", "path": "/light"}])"),
              "/light: required key is missing");
}

// Coordinates whose squared lengths overflow (±1e200, a camera or light at 1e300) or a
// scene whose squared lengths underflow (scaled by 1e-300) were reported as "zero-length
// segment"; each now names its field and the bound (flatland/scene.h).
TEST(FlatlandCase, OutOfRangeScenesGiveTheRealReason) {
    EXPECT_EQ(
        ErrorFor(
            R"([{"op": "replace", "path": "/geometry/0", "value": [[-1e200, 0], [1e200, 0]]}])"),
        "/geometry/0/0: coordinate too large: |x| = 1e+200, must be at most 1e+15");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/geometry/1/2", "value": [8, -1e200]}])"),
              "/geometry/1/2: coordinate too large: |x| = 1e+200, must be at most 1e+15");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/camera/position", "value": [1e300, 2]}])"),
              "/camera/position: coordinate too large: |x| = 1e+300, must be at most 1e+15");
    EXPECT_EQ(ErrorFor(R"([{"op": "replace", "path": "/light/position", "value": [-3, 1e300]}])"),
              "/light/position: coordinate too large: |x| = 1e+300, must be at most 1e+15");
    // "Zero" is relative: a segment 2 long in a scene 1.4e15 across is zero-length (1e-12 of the
    // size is 1414), and the message says so.
    EXPECT_EQ(
        ErrorFor(
            R"([{"op": "replace", "path": "/geometry/0", "value": [[-1e15, -1e15], [-1e15, 1e15]]}])"),
        "/geometry/1/0: zero-length segment (points 0 and 1 are 2 apart, within 1e-12 of the "
        "scene's size 1.41421e+15)");
    // A coordinate above the bound is refused; kGood scaled by 5e12 reaches it (200 · 5e12 = 1e15)
    // and loads.
    EXPECT_EQ(
        ErrorFor(R"([{"op": "replace", "path": "/geometry/0", "value": [[-1.5e15, 0], [1, 0]]}])"),
        "/geometry/0/0: coordinate too large: |x| = 1.5e+15, must be at most 1e+15");
    const auto scaled = [](double factor) {
        nlohmann::json doc = nlohmann::json::parse(kGood);
        const auto scale = [factor](nlohmann::json& point) {
            for (auto& x : point) x = x.get<double>() * factor;
        };
        scale(doc["camera"]["position"]);
        scale(doc["light"]["position"]);
        for (auto& polyline : doc["geometry"])
            for (auto& point : polyline) scale(point);
        return doc;
    };
    EXPECT_NO_THROW(FlatSceneFromJson(scaled(5e12), "x"));

    // kGood scaled by 1e-300: the size is |camera - (200, 0) · 1e-300| = √(200² + 2²) · 1e-300.
    std::string error = "no error";
    try {
        FlatSceneFromJson(scaled(1e-300), "x");
    } catch (const InputError& e) {
        error = e.what();
    }
    EXPECT_EQ(error,
              "/geometry: the scene is too small: its size (the largest distance from the camera "
              "to the light or a geometry point) is 2.0001e-298, must be at least 1e-15");
    // The same scene at 1e-10 is inside the bounds and loads: "zero" is relative to the size.
    EXPECT_NO_THROW(FlatSceneFromJson(scaled(1e-10), "x"));
}

// A camera direction of any finite non-zero size normalizes (|[1e200, 0]|² overflows and
// |[1e-300, 0]|² underflows when normalized directly).
TEST(FlatlandCase, HugeAndTinyDirectionsNormalize) {
    for (const char* direction : {"[2e200, -0.5e200]", "[2e-300, -0.5e-300]"}) {
        nlohmann::json doc = nlohmann::json::parse(kGood);
        doc["camera"]["direction"] = nlohmann::json::parse(direction);
        const auto scene = FlatSceneFromJson(doc, "x");
        EXPECT_NEAR(scene.camera.wsDirection.x(), 2 / std::sqrt(4.25), 1e-15) << direction;
        EXPECT_NEAR(scene.camera.wsDirection.y(), -0.5 / std::sqrt(4.25), 1e-15) << direction;
    }
}

TEST(FlatlandCase, SpatialCasesAreRecognized) {
    EXPECT_TRUE(IsSpatialCase(nlohmann::json::parse(R"({"lights": []})")));
    EXPECT_FALSE(IsSpatialCase(nlohmann::json::parse(kGood)));
}

}  // namespace
}  // namespace lexel::cases
