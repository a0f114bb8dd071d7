#include "lexel/cases/app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <iostream>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {

Progress::Progress(std::string label, std::size_t total, std::string what)
    : label_(std::move(label)),
      what_(std::move(what)),
      total_(total),
      enabled_(isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {}

void Progress::Step() {
    const std::size_t done = ++done_;
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int width = 30,
              filled = static_cast<int>(width * done / std::max<std::size_t>(1, total_));
    std::cerr << '\r' << label_ << " [" << std::string(filled, '#')
              << std::string(width - filled, '.') << "] " << done << "/" << total_ << " " << what_
              << ", " << Fixed(s, 0) << " s" << (done == total_ ? "\n" : "") << std::flush;
}

}  // namespace lexel::cases
