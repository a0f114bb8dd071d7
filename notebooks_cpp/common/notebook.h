// What every teaching program in notebooks_cpp/ shares: where its figure goes, and the claims it
// checks about the number it teaches (a failed claim makes the program exit non-zero, so its CTest
// test cannot pass vacuously). Not part of lexel's API.
#pragma once

#include <filesystem>

namespace lexel::notebooks {

// The directory a program writes its figure into: `DIR` or `--out DIR` on the command line, else
// out/notebooks relative to the working directory; created when missing. Any other argument
// prints a usage line and exits with status 2.
std::filesystem::path OutputDirectory(int argc, char** argv);

// The claims a program checks. Check prints one line per claim, "check: <claim>" or
// "FAILED: <claim>" (printf-style, with the numbers it compared); ExitStatus prints the tally and
// returns main's status: 0 when every claim held, 1 otherwise.
class Claims {
  public:
    [[gnu::format(printf, 3, 4)]] void Check(bool holds, const char* format, ...);
    int ExitStatus() const;

  private:
    int checked_ = 0, failed_ = 0;
};

}  // namespace lexel::notebooks
