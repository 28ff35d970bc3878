#pragma once
#include <CLI/App.hpp>

namespace strata {

// `strata view [SCENE.obj]`: the interactive progressive viewer (app/viewer/), windowed or
// --headless.
void addViewCommand(CLI::App& app);

}  // namespace strata
