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

// An option given a value it cannot take, or options that do not go together: a usage error,
// which the command line reports with exit status 2 where an input error exits with 1.
class UsageError : public Error {
public:
    using Error::Error;
};

}  // namespace strata
