// What the fuzz targets under tests/fuzz/ share: the oracle for an expected refusal. A bad input
// must be refused with the documented exception and a one-line, non-empty message (the CLI prints
// it as `lexel: error: ...`); anything else is a finding and aborts, so libFuzzer saves the input.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

namespace lexel::fuzz {

inline void CheckRefusalMessage(const std::exception& e) {
    const std::string_view message = e.what();
    if (message.empty() || message.find_first_of("\n\r") != std::string_view::npos) {
        std::fprintf(stderr, "fuzz: refusal message is empty or spans lines: \"%s\"\n", e.what());
        std::abort();
    }
}

}  // namespace lexel::fuzz
