#include <doctest/doctest.h>

#include <algorithm>

#include "util/error.h"
#include "integrator/pass_partition.h"

using namespace strata;

TEST_CASE("pass partition: every pass goes to exactly one rank, in consecutive balanced blocks") {
    for (uint32_t passes : {0u, 1u, 2u, 5u, 10u, 24u, 1000u, 1001u}) {
        for (int ranks : {1, 2, 3, 7, 16}) {
            CAPTURE(passes);
            CAPTURE(ranks);
            uint32_t next = 0;
            uint32_t smallest = passes;
            uint32_t largest = 0;
            for (int rank = 0; rank < ranks; ++rank) {
                const PassRange range = passesOfRank(passes, rank, ranks);
                CHECK(range.begin == next);  // consecutive, in rank order, no gap or overlap
                CHECK(range.end >= range.begin);
                next = range.end;
                smallest = std::min(smallest, range.size());
                largest = std::max(largest, range.size());
                if (rank == 0) CHECK(range.size() * static_cast<uint32_t>(ranks) >= passes);
            }
            CHECK(next == passes);
            CHECK(largest - smallest <= 1);
        }
    }
    // 10 passes over 4 ranks: 3, 3, 2, 2.
    CHECK(passesOfRank(10, 1, 4).begin == 3);
    CHECK(passesOfRank(10, 1, 4).end == 6);
    CHECK(passesOfRank(10, 3, 4).begin == 8);
    CHECK(passesOfRank(10, 3, 4).end == 10);
}

TEST_CASE("pass partition: a rank outside the job is refused") {
    CHECK_THROWS_AS(passesOfRank(10, 2, 2), Error);
    CHECK_THROWS_AS(passesOfRank(10, -1, 2), Error);
    CHECK_THROWS_AS(passesOfRank(10, 0, 0), Error);
}
