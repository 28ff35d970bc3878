#include "integrator/pass_partition.h"

#include <algorithm>
#include <string>

#include "util/error.h"

namespace strata {

PassRange passesOfRank(uint32_t passes, int rank, int ranks) {
    if (ranks < 1 || rank < 0 || rank >= ranks) {
        throw Error("rank " + std::to_string(rank) + " is not in a job of " +
                    std::to_string(ranks) + " ranks");
    }
    const auto r = static_cast<uint32_t>(rank);
    const uint32_t base = passes / static_cast<uint32_t>(ranks);
    // The ranks below `extra` render one pass more.
    const uint32_t extra = passes % static_cast<uint32_t>(ranks);
    const uint32_t begin = r * base + std::min(r, extra);
    return {begin, begin + base + (r < extra ? 1u : 0u)};
}

}  // namespace strata
