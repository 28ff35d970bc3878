#pragma once

#include "cli_forward.h"

namespace strata {
// `strata render`: the headless progressive batch renderer.
void addRenderCommand(CLI::App& app);
}  // namespace strata
