#include "lexel/cases/load/memory_budget.h"

#include <cstdio>

namespace lexel::cases {

std::string FormatBytes(double bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
    int unit = 0;
    while (bytes >= 1024.0 && unit < 5) {
        bytes /= 1024.0;
        ++unit;
    }
    char text[64];
    std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.3g %s", bytes, units[unit]);
    return text;
}

std::string MemoryBudgetExcess(double bytes, const std::string& what) {
    if (!(bytes > kMemoryBudgetBytes)) return {};
    return "needs about " + FormatBytes(bytes) + " (" + what +
           "), above lexel's memory budget of " + FormatBytes(kMemoryBudgetBytes);
}

}  // namespace lexel::cases
