// A progress bar on stderr for long commands, shown only when stderr is a terminal: units done,
// the time elapsed and an estimate of the time left (cases/report/progress_text.h).
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace lexel::cases {

class Progress {
  public:
    // `what`: the unit counted ("lights"); `label`: the bar's name ("sweep"). Draws the bar at
    // once (0 done, "estimating the time left").
    Progress(std::string label, std::size_t total, std::string what);
    // An unfinished bar (the command failed) is erased, so the error line stands alone.
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    void Step();  // one unit done; thread-safe

  private:
    void Draw(std::size_t done, double seconds);

    std::string label_, what_;
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::size_t done_ = 0;
    double drawnAt_ = -1.0;  // seconds since start_ of the last redraw
    std::mutex mutex_;
};

}  // namespace lexel::cases
