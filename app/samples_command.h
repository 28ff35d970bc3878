#pragma once

#include "cli_forward.h"

namespace strata {
// `strata samples`: the directions a sampler gives one pixel, as CSV, for plots and outside checks.
void addSamplesCommand(CLI::App& app);
}  // namespace strata
