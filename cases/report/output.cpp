#include "lexel/cases/report/output.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace lexel::cases {

void WriteFileAtomically(const std::string& path, const std::string& content) {
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot write");
        out << content;
        if (!out) throw std::runtime_error(path + ": write failed");
    }
    std::filesystem::rename(temporary, path);
}

}  // namespace lexel::cases
