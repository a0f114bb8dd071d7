// What the fuzz targets under tests/fuzz/ share: the oracle for an expected refusal, and the mesh
// targets' way of handing their bytes to the loader. A bad input must be refused with the
// documented exception and a one-line, non-empty message (the CLI prints it as
// `lexel: error: ...`); anything else is a finding and aborts, so libFuzzer saves the input.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/mesh_loader.h"

namespace lexel::fuzz {

inline void CheckRefusalMessage(const std::exception& e) {
    const std::string_view message = e.what();
    if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
        std::fprintf(stderr, "fuzz: refusal message is empty or spans lines: \"%s\"\n", e.what());
        std::abort();
    }
}

// A scratch directory of this process, temp/<prefix>_<pid> (libFuzzer's -jobs run several
// processes at once), made on each call (the targets call it once, from a static).
inline std::filesystem::path MakeProcessDir(std::string_view prefix) {
    const auto path = std::filesystem::temp_directory_path() /
                      (std::string(prefix) + "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
}

// The mesh targets' oracle: `bytes` written to `path`, whose extension tells spatial::LoadMesh the
// format, must load or be refused with a one-line DomainError; the file is removed after.
inline void LoadMeshBytes(std::string_view bytes, const std::filesystem::path& path) {
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    try {
        lexel::spatial::LoadMesh(path);
    } catch (const lexel::DomainError& e) {
        CheckRefusalMessage(e);
    }
    std::filesystem::remove(path);
}

}  // namespace lexel::fuzz
