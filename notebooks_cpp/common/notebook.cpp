#include "notebook.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace lexel::notebooks {

std::filesystem::path OutputDirectory(int argc, char** argv) {
    std::filesystem::path outDir = "out/notebooks";
    const bool flag = argc == 3 && std::string_view(argv[1]) == "--out";
    if (flag || (argc == 2 && argv[1][0] != '-')) {
        outDir = argv[flag ? 2 : 1];
    } else if (argc != 1) {
        std::fprintf(stderr, "usage: %s [OUT_DIR | --out OUT_DIR]   (default out/notebooks)\n",
                     argv[0]);
        std::exit(2);
    }
    std::filesystem::create_directories(outDir);
    return outDir;
}

void Claims::Check(bool holds, const char* format, ...) {
    ++checked_;
    failed_ += holds ? 0 : 1;
    std::printf("%s", holds ? "check: " : "FAILED: ");
    va_list args;
    va_start(args, format);
    std::vprintf(format, args);
    va_end(args);
    std::printf("\n");
}

int Claims::ExitStatus() const {
    if (failed_ == 0) {
        std::printf("all %d checks hold\n", checked_);
        return 0;
    }
    std::printf("%d of %d checks FAILED\n", failed_, checked_);
    return 1;
}

}  // namespace lexel::notebooks
