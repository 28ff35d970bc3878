#include <doctest/doctest.h>

#include <array>
#include <set>
#include <utility>
#include <vector>

#include "sampling/random.h"
#include "sampling/strata24.h"
#include "sampling/stratum_schedule.h"
#include "test_support.h"

using namespace strata;

namespace {
constexpr int kStrata = kStrataCount;
uint64_t pixelKeyFor(uint64_t pixel) { return hashCombine(mixBits(42), pixel); }
}  // namespace

TEST_CASE("schedule: permuteStratum is a bijection of 0..23 for every key") {
    for (uint64_t key = 0; key < 5000; ++key) {
        std::array<bool, kStrata> seen{};
        for (int i = 0; i < kStrata; ++i) {
            const int s = permuteStratum(i, mixBits(key));
            REQUIRE(s >= 0);
            REQUIRE(s < kStrata);
            REQUIRE_FALSE(seen[s]);
            seen[s] = true;
        }
    }
}

TEST_CASE("schedule: permuteStratum sends each pair of indices to every ordered pair equally") {
    // What a random permutation does and a rotation or a fixed shuffle does not: for indices
    // i != j, (sigma(i), sigma(j)) is uniform over the 24 * 23 ordered pairs of distinct ids.
    constexpr int kKeys = 552 * 200;
    for (const auto& [i, j] : {std::pair{0, 1}, std::pair{5, 17}, std::pair{23, 12}}) {
        std::array<int, kStrata * kStrata> counts{};
        for (uint64_t key = 0; key < kKeys; ++key) {
            const uint64_t bits = mixBits(key + 0x5eedull);
            ++counts[static_cast<size_t>(permuteStratum(i, bits) * kStrata + permuteStratum(j, bits))];
        }
        const double expected = kKeys / 552.0;
        double chiSquare = 0.0;
        for (int a = 0; a < kStrata; ++a) {
            REQUIRE(counts[static_cast<size_t>(a * kStrata + a)] == 0);
            for (int b = 0; b < kStrata; ++b) {
                if (a == b) continue;
                const double c = counts[static_cast<size_t>(a * kStrata + b)];
                chiSquare += (c - expected) * (c - expected) / expected;
            }
        }
        INFO("indices " << i << ", " << j << ": chi-square " << chiSquare << " on 551 degrees");
        CHECK(chiSquare < test::chiSquareCritical(551));
    }
}

TEST_CASE("schedule (a): in every pass each bounce uses each stratum exactly once") {
    for (uint64_t pixel = 0; pixel < 20; ++pixel) {
        for (uint32_t pass = 0; pass < 600; pass += 7) {
            for (int bounce = 0; bounce < 6; ++bounce) {
                std::set<int> used;
                for (int step = 0; step < kStrata; ++step) {
                    used.insert(scheduledStratum(pixelKeyFor(pixel), pass, step, bounce));
                }
                REQUIRE(used.size() == kStrata);
            }
        }
    }
}

TEST_CASE("schedule (b): any 24^(k-1) consecutive passes cover the 24^k product cells once") {
    const uint64_t key = pixelKeyFor(3);
    for (int k = 1; k <= kProductStratifiedBounces; ++k) {
        uint32_t run = 1;
        for (int i = 1; i < k; ++i) run *= kStrata;
        // Aligned and unaligned windows.
        for (uint32_t start : {0u, 1u, 13u, run - 1, 2 * run + 5}) {
            std::set<std::vector<int>> cells;
            for (uint32_t pass = start; pass < start + run; ++pass) {
                for (int step = 0; step < kStrata; ++step) {
                    std::vector<int> cell;
                    for (int bounce = 0; bounce < k; ++bounce) {
                        cell.push_back(scheduledStratum(key, pass, step, bounce));
                    }
                    cells.insert(cell);
                }
            }
            INFO("k = " << k << ", window starts at pass " << start);
            CHECK(cells.size() == static_cast<size_t>(run) * kStrata);
        }
    }
}

TEST_CASE("schedule: bounces 0 and 2 cover all 576 pairs in every aligned run of 24 passes") {
    const uint64_t key = pixelKeyFor(11);
    for (uint32_t start : {0u, 24u, 480u}) {
        std::set<std::pair<int, int>> pairs;
        for (uint32_t pass = start; pass < start + kStrata; ++pass) {
            for (int step = 0; step < kStrata; ++step) {
                pairs.insert({scheduledStratum(key, pass, step, 0), scheduledStratum(key, pass, step, 2)});
            }
        }
        CHECK(pairs.size() == kStrata * kStrata);
    }
}

TEST_CASE("schedule (c): each step's strata are uniform across pixels, and independent across "
          "bounces") {
    // Over pixels (the randomisation), step 0's first-bounce stratum is uniform on 0..23, and the
    // pair (bounce 0, bounce 1) is uniform on the 576 cells: every path, so every partial pass,
    // samples the product space uniformly, hence without bias.
    constexpr int kPixels = 576 * 200;
    std::vector<int> first(kStrata, 0);
    std::vector<int> pairs(kStrata * kStrata, 0);
    for (int pixel = 0; pixel < kPixels; ++pixel) {
        const uint64_t key = pixelKeyFor(pixel);
        const int s0 = scheduledStratum(key, 5, 0, 0);
        const int s1 = scheduledStratum(key, 5, 0, 1);
        ++first[s0];
        ++pairs[s0 * kStrata + s1];
    }
    auto chiSquare = [](const std::vector<int>& counts, double expected) {
        double x = 0.0;
        for (int c : counts) x += (c - expected) * (c - expected) / expected;
        return x;
    };
    CHECK(chiSquare(first, static_cast<double>(kPixels) / kStrata) < test::chiSquareCritical(kStrata - 1));
    CHECK(chiSquare(pairs, static_cast<double>(kPixels) / (kStrata * kStrata)) <
          test::chiSquareCritical(kStrata * kStrata - 1));
}

TEST_CASE("schedule (c): a pixel's delivery order changes from pass to pass") {
    const uint64_t key = pixelKeyFor(5);
    std::set<int> firstStepStrata;
    for (uint32_t pass = 0; pass < 200; ++pass) firstStepStrata.insert(scheduledStratum(key, pass, 0, 0));
    CHECK(firstStepStrata.size() == kStrata);
}

TEST_CASE("schedule: deep bounces are re-randomised every pass (padded stratification)") {
    const uint64_t key = pixelKeyFor(9);
    const int deep = kProductStratifiedBounces + 2;
    // The map from first-bounce stratum to deep-bounce stratum must not stay fixed across passes.
    std::set<std::vector<int>> maps;
    for (uint32_t pass = 0; pass < 10; ++pass) {
        std::vector<int> map(kStrata);
        for (int step = 0; step < kStrata; ++step) {
            map[scheduledStratum(key, pass, step, 0)] = scheduledStratum(key, pass, step, deep);
        }
        maps.insert(map);
    }
    CHECK(maps.size() == 10);
}
