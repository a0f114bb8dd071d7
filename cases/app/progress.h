// A progress bar on stderr for long commands, shown only when stderr is a terminal.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace lexel::cases {

class Progress {
  public:
    // `what`: the unit counted ("lights"); `label`: the bar's name ("sweep").
    Progress(std::string label, std::size_t total, std::string what);
    void Step();  // one unit done; thread-safe

  private:
    std::string label_, what_;
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::atomic<std::size_t> done_{0};
    std::mutex mutex_;
};

}  // namespace lexel::cases
