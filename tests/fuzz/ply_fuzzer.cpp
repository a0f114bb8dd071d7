// libFuzzer target: PLY files through spatial::LoadMesh (spatial/harness/mesh_loader.h), which
// reads them with lexel's own reader (mesh_ply_reader.h) under the loader's allocation cap. The
// bytes are written to input.ply. A bad file must be refused with a DomainError of one line; any
// other exception, a crash, a sanitizer report or a hang is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "fuzz_support.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_loader.h"

namespace {

// One directory per process (libFuzzer's -jobs run several), made on first use.
const std::filesystem::path& WorkDir() {
    static const std::filesystem::path dir = [] {
        const auto path = std::filesystem::temp_directory_path() /
                          ("lexel_ply_fuzz_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const std::filesystem::path path = WorkDir() / "input.ply";
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    try {
        lexel::spatial::LoadMesh(path);
    } catch (const lexel::DomainError& e) {
        lexel::fuzz::CheckRefusalMessage(e);
    }
    std::filesystem::remove(path);
    return 0;
}
