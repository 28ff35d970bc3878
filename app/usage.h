#pragma once
// How `strata` answers a command line it cannot run: its exit statuses, the note every --help
// gives on them, and one-line messages for CLI11's parse errors that name the nearest known
// option or command.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_forward.h"
#include "io/image_io.h"

namespace CLI {
class Option;
class ParseError;
}

namespace strata {

// strata::Error: a file is missing, unreadable or malformed, or an output cannot be written.
inline constexpr int kInputExitStatus = 1;
// strata::UsageError and CLI11's parse errors: the command line itself is wrong.
inline constexpr int kUsageExitStatus = 2;

// The footer of every command's --help.
inline constexpr const char* kExitStatusHelp =
    "Exit status: 0 done; 1 bad input (a file missing, unreadable or malformed, an output that "
    "cannot be written); 2 bad usage (an unknown command or option, a bad or out-of-range "
    "value), found before any rendering.";

// The name of `known` a mistyped `typed` most likely meant: the only one `typed` begins (at least
// two characters past the dashes), else the nearest by edit distance (a swap of two adjacent
// characters one edit) when that distance is at most
// a third of the typed length past the dashes, rounded (and at least 1); none when nothing is
// that near.
std::optional<std::string> nearestName(const std::string& typed, const std::vector<std::string>& known);

// One line for a parse error of `app` (the top-level program): for an unknown option,
// "unknown option '--sp'; did you mean '--spp'? (see strata render --help)"; for an argument no
// positional takes, "unexpected argument 'b.obj' (see ...)"; for anything else CLI11's message.
std::string describeParseError(const CLI::App& app, const CLI::ParseError& error);

// Makes `option` (of an unsigned 64-bit integer: a seed, a count) take only a whole number from 0
// to 2^64 - 1, written in decimal digits: CLI11 alone would read "-1" as 2^64 - 1 and 2^64 as 0.
void acceptUnsigned64(CLI::Option& option);

// Checks the value of an output option (`option`: "--out", "--screenshot") before any work: its
// image format by extension, in any letter case (else strata::UsageError "OPTION: PATH: unknown
// image format ..."), and when `probe`, that it can be written (else strata::Error
// "OPTION: PATH: cannot write: ...", io/output_file.h; a folder at PATH is named so first).
ImageFormat checkOutputOption(const std::string& option, const std::filesystem::path& path,
                              bool probe = true);

}  // namespace strata
