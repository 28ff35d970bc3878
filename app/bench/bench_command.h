#pragma once
// `strata bench`: run time against error, throughput against Embree's ceiling, and a peer.

namespace CLI {
class App;  // CLI/App.hpp, included where options are registered: it is slow to compile
}

namespace strata {

void addBenchCommand(CLI::App& app);

}  // namespace strata
