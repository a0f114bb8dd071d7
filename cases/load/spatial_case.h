// Loading and validating 3D case files (schema: cases/README.md, "3D cases"): the scene of
// Chong & Gortler's experiments (report §3) — camera, lights or a light sweep, resolutions, and
// geometry from primitives, model files and the floor-objects generator, and the case's own methods
// (one clip matrix per light: case_methods.h).
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lexel/cases/load/json_reader.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/mesh_frame.h"
#include "lexel/spatial/harness/primitives.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::cases {

// Screen, readback and shadow-map sides are at most this many pixels or texels.
inline constexpr long long kMaxSide = 16384;
// The most lights a sweep holds (light_sweep.count, `sweep --lights`, a sweep record's lights).
inline constexpr long long kMaxSweepLights = 100000;
// optimizer.max_samples is at most this: every readback pixel of the largest readback (a budget
// never thins beyond the samples there are, so a larger one would mean no budget).
inline constexpr long long kMaxOptimizerSamples = kMaxSide * kMaxSide;
// optimizer.edge_exponent's range, (0, 4]: p = 0 would count every sample alike whatever its band,
// and a footprint of 10⁴ pixels per texel to the 4th power is still far from overflow.
inline constexpr double kMaxEdgeExponent = 4.0;

// The range of 3D scenes lexel accepts (world units). Every coordinate of the camera, its targets,
// the point lights and the transformed geometry is at most kMaxCoordinate in magnitude; the
// geometry is at least kMinSceneSize across (its bounds' diagonal); and the centre of its bounds
// lies at most kMaxCentreRadii bounding radii from the origin. Inside this range 3D results do not
// depend on the scene's scale or position (tests/spatial/harness/scale_invariance_test.cpp:
// identical counts and samples, h to rounding): what works in float works in the scene's unit
// frame (scene.h), squared lengths and the products of up to four stay normal doubles (1e±60),
// and the case's coordinates keep about 8 significant digits within the scene (at 1e8 radii a
// double's step is 2e-8 of the radius; measured on spatial_small: counts identical to 8e8 radii,
// h within 1.2e-5 at 1e8).
inline constexpr double kMaxCoordinate = 1e15;
inline constexpr double kMinSceneSize = 1e-15;
inline constexpr double kMaxCentreRadii = 1e8;
// far / near of the camera is at most this. With the standard perspective depth mapping and a
// depth buffer whose steps near 1 are 2^-24 (24-bit fixed or 32-bit float), the depth step at a
// distance z is about z · (z / near) · 2^-24: at far = 1e5 · near that is 0.6% of the distance,
// beyond it depth tests and the methods' depth ranges lose their meaning. The shipped cases use
// 1000 to 1500 (the default 0.1 .. 200 is 2000).
inline constexpr double kMaxFarOverNear = 1e5;

// Validates a parsed document; throws InputError naming the JSON pointer and the reason. Relative
// mesh paths are resolved against baseDir (the case file's directory).
spatial::Scene SpatialSceneFromJson(const nlohmann::json& document, const std::string& fallbackName,
                                    const std::filesystem::path& baseDir);
// Reads the file; errors are prefixed with its path.
spatial::Scene LoadSpatialScene(const std::filesystem::path& path);
// The same for a file already read (ReadCaseFile).
spatial::Scene LoadSpatialScene(const CaseFile& file);

// A `mesh` geometry entry of a 3D case: its file (a relative path resolved against the case's
// directory), the file's axes and units (`up`, `units`) and the entry's transform; the entry's
// triangles in world space are transform.Matrix() · SceneFromFile(frame) applied to the file's.
struct SpatialMeshEntry {
    std::string pointer;  // "/geometry/K"
    std::filesystem::path file;
    spatial::MeshFrame frame;
    spatial::Transform transform;
};

// The mesh entries of a 3D case file, read and checked as LoadSpatialScene reads them, without
// loading any mesh or checking the rest of the scene. Throws InputError "<case>: <pointer>:
// reason".
std::vector<SpatialMeshEntry> LoadSpatialMeshEntries(const std::filesystem::path& path);

// Where in a case a DomainError met while evaluating its loaded scene points, for one-line
// errors: `camera` (default "/camera") for Subject::kCamera, `light` for kLight ("/lights/k" of
// a fixed light: LightField; a description of a sweep light), "/geometry" for kGeometry.
std::string SpatialErrorField(const DomainError& e, const std::string& light,
                              const std::string& camera = "/camera");
std::string LightField(std::size_t light);      // "/lights/<light>"
std::string CameraPathField(std::size_t pose);  // "/camera_path/<pose>"

}  // namespace lexel::cases
