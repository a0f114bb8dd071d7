// libFuzzer target: model files through spatial::LoadMesh (spatial/harness/mesh_loader.h), the
// loader of a 3D case's `mesh` entries. The bytes are written to a file whose extension is the
// format they look like, as a user would name it — "OFF" (or COFF, NOFF, ...) → .off, "solid" →
// .stl, a zero byte (binary) → .stl, anything else → .obj — so the three formats the loader reads
// through Assimp (mesh_file_check.h: OBJ, OFF, STL), its checks and Assimp's importers for them
// are the ones fuzzed (PLY and glTF have their own targets, ply_fuzzer and gltf_fuzzer; the PLY
// seeds of Assimp's earlier findings are read here as OBJ, and there as PLY). A bad file must be
// refused with a DomainError of one line; any other exception, a crash, a sanitizer report or a
// hang is a finding. Assimp is not instrumented: coverage guides only through lexel's code.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz_support.h"

namespace {

std::string_view ExtensionFor(std::string_view bytes) {
    const std::size_t off = bytes.find("OFF");
    if (off != std::string_view::npos && off < 5 && bytes.find('\n') > off) return ".off";
    if (bytes.starts_with("solid")) return ".stl";
    if (bytes.find('\0') != std::string_view::npos) return ".stl";
    return ".obj";
}

// One directory per process, made on first use.
const std::filesystem::path& WorkDir() {
    static const std::filesystem::path dir = lexel::fuzz::MakeProcessDir("lexel_mesh_fuzz");
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    lexel::fuzz::LoadMeshBytes(bytes, WorkDir() / ("input" + std::string(ExtensionFor(bytes))));
    return 0;
}
