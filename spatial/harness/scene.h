// The 3D scenes of Chong & Gortler's experiments (report §3): a triangle soup in world space, the
// camera, point and directional lights or a sweep of them, and the resolutions of the shadow map
// and of the low-resolution camera readback. The harness renders them; the core of lexel::spatial
// never sees a Scene (it takes cameras, lights, bounds and buffers).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "lexel/spatial/bounds.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/partitions.h"

namespace lexel::spatial {

// Indexed triangles, world units, in double: a scene keeps its shape wherever it sits (a float
// vertex 1e8 from the origin would be up to 4 units off). What works in float (Embree, the GPU)
// takes the mesh into its UnitFrame first.
struct TriangleMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::uvec3> triangles;

    void Append(const TriangleMesh& other);
    Bounds ComputeBounds() const;
    // Unit geometric normal of triangle t, counter-clockwise winding; zero when degenerate.
    glm::dvec3 FaceNormal(std::size_t t) const;
};

// The similarity unit = (ws - wsOrigin) / wsScale that centres a scene on its bounds and scales
// it to unit size, for the consumers that work in float (Embree's rays, the GPU's vertices and
// G-buffer). In it a float coordinate of the scene is good to ~1e-7 of the scene's radius
// whatever the scene's size and distance from the origin, so their results do not depend on
// either. wsScale is a power of two: exact in float and double, so scaling loses nothing.
struct UnitFrame {
    glm::dvec3 wsOrigin{0.0};
    double wsScale = 1.0;

    glm::dvec3 ToUnit(const glm::dvec3& wsPoint) const { return (wsPoint - wsOrigin) / wsScale; }
    glm::dvec3 ToWorld(const glm::dvec3& unitPoint) const { return wsOrigin + wsScale * unitPoint; }
    glm::dmat4 WorldFromUnit() const;  // the same map as a 4×4 matrix
};

// The frame of `wsBounds`: origin at their centre, wsScale the least power of two ≥ their radius
// (1 for empty or one-point bounds), so unit coordinates of the bounds lie in [-1, 1].
UnitFrame UnitFrameOf(const Bounds& wsBounds);

// `light_sweep` of a case: `count` lights uniformly at random on the upper hemisphere (y ≥
// centre.y) of radius `radius` around the centre of the floor, as in report §3: point lights
// there, or directional lights shining from there toward the centre (the same directions).
struct LightSweep {
    int count = 500;
    std::uint64_t seed = 7;
    double radius = 100.0;
    Light::Type type = Light::Type::kPoint;
};

// A method the case supplies (its `methods`, cases/README.md): one clip matrix (OpenGL clip space,
// as ClipFromWorld returns) per light, for the case's fixed lights (`lexel run`) or for the lights
// of its light sweep (`lexel sweep`, in sweep order).
struct CaseMethod {
    std::string name;
    bool forSweep = false;
    std::vector<glm::dmat4> clipFromWorld;  // [light]
};

struct Scene {
    std::string name;
    Camera camera;
    std::vector<Light> lights;
    Resolution shadowMap{400, 400};
    Resolution readback{180, 180};
    TriangleMesh geometry;
    // The floor plane n·x + d = 0 as (n, d) with |n| = 1, n facing up: set from the first `plane`
    // primitive or by the floor_objects generator; plane-optimal needs it.
    std::optional<glm::dvec4> floorPlane;
    std::optional<LightSweep> lightSweep;
    std::vector<Camera> cameraPath;   // optional sequence of poses (temporal hysteresis)
    PartitionOptions partitions;      // the partitioned methods' k, λ, texel allocation and energy
    std::vector<CaseMethod> methods;  // the case's own methods
    // Sub-texel phases every method's errors are averaged over (EvaluationOptions::phases,
    // sub_texel_phase.h): 1 measures each map once, as computed.
    int phases = 1;
    // When above `phases`, the most phases a method's mean on one light is raised to, doubling
    // while its residual is above 2% (EvaluationOptions::maxPhases, CountOverPhases); 0: `phases`.
    int maxPhases = 0;
    // The optimizer's sample budget (OptimizerOptions::maxSamples): every optimal* method and
    // sdsm-optimal's partitions search on at most this many boundary samples; 0: all of them.
    std::size_t optimizerMaxSamples = 0;
    // The edge energy's exponent p (EnergyOptions::exponent) for every method on e: optimal,
    // optimal-refined, sdsm-optimal, the Lagrange costs on e and the evaluation's e column.
    double edgeExponent = kDefaultEdgeExponent;
};

// The report's §3 set-up of a scene (Chong & Gortler: "a 180x180 sample resolution"): the readback
// at 180² and every boundary sample to the optimizer. The shipped cases read back at 720² with a
// budget of 512 samples (RESULTS.md, "Re-measured at the shipped readback").
inline constexpr Resolution kReportReadback{180, 180};
inline Scene WithReportReadback(Scene scene) {
    scene.readback = kReportReadback;
    scene.optimizerMaxSamples = 0;
    return scene;
}

}  // namespace lexel::spatial
