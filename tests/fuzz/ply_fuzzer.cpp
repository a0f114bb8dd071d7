// libFuzzer target: PLY files through spatial::LoadMesh (spatial/harness/mesh_loader.h), which
// reads them with lexel's own reader (mesh_ply_reader.h) under the loader's allocation cap. The
// bytes are written to input.ply. A bad file must be refused with a DomainError of one line; any
// other exception, a crash, a sanitizer report or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz_support.h"

namespace {

// One directory per process, made on first use.
const std::filesystem::path& WorkDir() {
    static const std::filesystem::path dir = lexel::fuzz::MakeProcessDir("lexel_ply_fuzz");
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    lexel::fuzz::LoadMeshBytes(bytes, WorkDir() / "input.ply");
    return 0;
}
