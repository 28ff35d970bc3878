#pragma once

namespace CLI {
class App;  // CLI/App.hpp, included where options are registered: it is slow to compile
}

namespace strata {
// `strata render`: the headless progressive batch renderer.
void addRenderCommand(CLI::App& app);
}  // namespace strata
