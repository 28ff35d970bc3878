#pragma once
// How a distributed render (`mpirun -np R strata render`) splits its passes over the ranks.
// Whole passes only: a pixel's pass p (its 24 paths, one per stratum under strata24, §3 of the
// paper) is rendered entirely by one rank, so every pass keeps its stratification, and since a
// sample depends only on (seed, pixel, pass, step, bounce) the ranks' passes together are exactly
// the single-process render's passes.
#include <cstdint>

namespace strata {

struct PassRange {
    uint32_t begin = 0;
    uint32_t end = 0;  // one past the last
    uint32_t size() const { return end - begin; }
};

// Rank `rank` (0..ranks-1) of `ranks` renders passes [begin, end): consecutive blocks in rank
// order whose sizes differ by at most one (the lower ranks take the extra passes, so rank 0, which
// reports progress, has the largest share). A rank gets no passes when ranks > passes.
PassRange passesOfRank(uint32_t passes, int rank, int ranks);

}  // namespace strata
