#pragma once
// A user-facing failure: bad input, a missing file, an absurd option. Its message is one line that
// names the file (and line) or the option, so front ends print it as is and exit non-zero.
#include <stdexcept>
#include <string>

namespace strata {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace strata
