// A mesh file's axes and units (see mesh_frame.h).
#include "lexel/spatial/harness/mesh_frame.h"

namespace lexel::spatial {

std::optional<double> UnitScaleByName(std::string_view name) {
    struct Unit {
        std::string_view name;
        double metres;
    };
    constexpr Unit kUnits[] = {{"m", 1.0},     {"cm", 0.01},   {"mm", 0.001},
                               {"km", 1000.0}, {"in", 0.0254}, {"ft", 0.3048}};
    for (const Unit& unit : kUnits)
        if (unit.name == name) return unit.metres;
    return std::nullopt;
}

glm::dmat4 SceneFromFile(const MeshFrame& frame) {
    const double s = frame.unitScale;
    glm::dmat4 sceneFromFile(0.0);  // columns: the images of the file's x, y, z axes
    sceneFromFile[0] = {s, 0, 0, 0};
    if (frame.up == UpAxis::kZ) {
        sceneFromFile[1] = {0, 0, -s, 0};  // file +y (Z-up: forward) is the scene's −z
        sceneFromFile[2] = {0, s, 0, 0};   // file +z (up) is the scene's +y
    } else {
        sceneFromFile[1] = {0, s, 0, 0};
        sceneFromFile[2] = {0, 0, s, 0};
    }
    sceneFromFile[3] = {0, 0, 0, 1};
    return sceneFromFile;
}

const char* UpAxisName(UpAxis up) { return up == UpAxis::kZ ? "z" : "y"; }

}  // namespace lexel::spatial
