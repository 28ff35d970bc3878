#pragma once

namespace CLI {
class App;  // CLI/App.hpp, included where options are registered: it is slow to compile
}

namespace strata {

// `strata view [SCENE.obj]`: the interactive progressive viewer (app/viewer/), windowed or
// --headless.
void addViewCommand(CLI::App& app);

}  // namespace strata
