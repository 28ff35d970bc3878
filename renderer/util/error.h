#pragma once
// A user-facing failure: bad input, a missing file, an absurd option. Its message is one line that
// names the file (and line) or the option, so front ends print it as is and exit non-zero.
#include <stdexcept>
#include <string>

namespace strata {

// Bad input: a file that is missing, unreadable, malformed or cannot be written (exit status 1).
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Bad usage: the command line itself is wrong, whatever the files hold: an unknown option or
// value, a value out of range, options that exclude each other (exit status 2).
class UsageError : public Error {
public:
    using Error::Error;
};

}  // namespace strata
