#pragma once
// The command lines of the `strata` children the bench runs (this very program), built from the
// same RenderOptions the commands parse, so every child renders what its options say.
#include <filesystem>
#include <string>
#include <vector>

#include "render_options.h"

namespace strata {

// `strata COMMAND` with `options`, then `more` (the command's own arguments).
std::vector<std::string> strataCommandLine(const std::string& command, const RenderOptions& options,
                                           const std::vector<std::string>& more = {});
// `strata render` with `options` at `spp`, writing `out` unless it is empty.
std::vector<std::string> renderCommandLine(const RenderOptions& options, int spp,
                                           const std::filesystem::path& out = {});

}  // namespace strata
