#include "lexel/flatland/studies/scene_family.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lexel/solvers/geometry.h"

namespace lexel::flatland {

namespace {

Vec2 Unit(double deg) { return {std::cos(Radians(deg)), std::sin(Radians(deg))}; }

// Shared gauge (scene_family.h): camera at (0, 2), 1000 pixels, a 100-pixel decision pass, the
// floor y = 0 over [−500, 500], far clipping beyond every hit.
constexpr double kCameraHeight = 2.0;
constexpr double kFloorHalfLength = 500.0;
constexpr double kFar = 4000.0;  // world units; larger than any depth in the families

// Smallest depth (distance along the camera direction) of the geometry inside the camera's view
// wedge. The nearest point of the wedge is visible (an occluder on its ray would be nearer), and
// depth is linear along a segment, so the minimum sits at an end of a segment clipped to the
// wedge. Returns +inf when no geometry is in view.
double NearestDepthInView(const FlatScene& scene) {
    const Vec2 c = scene.camera.wsPosition, d = scene.camera.wsDirection;
    const Vec2 u = Perp(d);
    const double tanHalf = std::tan(Radians(0.5 * scene.camera.fovDeg));
    // Inside the wedge: x_c > 0 and |y_c| ≤ x_c tan(fov/2): three half-planes, linear in λ.
    double best = INFINITY;
    for (const FlatSegment& s : Segments(scene)) {
        const Vec2 a = s.a - c, e = s.b - s.a;
        double lo = 0.0, hi = 1.0;
        // Half-plane g0 + λ g1 ≥ 0 clips [lo, hi].
        auto clip = [&](double g0, double g1) {
            if (g1 == 0.0) {
                if (g0 < 0.0) hi = -1.0;
                return;
            }
            const double root = -g0 / g1;
            if (g1 > 0.0)
                lo = std::max(lo, root);
            else
                hi = std::min(hi, root);
        };
        clip(a.dot(d), e.dot(d));
        clip(a.dot(d) * tanHalf - a.dot(u), e.dot(d) * tanHalf - e.dot(u));
        clip(a.dot(d) * tanHalf + a.dot(u), e.dot(d) * tanHalf + e.dot(u));
        if (lo > hi) continue;
        best = std::min({best, (a + lo * e).dot(d), (a + hi * e).dot(d)});
    }
    return best;
}

FlatScene BaseScene(const std::string& name, double cameraDirectionDeg, double fovDeg,
                    double lexels) {
    FlatScene scene;
    scene.name = name;
    scene.camera.wsPosition = {0.0, kCameraHeight};
    scene.camera.wsDirection = Unit(cameraDirectionDeg);
    scene.camera.fovDeg = fovDeg;
    scene.camera.pixels = 1000;
    scene.camera.far = kFar;
    scene.decisionPixels = 100;
    scene.lexels = std::max(1, static_cast<int>(std::lround(lexels)));
    scene.geometry.push_back({{-kFloorHalfLength, 0.0}, {kFloorHalfLength, 0.0}});
    return scene;
}

// The near plane as a fraction of the nearest depth in view: it never clips what the camera
// sees, and it sets PSM's post-projective depth map (baselines.h).
FlatScene WithNearPlane(FlatScene scene, double nearFraction) {
    const double nearest = NearestDepthInView(scene);
    scene.camera.near = std::isfinite(nearest) && nearest > 0.0 ? nearFraction * nearest : 1e-3;
    return scene;
}

// Parameters every family shares.
FamilyParameter PitchParameter(double lo, double hi) {
    return {"camera_pitch_deg", lo, hi, false,
            "camera direction below the horizontal, degrees (positive looks down)"};
}
FamilyParameter FovParameter(double lo = 10.0) {
    return {"fov_deg", lo, 120.0, true, "camera's full field of view, degrees"};
}
FamilyParameter NearParameter() {
    return {"near_fraction", 0.01, 0.99, true,
            "camera near plane as a fraction of the nearest depth in view (sets PSM's "
            "post-projective depth map; clips nothing)"};
}
FamilyParameter LexelsParameter() {
    return {"lexels", 20.0, 5000.0, true, "lexel count N of the shadow map (real; rounded)"};
}

}  // namespace

double SceneFamily::FootprintScale(std::span<const double> values) const {
    const double n = values[lexelsIndex];
    return std::max(1.0, std::round(n)) / n;
}

std::vector<std::string> SceneFamily::ParameterNames() const {
    std::vector<std::string> names;
    for (const auto& p : parameters) names.push_back(p.name);
    return names;
}

SceneFamily SinglePlaneFamily() {
    SceneFamily family;
    family.name = "single_plane";
    family.layout =
        "§4.1.3: a single plane (a floor) with a light shining from above; the camera looks down "
        "at it toward -x (the orientation in which the printed angles are positive). The printed "
        "optimum, 9°, is Theorem 1's angle (§2.2.1): the light lies on the line through q (where "
        "the floor meets the camera's view plane) at 9° from vertical, at distance s from q.";
    family.parameters = {PitchParameter(5.0, 80.0),
                         FovParameter(),
                         {"light_distance", 0.5, 80.0, true,
                          "distance s from q to the light along the 9° line, world units"},
                         NearParameter(),
                         LexelsParameter()};
    family.lexelsIndex = 4;
    family.build = [](std::span<const double> v) {
        const double pitch = v[0];
        FlatScene scene = BaseScene("single_plane", 180.0 + pitch, v[1], v[4]);
        // View plane through the camera, perpendicular to d = (−cos β, −sin β): it meets the
        // floor at q = (h tan β, 0).
        const Vec2 q{kCameraHeight * std::tan(Radians(pitch)), 0.0};
        // The lexel plane at 9° (counterclockwise from vertical) runs along 99°: the light sits
        // above q on that line (Theorem 1: the optimal plane is parallel to light→q).
        scene.wsLight = q + v[2] * Unit(99.0);
        return WithNearPlane(std::move(scene), v[3]);
    };
    return family;
}

SceneFamily SimpleGeometryFamily() {
    SceneFamily family;
    family.name = "simple_geometry";
    family.layout =
        "§4.1.3: 'the view camera looks at a simple setup with lighting from above the view "
        "camera': a floor and one box (the simplest non-planar setup) in front of a camera that "
        "looks down toward -x; the light above the camera, offset horizontally by at most 3 "
        "units.";
    family.parameters = {
        PitchParameter(5.0, 85.0),
        FovParameter(),
        {"light_dx", -3.0, 3.0, false, "light's horizontal offset from the camera, world units"},
        {"light_dy", 0.2, 30.0, true, "light's height above the camera, world units"},
        {"box_distance", 0.2, 30.0, true, "horizontal distance camera → box's near face"},
        {"box_width", 0.1, 20.0, true, "box width along x, world units"},
        {"box_height", 0.05, 6.0, true, "box height, world units"},
        NearParameter(),
        LexelsParameter()};
    family.lexelsIndex = 8;
    family.build = [](std::span<const double> v) {
        FlatScene scene = BaseScene("simple_geometry", 180.0 + v[0], v[1], v[8]);
        scene.wsLight = {v[2], kCameraHeight + v[3]};
        const double x0 = -v[4], x1 = -v[4] - v[5], h = v[6];
        scene.geometry.push_back({{x0, 0.0}, {x0, h}, {x1, h}, {x1, 0.0}});
        return WithNearPlane(std::move(scene), v[7]);
    };
    return family;
}

namespace {

// A plank from `base`, running at plankDeg (world degrees), with the light
// beyond its top, `angleDeg` off the plank's line (counterclockwise) as seen from its base.
void AddPlankTowardLight(FlatScene& scene, const Vec2& base, double plankDeg, double length,
                         double beyond, double angleDeg) {
    scene.geometry.push_back({base, base + length * Unit(plankDeg)});
    scene.wsLight = base + (length + beyond) * Unit(plankDeg + angleDeg);
}

FamilyParameter PlankLightBeyond() {
    return {"light_beyond", 0.1, 100.0, true,
            "light's distance from the plank's base minus the plank's length, world units"};
}
FamilyParameter PlankLightAngle() {
    return {"light_angle_deg", 0.02, 30.0, true,
            "angle at the plank's base between the plank and the light (toward the camera), "
            "degrees: how nearly the plank points at the light"};
}

}  // namespace

SceneFamily LightFromTopFamily() {
    SceneFamily family;
    family.name = "light_from_top";
    family.layout =
        "§4.1.3: 'a point light shines from on top of the scene's geometry which includes one "
        "plane facing the view camera', modeled after §2.2.3's second scenario (a point light "
        "above the view frustum; polygons facing the viewer get too few lexels): a floor and a "
        "wall facing the camera, tilted at most 30° from vertical, the light above the wall's "
        "top within 30° of the wall's line. The camera looks toward +x: the orientation in "
        "which the printed Normal and PSM angles (83.1°, 77.3°) are below 90°.";
    family.parameters = {
        PitchParameter(-30.0, 60.0),
        FovParameter(),
        {"wall_distance", 0.5, 200.0, true, "horizontal distance camera → wall's base"},
        {"wall_length", 0.1, 60.0, true, "wall length, world units"},
        {"wall_tilt_deg", -30.0, 30.0, false,
         "wall's lean from vertical, degrees (+ away from the camera)"},
        PlankLightBeyond(),
        PlankLightAngle(),
        NearParameter(),
        LexelsParameter()};
    family.lexelsIndex = 8;
    family.build = [](std::span<const double> v) {
        FlatScene scene = BaseScene("light_from_top", -v[0], v[1], v[8]);
        AddPlankTowardLight(scene, {v[2], 0.0}, 90.0 - v[4], v[3], v[5], v[6]);
        return WithNearPlane(std::move(scene), v[7]);
    };
    return family;
}

SceneFamily ProjectionAliasingFamily() {
    SceneFamily family;
    family.name = "projection_aliasing";
    family.layout =
        "§4.1.3: 'a piece of geometry is oriented so that it points toward the light and faces "
        "the viewer flat on': a floor and a plank (standing on it or raised above it), within "
        "20° of perpendicular "
        "to the camera's view direction (flat on; the camera looks toward +x), whose line "
        "passes within 30° of the light, which lies beyond the plank's top on the camera's "
        "side.";
    family.parameters = {
        PitchParameter(-30.0, 60.0),
        FovParameter(),
        {"plank_distance", 0.5, 40.0, true, "horizontal distance camera → plank's base"},
        {"plank_elevation", 0.0, 3.0, false,
         "height of the plank's base above the floor, world units (0: standing on it)"},
        {"plank_length", 0.1, 15.0, true, "plank length, world units"},
        {"plank_tilt_deg", -20.0, 20.0, false,
         "plank's lean from perpendicular to the view direction, degrees (+ away from camera)"},
        PlankLightBeyond(),
        PlankLightAngle(),
        NearParameter(),
        LexelsParameter()};
    family.lexelsIndex = 9;
    family.build = [](std::span<const double> v) {
        const double pitch = v[0];
        FlatScene scene = BaseScene("projection_aliasing", -pitch, v[1], v[9]);
        // Flat on: the plank runs along u = d rotated by +90°, i.e. at 90° − β.
        AddPlankTowardLight(scene, {v[2], v[3]}, 90.0 - pitch - v[5], v[4], v[6], v[7]);
        scene.frusta = FrustaOptions{16, 2, Metric::kL1};
        return WithNearPlane(std::move(scene), v[8]);
    };
    return family;
}

SceneFamily FixParameter(const SceneFamily& family, const std::string& name, double value) {
    int index = -1;
    for (std::size_t i = 0; i < family.parameters.size(); ++i)
        if (family.parameters[i].name == name) index = static_cast<int>(i);
    if (index < 0)
        throw std::invalid_argument("family '" + family.name + "' has no parameter '" + name + "'");
    if (index == family.lexelsIndex)
        throw std::invalid_argument("family '" + family.name +
                                    "': the lexel count cannot be fixed");
    SceneFamily fixed = family;
    fixed.parameters.erase(fixed.parameters.begin() + index);
    if (fixed.lexelsIndex > index) --fixed.lexelsIndex;
    fixed.build = [build = family.build, index, value](std::span<const double> v) {
        std::vector<double> full(v.begin(), v.end());
        full.insert(full.begin() + index, value);
        return build(full);
    };
    return fixed;
}

const std::vector<SceneFamily>& ThesisFamilies() {
    static const std::vector<SceneFamily> families = {SinglePlaneFamily(), SimpleGeometryFamily(),
                                                      LightFromTopFamily(),
                                                      ProjectionAliasingFamily()};
    return families;
}

const SceneFamily* FindFamily(std::string_view name) {
    for (const auto& family : ThesisFamilies())
        if (family.name == name) return &family;
    return nullptr;
}

}  // namespace lexel::flatland
