#pragma once
// `strata bench`: run time against error, throughput against Embree's ceiling, and a peer.

#include "cli_forward.h"

namespace strata {

void addBenchCommand(CLI::App& app);

}  // namespace strata
