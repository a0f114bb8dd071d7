// libFuzzer target: glTF 2.0 files through spatial::LoadMesh (spatial/harness/mesh_loader.h),
// which reads them with tinygltf and lexel's accessor reading (mesh_gltf_reader.h) under the
// loader's allocation caps. The bytes are written to input.gltf (binary or JSON is told by the
// "glTF" magic, not the extension) beside a fixed buffer file, buffer.bin (a triangle's three
// positions and its indices, 48 bytes), so that documents naming it reach the external-buffer path.
// A bad file must be refused with a DomainError of one line; any other exception, a crash, a
// sanitizer report or a hang is a finding. tinygltf is compiled into lexel's code, so its parsing
// is instrumented too.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "fuzz_support.h"

namespace {

// One directory per process, made on first use with buffer.bin.
const std::filesystem::path& WorkDir() {
    static const std::filesystem::path dir = [] {
        const auto path = lexel::fuzz::MakeProcessDir("lexel_gltf_fuzz");
        const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        const std::uint32_t indices[3] = {0, 1, 2};
        std::ofstream bin(path / "buffer.bin", std::ios::binary | std::ios::trunc);
        bin.write(reinterpret_cast<const char*>(positions), sizeof positions);
        bin.write(reinterpret_cast<const char*>(indices), sizeof indices);
        return path;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    lexel::fuzz::LoadMeshBytes(bytes, WorkDir() / "input.gltf");
    return 0;
}
