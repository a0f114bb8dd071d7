#include "lexel/cases/load/flatland_case.h"

#include <cmath>
#include <limits>

#include "lexel/cases/load/case_name.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/memory_budget.h"
#include "lexel/flatland/memory.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace {

// "<field>: <reason>" for a DomainError of a flatland scene (FlatlandInputError).
std::string FlatlandErrorMessage(const DomainError& e) {
    const auto [first, second] = e.index();
    std::string geometry = "/geometry";
    if (first >= 0) geometry += "/" + std::to_string(first);
    if (second >= 0) geometry += "/" + std::to_string(second);
    switch (e.subject()) {
        case Subject::kCamera:
            return "/camera/position: " + std::string(e.what()) +
                   (first >= 0 ? " (" + geometry + ")" : "");
        case Subject::kLight:
            return "/light/position: " + std::string(e.what()) +
                   (first >= 0 ? " (" + geometry + ")" : "");
        case Subject::kGeometry:
        case Subject::kSegment:
            return geometry + ": " + e.what();
        case Subject::kLexels:
            return "/lexels: " + std::string(e.what());
    }
    return e.what();
}

// Refuses a scene whose run would need more than the memory budget (flatland/memory.h), naming
// the larger pixel count. (The other sizes cannot reach the budget alone: kMaxWedges bounds the
// split's tables to about 1 GiB, and the geometry is bounded by the case file.)
void CheckMemoryBudget(const JsonField& root, const flatland::FlatScene& scene) {
    const flatland::FlatlandSizes sizes = flatland::SizesOf(scene);
    const double bytes = flatland::FlatlandRunBytes(sizes);
    const auto count = [](double n) { return std::to_string(static_cast<long long>(n)); };
    std::string what = count(sizes.pixels) + " camera pixels";
    if (sizes.decisionPixels != sizes.pixels)
        what += " and " + count(sizes.decisionPixels) + " decision pixels in a second pass";
    what += ", " + count(flatland::kPassBytesPerPixel) + " bytes per pass pixel and up to " +
            count(flatland::kRunBytesPerPixel - flatland::kPassBytesPerPixel) + " more at the peak";
    const std::string excess = MemoryBudgetExcess(bytes, what);
    if (excess.empty()) return;
    if (sizes.decisionPixels > sizes.pixels) root["decision_pixels"].Fail(excess);
    root["camera"]["pixels"].Fail(excess);
}

}  // namespace

InputError FlatlandInputError(const std::string& source, const DomainError& e) {
    return InputError(source + ": " + FlatlandErrorMessage(e));
}

bool IsSpatialCase(const nlohmann::json& document) {
    // A 3D case may give only a light sweep; flatland cases have neither key.
    return document.is_object() &&
           (document.contains("lights") || document.contains("light_sweep"));
}

flatland::FlatScene FlatSceneFromJson(const nlohmann::json& document,
                                      const std::string& fallbackName) {
    const JsonField root(document, "");
    root.ExpectObject({"camera", "light", "lexels", "geometry"},
                      {"name", "description", "decision_pixels", "frusta"});
    flatland::FlatScene scene;
    scene.name = CaseNameOf(root, fallbackName);
    if (root.Has("description")) root["description"].String();

    const JsonField camera = root["camera"];
    camera.ExpectObject({"position", "direction", "fov_deg", "pixels"}, {"near", "far"});
    scene.camera.wsPosition = camera["position"].Vec2();
    const Eigen::Vector2d direction = camera["direction"].Vec2();
    // A direction whose squared length overflows or underflows ([1e200, 0], [1e-300, 0]) is
    // divided by its largest |component| before it is normalized; others are normalized as given.
    const double largest = direction.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) camera["direction"].Fail("must be a non-zero vector");
    const double squared = direction.squaredNorm();
    const bool representable =
        std::isfinite(squared) && squared >= std::numeric_limits<double>::min();
    scene.camera.wsDirection =
        (representable ? direction : Eigen::Vector2d(direction / largest)).normalized();
    scene.camera.fovDeg = camera["fov_deg"].NumberIn(0.0, 180.0, true, true);
    scene.camera.pixels = static_cast<int>(camera["pixels"].Integer(1, kMaxPixels));
    if (camera.Has("near")) scene.camera.near = camera["near"].Positive();
    if (camera.Has("far")) {
        scene.camera.far = camera["far"].Positive();
        if (!(scene.camera.far > scene.camera.near))
            camera["far"].Fail("must be greater than near (" + FormatNumber(scene.camera.near) +
                               "), got " + FormatNumber(scene.camera.far));
    }

    const JsonField light = root["light"];
    light.ExpectObject({"position"});
    scene.wsLight = light["position"].Vec2();

    scene.lexels = static_cast<int>(root["lexels"].Integer(1, kMaxLexels));

    const JsonField geometry = root["geometry"];
    for (const JsonField& polyline : geometry.Array(1)) {
        std::vector<Eigen::Vector2d> points;
        for (const JsonField& point : polyline.Array(2)) points.push_back(point.Vec2());
        scene.geometry.push_back(std::move(points));
    }

    if (root.Has("decision_pixels"))
        scene.decisionPixels = static_cast<int>(root["decision_pixels"].Integer(1, kMaxPixels));

    if (root.Has("frusta")) {
        const JsonField frusta = root["frusta"];
        frusta.ExpectObject({}, {"max", "budget", "metric"});
        flatland::FrustaOptions options;
        if (frusta.Has("max")) options.max = static_cast<int>(frusta["max"].Integer(1, kMaxWedges));
        if (frusta.Has("budget"))
            options.budget = static_cast<int>(frusta["budget"].Integer(1, options.max));
        else if (options.budget > options.max)
            options.budget = options.max;
        if (frusta.Has("metric")) {
            const std::string metric = frusta["metric"].String();
            if (metric != "l1" && metric != "l2")
                frusta["metric"].Fail("must be one of l1, l2, got '" + metric + "'");
            options.metric = *ParseMetric(metric);
        }
        scene.frusta = options;
    }
    CheckMemoryBudget(root, scene);
    try {
        flatland::CheckSceneGeometry(scene);
    } catch (const DomainError& e) {
        throw InputError(FlatlandErrorMessage(e));
    }
    return scene;
}

flatland::FlatScene LoadFlatScene(const std::filesystem::path& path) {
    return LoadFlatScene(ReadCaseFile(path));
}

flatland::FlatScene LoadFlatScene(const CaseFile& file) {
    const std::filesystem::path& path = file.path;
    const nlohmann::json& document = file.document;
    if (IsSpatialCase(document))
        throw InputError(path.string() +
                         ": this is a 3D case (it has \"lights\" or \"light_sweep\"); expected a "
                         "flatland case");
    try {
        return FlatSceneFromJson(document, path.stem().string());
    } catch (const InputError& e) {
        throw InputError(path.string() + ": " + e.what());
    }
}

}  // namespace lexel::cases
