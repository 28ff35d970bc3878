#pragma once

#include "cli_forward.h"

namespace strata {

// `strata view [SCENE.obj]`: the interactive progressive viewer (app/viewer/), windowed or
// --headless.
void addViewCommand(CLI::App& app);

}  // namespace strata
