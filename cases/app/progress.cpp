#include "lexel/cases/app/progress.h"

#include <unistd.h>

#include <iostream>

#include "lexel/cases/report/progress_text.h"

namespace lexel::cases {

namespace {
// Redraws at most this often (seconds): a 100000-light sweep would otherwise write 100000 lines.
constexpr double kRedrawSeconds = 0.2;
}  // namespace

Progress::Progress(std::string label, std::size_t total, std::string what)
    : label_(std::move(label)),
      what_(std::move(what)),
      total_(total),
      enabled_(isatty(STDERR_FILENO) && total > 0),
      start_(std::chrono::steady_clock::now()) {
    if (enabled_) Draw(0, 0.0);
}

Progress::~Progress() {
    if (enabled_ && done_ < total_) std::cerr << "\r\033[K" << std::flush;
}

void Progress::Step() {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    const std::size_t done = ++done_;
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (done < total_ && s - drawnAt_ < kRedrawSeconds) return;
    Draw(done, s);
}

// "\r" and the line, cleared to the end ("\033[K") in case the previous one was longer; a newline
// once everything is done.
void Progress::Draw(std::size_t done, double seconds) {
    drawnAt_ = seconds;
    std::cerr << '\r' << ProgressText(label_, done, total_, what_, seconds) << "\033[K"
              << (done >= total_ ? "\n" : "") << std::flush;
}

}  // namespace lexel::cases
