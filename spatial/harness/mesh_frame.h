// A mesh file's axes and units against the scene's (cases/README.md, "3D cases"): lexel's world is
// right-handed with +y up and, by convention, one unit a metre; a model made Z-up (Blender, 3ds
// Max, most CAD and scans) or in centimetres is brought into it before its entry's transform.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string_view>

namespace lexel::spatial {

// The file's up axis: +y (glTF, OBJ as most tools write it) or +z.
enum class UpAxis { kY, kZ };

struct MeshFrame {
    UpAxis up = UpAxis::kY;
    double unitScale = 1.0;  // scene units per file unit (> 0): "cm" is 0.01 when a unit is a metre
};

// The named units and their length in metres (the scene unit): "m" 1, "cm" 0.01, "mm" 0.001,
// "km" 1000, "in" 0.0254, "ft" 0.3048; nullopt for another name.
std::optional<double> UnitScaleByName(std::string_view name);
inline constexpr const char* kUnitNames = "m, cm, mm, km, in, ft";

// The scene-from-file matrix: the uniform unit scale, then for a Z-up file the turn that takes +z
// to +y and +y to −z, (x, y, z) ↦ (x, z, −y), a rotation (determinant +1: windings and handedness
// are kept). Every entry is exact (0, ±unitScale, 1).
glm::dmat4 SceneFromFile(const MeshFrame& frame);

// "y" or "z".
const char* UpAxisName(UpAxis up);

}  // namespace lexel::spatial
