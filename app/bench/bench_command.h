#pragma once
// `strata bench`: run time against error, throughput against Embree's ceiling, and a peer.
#include <CLI/App.hpp>

namespace strata {

void addBenchCommand(CLI::App& app);

}  // namespace strata
