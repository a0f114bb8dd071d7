#include "lexel/cases/report/progress_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lexel::cases {

std::string DurationText(double seconds) {
    const double s = std::isfinite(seconds) ? std::max(0.0, seconds) : 0.0;
    const auto whole = static_cast<long long>(std::min(s, 1e15));
    char buffer[64];
    if (whole < 60)
        std::snprintf(buffer, sizeof buffer, "%lld s", whole);
    else if (whole < 3600)
        std::snprintf(buffer, sizeof buffer, "%lld min %02lld s", whole / 60, whole % 60);
    else if (whole < 86400)
        std::snprintf(buffer, sizeof buffer, "%lld h %02lld min", whole / 3600, whole % 3600 / 60);
    else
        std::snprintf(buffer, sizeof buffer, "%lld d %02lld h", whole / 86400,
                      whole % 86400 / 3600);
    return buffer;
}

std::string ProgressText(const std::string& label, std::size_t done, std::size_t total,
                         const std::string& what, double elapsedSeconds) {
    constexpr std::size_t kBar = 30;
    const std::size_t shown = std::min(done, total);
    const std::size_t filled = total ? kBar * shown / total : kBar;
    std::string text = label + " [" + std::string(filled, '#') + std::string(kBar - filled, '.') +
                       "] " + std::to_string(shown) + "/" + std::to_string(total) + " " + what +
                       ", " + DurationText(elapsedSeconds) + " elapsed";
    if (shown == 0)
        text += ", estimating the time left";
    else if (shown < total)
        text += ", about " +
                DurationText(elapsedSeconds / static_cast<double>(shown) *
                             static_cast<double>(total - shown)) +
                " left";
    return text;
}

}  // namespace lexel::cases
