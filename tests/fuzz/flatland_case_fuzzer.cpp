// libFuzzer target: flatland case files, the path of `lexel run` (cases/load/flatland_case.h):
// text → ParseJsonText → FlatSceneFromJson, which ends in CheckSceneGeometry. A bad case must be
// refused with an InputError of one line; any other exception, a crash, a sanitizer report or a
// hang is a finding. 3D cases (IsSpatialCase) are refused by LoadFlatScene before this loader.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/solvers/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const nlohmann::json document = lexel::cases::ParseJsonText(text, "fuzz.json");
        if (lexel::cases::IsSpatialCase(document)) return 0;
        lexel::cases::FlatSceneFromJson(document, "fuzz");
    } catch (const lexel::InputError& e) {
        lexel::fuzz::CheckRefusalMessage(e);
    }
    return 0;
}
