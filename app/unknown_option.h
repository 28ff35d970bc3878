#pragma once
// A mistyped option named with the nearest one the command knows: CLI11 reports "--sp 24" only as
// "The following arguments were not expected: 24 --sp".
#include <optional>
#include <string>
#include <vector>

#include "cli_forward.h"

namespace strata {

// The known option nearest to `name` (both with their leading "--"), by edit distance, when one
// is near enough to be a likely typo (or `name` is the start of exactly one); else none.
std::optional<std::string> nearestOption(const std::string& name, const std::vector<std::string>& known);

// The message for the first "--name" among `arguments` (those after the command's name) that
// `command` has no option for: "unknown option '--sp' (did you mean --spp?)"; none when every
// option is known. Scanning stops at a lone "--", after which words are not options.
std::optional<std::string> unknownOptionMessage(const CLI::App& command, const std::vector<std::string>& arguments);

}  // namespace strata
