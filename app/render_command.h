#pragma once
#include <CLI/App.hpp>

namespace strata {
// `strata render`: the headless progressive batch renderer.
void addRenderCommand(CLI::App& app);
}  // namespace strata
