// The one exception type lexel throws for bad input: malformed case files, degenerate geometry,
// configurations with no valid projection. Its message is a single line that names the offending
// field (a JSON pointer where there is one) and the reason; the CLI prints it and exits with 2.
#pragma once

#include <stdexcept>
#include <string>

namespace lexel {

class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace lexel
