#pragma once
#include <CLI/App.hpp>

namespace strata {
// `strata samples`: the directions a sampler gives one pixel, as CSV, for plots and outside checks.
void addSamplesCommand(CLI::App& app);
}  // namespace strata
