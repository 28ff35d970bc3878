#pragma once

namespace CLI {
class App;  // CLI/App.hpp, included where options are registered: it is slow to compile
}

namespace strata {
// `strata samples`: the directions a sampler gives one pixel, as CSV, for plots and outside checks.
void addSamplesCommand(CLI::App& app);
}  // namespace strata
