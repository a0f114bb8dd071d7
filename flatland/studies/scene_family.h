// Parameterized scene families for the four flatland cases of Chong 2003, ch. 4.1.3: the layout
// each case's text fixes (a floor, a box, a wall, a plank; where the light and the camera are),
// with the quantities it leaves open as parameters. A fit (scene_fit.h) chooses the parameters
// so that lexel reproduces the thesis's printed table.
//
// Conventions shared by every family (what the thesis gives, and the gauge it leaves free):
//   - the camera has 1000 pixels (§4.1.1: scenes "rendered at high resolution (1000 pixels)")
//     and the decisions see a 100-pixel pass (§4.1.2: "we settled upon a low resolution pass of
//     100 pixels");
//   - the floor is the line y = 0 and the camera stands at (0, 2): flatland footprints are
//     invariant under a uniform scaling of the world, so one length must be fixed;
//   - the floor spans x ∈ [−500, 500], the far plane is at 4000 (beyond every hit), and the near
//     plane is a fraction of the nearest depth in view: it clips nothing and only sets PSM's
//     post-projective depth map (baselines.h), which the thesis does not give;
//   - the lexel count N is a real parameter: every single-frustum footprint is exactly
//     proportional to 1/N (lexel_remap.h, R1), so a fit can move it smoothly; the built scene
//     carries round(N) and FootprintScale() says how to rescale its footprints to the real N (for
//     a split's mean only approximately: its lexels are allocated in integers).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lexel/flatland/scene.h"

namespace lexel::flatland {

struct FamilyParameter {
    std::string name;  // e.g. "camera_pitch_deg"
    double lo = 0.0;   // plausible range, closed; the fit's bounds
    double hi = 1.0;
    bool logScale = false;  // searched uniformly in log(value) (lexel count, near plane)
    std::string meaning;    // one line, with units
};

struct SceneFamily {
    std::string name;    // the case's file stem: single_plane, simple_geometry, ...
    std::string layout;  // which constraints were taken from where in the thesis
    std::vector<FamilyParameter> parameters;
    int lexelsIndex = -1;  // the parameter that is the lexel count N
    // Builds the scene for a parameter vector (size == parameters.size(), inside the ranges).
    // May return a scene lexel refuses (TryCompareWithTable in scene_fit.h says why); the fit
    // skips those.
    std::function<FlatScene(std::span<const double>)> build;

    FlatScene Build(std::span<const double> values) const { return build(values); }
    // round(N)/N: multiply the built scene's footprints by this to get those at the real N.
    double FootprintScale(std::span<const double> values) const;
    std::vector<std::string> ParameterNames() const;
};

// "Single Plane Geometry": a floor lit from above; the light on the line through Theorem 1's
// point q at the published optimal angle (9°), so the optimum is exactly the printed one.
SceneFamily SinglePlaneFamily();
// "Simple Geometry": a floor and one box, the light above the camera.
SceneFamily SimpleGeometryFamily();
// "Light from Top": a floor and a vertical wall facing the camera, the light above the wall.
SceneFamily LightFromTopFamily();
// "Projection Aliasing": a floor and a plank facing the viewer flat on (perpendicular to the view
// direction), whose line passes close to the light.
SceneFamily ProjectionAliasingFamily();

// The family with parameter `name` held at `value` (one parameter fewer). A table can determine
// fewer combinations of the parameters than a family has (the single-plane table fixes four of
// its family's five, scene_fit_test.cpp): fixing one makes the rest identifiable. Throws
// std::invalid_argument for an unknown name or the lexel count (preconditions).
SceneFamily FixParameter(const SceneFamily& family, const std::string& name, double value);

// The four families in the thesis's order.
const std::vector<SceneFamily>& ThesisFamilies();
// The family named `name` (a case's file stem), or null when there is none.
const SceneFamily* FindFamily(std::string_view name);

}  // namespace lexel::flatland
