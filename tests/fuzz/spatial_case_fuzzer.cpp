// libFuzzer target: 3D case files, the path of `lexel run` (cases/load/spatial_case.h): text →
// ParseJsonText → SpatialSceneFromJson (meshes, primitives, the generator, and the checks on the
// whole scene). Relative mesh paths resolve against the mesh seeds (LEXEL_FUZZ_MESH_DIR), so
// "tetra.obj" loads a small mesh. A bad case must be refused with an InputError of one line;
// any other exception, a crash, a sanitizer report or a hang is a finding. Flatland cases are
// refused by LoadSpatialScene before this loader.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "lexel/cases/load/flatland_case.h"  // IsSpatialCase
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/solvers/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const nlohmann::json document = lexel::cases::ParseJsonText(text, "fuzz.json");
        if (!lexel::cases::IsSpatialCase(document)) return 0;
        lexel::cases::SpatialSceneFromJson(document, "fuzz", LEXEL_FUZZ_MESH_DIR);
    } catch (const lexel::InputError& e) {
        lexel::fuzz::CheckRefusalMessage(e);
    }
    return 0;
}
