// Wall-clock timing for the reports' millisecond columns (std::chrono::steady_clock).
#pragma once

#include <chrono>

namespace lexel {

// Starts on construction; Ms() is the time since then (or since the last Restart) in
// milliseconds.
class Stopwatch {
  public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    void Restart() { start_ = std::chrono::steady_clock::now(); }
    double Ms() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
            .count();
    }

  private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace lexel
