// Generated floor-objects scenes and light sweeps (report §3; see generator.h).
#include "lexel/spatial/harness/generator.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "lexel/solvers/geometry.h"
#include "lexel/spatial/harness/primitives.h"

namespace lexel::spatial {
namespace {

// [0, 1) from the top 53 bits: exact doubles, the same on every platform.
double Uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double Uniform(std::mt19937_64& rng, double lo, double hi) {
    return lo + (hi - lo) * Uniform01(rng);
}
// {0, ..., n-1}; the bias of the floor mapping is below 2^-53 · n, negligible here.
int UniformInt(std::mt19937_64& rng, int n) {
    return std::min(n - 1, static_cast<int>(Uniform01(rng) * n));
}

struct Footprint {
    glm::dvec2 wsCentre;
    double radius;
};

constexpr double kMinSize = 0.3, kMaxSize = 2.5;
constexpr double kPlacementHalfSize = 18.0;
constexpr int kPlacementTries = 64;

}  // namespace

namespace {

// One object's draw, in the order the published layouts were drawn: its shape (box, sphere,
// cylinder), its size (every extent in [kMinSize, kMaxSize]: a sphere's and a cylinder's
// diameter; the unit box and cylinder are 1 tall, the unit sphere 2 across), its turn about y, a
// tilt for a third of them and a lift off the floor for a third.
struct DrawnObject {
    int kind = 0;
    Transform transform;
    double lift = 0.0;
};

DrawnObject DrawObject(std::mt19937_64& rng) {
    DrawnObject o;
    o.kind = UniformInt(rng, 3);
    Transform& t = o.transform;
    if (o.kind == 0) {
        t.scale = {Uniform(rng, kMinSize, kMaxSize), Uniform(rng, kMinSize, kMaxSize),
                   Uniform(rng, kMinSize, kMaxSize)};
    } else if (o.kind == 1) {
        t.scale = glm::dvec3(0.5 * Uniform(rng, kMinSize, kMaxSize));
    } else {
        const double radius = 0.5 * Uniform(rng, kMinSize, kMaxSize);
        t.scale = {radius, Uniform(rng, kMinSize, kMaxSize), radius};
    }
    t.rotateDeg.y = Uniform(rng, 0.0, 360.0);
    if (Uniform01(rng) < 1.0 / 3.0) {
        const double tilt = Uniform(rng, -30.0, 30.0);
        (UniformInt(rng, 2) == 0 ? t.rotateDeg.x : t.rotateDeg.z) = tilt;
    }
    o.lift = Uniform01(rng) < 1.0 / 3.0 ? Uniform(rng, 0.05, 1.0) : 0.0;
    return o;
}

// Rejection sampling: the first spot (x, z) whose footprint circle of `radius` clears every placed
// one, or else the spot with the most clearance (the least overlap).
glm::dvec2 DrawSpot(std::mt19937_64& rng, double radius, const std::vector<Footprint>& placed) {
    glm::dvec2 best(0.0);
    double bestClearance = -std::numeric_limits<double>::infinity();
    for (int attempt = 0; attempt < kPlacementTries; ++attempt) {
        const double reach = kPlacementHalfSize - radius;
        // z is drawn before x: the order GCC gave the two draws when they were the arguments of
        // one constructor (unspecified in C++; clang drew x first and built another floor), kept
        // so the published layouts stay as they are.
        const double spotZ = Uniform(rng, -reach, reach);
        const double spotX = Uniform(rng, -reach, reach);
        const glm::dvec2 spot(spotX, spotZ);
        double clearance = std::numeric_limits<double>::infinity();
        for (const Footprint& other : placed)
            clearance =
                std::min(clearance, glm::length(spot - other.wsCentre) - radius - other.radius);
        if (clearance > bestClearance) bestClearance = clearance, best = spot;
        if (clearance >= 0.0) break;
    }
    return best;
}

}  // namespace

TriangleMesh FloorObjects(int count, std::uint64_t seed, glm::dvec4* floorPlane) {
    if (count < 0)
        throw std::invalid_argument("FloorObjects: count must be >= 0, got " +
                                    std::to_string(count));
    std::mt19937_64 rng(seed);
    Transform floorTransform;
    floorTransform.scale = glm::dvec3(2.0 * kFloorHalfSize, 1.0, 2.0 * kFloorHalfSize);
    TriangleMesh scene = TransformMesh(MakePlane(), floorTransform);
    if (floorPlane != nullptr) *floorPlane = glm::dvec4(0.0, 1.0, 0.0, 0.0);

    const TriangleMesh unitShapes[3] = {MakeBox(), MakeSphere(), MakeCylinder()};
    std::vector<Footprint> placed;
    for (int i = 0; i < count; ++i) {
        const DrawnObject drawn = DrawObject(rng);
        // Shaped and turned at the origin; its bounds give the footprint and the drop to the floor.
        TriangleMesh object = TransformMesh(unitShapes[drawn.kind], drawn.transform);
        const Bounds osBounds = object.ComputeBounds();
        const double radius = 0.5 * glm::length(glm::dvec2(osBounds.hi.x - osBounds.lo.x,
                                                           osBounds.hi.z - osBounds.lo.z));
        const glm::dvec2 best = DrawSpot(rng, radius, placed);
        placed.push_back({best, radius});

        const glm::dvec3 osCentre = osBounds.Center();
        const glm::dvec3 shift(best.x - osCentre.x, drawn.lift - osBounds.lo.y,
                               best.y - osCentre.z);
        scene.Append(TransformMesh(object, glm::translate(glm::dmat4(1.0), shift)));
    }
    return scene;
}

std::vector<Light> SweepLights(const LightSweep& sweep, const glm::dvec3& wsCenter) {
    if (sweep.count < 0)
        throw std::invalid_argument("SweepLights: count must be >= 0, got " +
                                    std::to_string(sweep.count));
    if (!(sweep.radius > 0.0) || !std::isfinite(sweep.radius))
        throw std::invalid_argument("SweepLights: radius must be positive and finite");
    std::mt19937_64 rng(sweep.seed);
    const double minY = std::sin(Radians(kSweepMinElevationDeg));
    std::vector<Light> lights;
    lights.reserve(static_cast<std::size_t>(sweep.count));
    for (int i = 0; i < sweep.count; ++i) {
        const double y = Uniform(rng, minY, 1.0);
        const double azimuth = Uniform(rng, 0.0, 2.0 * std::numbers::pi);
        const double horizontal = std::sqrt(std::max(0.0, 1.0 - y * y));
        const glm::dvec3 unit(horizontal * std::cos(azimuth), y, horizontal * std::sin(azimuth));
        Light light;
        light.type = sweep.type;
        light.position = wsCenter + sweep.radius * unit;
        light.direction = -unit;  // directional: from the hemisphere point toward the centre
        lights.push_back(light);
    }
    return lights;
}

}  // namespace lexel::spatial
