// The strata carried onto the cosine-weighted hemisphere (strata24_warped.h): the warp maps the
// uniform measure onto the cosine measure, so every warped stratum holds 1/24 of it, a stratum's
// samples stay in it, and the 24 strata together sample cos / pi (chi-square on cells that are
// equally likely under that density: cos^2(theta) and the azimuth uniform); the inverse warp
// (warpCosineToUniform) is checked against the warp and then classifies directions.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <glm/geometric.hpp>

#include "sampling/hemisphere.h"
#include "sampling/random.h"
#include "sampling/strata24.h"
#include "sampling/strata24_warped.h"
#include "test_support.h"

using namespace strata;

namespace {

}  // namespace

TEST_CASE("strata24-warped: samples are unit, above the horizon and in their stratum, edges included") {
    const float almostOne = 1.0f - std::numeric_limits<float>::epsilon() / 2.0f;
    const float edges[] = {0.0f, 1e-7f, 0.25f, 0.5f, 0.999f, almostOne};
    for (int id = 0; id < kStrataCount; ++id) {
        for (float a : edges) {
            for (float b : edges) {
                const glm::vec3 d = sampleWarpedStratum(id, {a, b});
                INFO("stratum " << id << " u " << a << " v " << b);
                CHECK(std::isfinite(d.x));
                CHECK(std::abs(d.x * d.x + d.y * d.y + d.z * d.z - 1.0f) < 4e-7f);
                CHECK(d.z >= 0.0f);
            }
        }
        // The warp keeps the azimuth, so the quadrant and the order of |x| and |y|; the stratum
        // of the unwarped direction is the one sampled (within rounding of the boundary planes).
        for (int k = 0; k < 2000; ++k) {
            const glm::vec3 d = sampleWarpedStratum(id, test::hashedPoint(static_cast<uint64_t>(id * 100000 + k)));
            const glm::vec3 back = warpCosineToUniform(d);
            const auto corners = stratumVertices(id);
            const glm::vec3 inside = corners[0] + corners[1] + corners[2];
            const glm::vec3 nudged = back + 1e-5f * (inside - back);
            REQUIRE(stratumContains(id, nudged));
        }
    }
}

TEST_CASE("strata24-warped: the warp carries uniform directions to cosine-weighted ones, and back") {
    for (int k = 0; k < 1000; ++k) {
        const glm::vec3 d = sampleUniformHemisphere(test::hashedPoint(0xbacull + k));
        const glm::vec3 there = warpUniformToCosine(d);
        const glm::vec3 back = warpCosineToUniform(there);
        CHECK(std::abs(glm::length(there) - 1.0f) < 4e-7f);
        CHECK(glm::length(back - d) < 1e-6f);
    }
    // Exact values: W(0, 0, 1) is the pole, the horizon stays the horizon, and a uniform direction
    // at cos = 1/4 (a quarter of the uniform measure below it) goes to cos = 1/2 (a quarter of the
    // cosine measure below it: 1 - cos^2 = 3/4 above).
    const glm::vec3 pole = warpUniformToCosine({0.0f, 0.0f, 1.0f});
    CHECK(pole.z == 1.0f);
    const glm::vec3 horizon = warpUniformToCosine({0.6f, 0.8f, 0.0f});
    CHECK(horizon.x == doctest::Approx(0.6f));
    CHECK(horizon.y == doctest::Approx(0.8f));
    CHECK(horizon.z == 0.0f);
    const float s = std::sqrt(1.0f - 0.0625f);
    const glm::vec3 quarter = warpUniformToCosine({s, 0.0f, 0.25f});
    CHECK(quarter.z == doctest::Approx(0.5f));
    CHECK(quarter.x == doctest::Approx(std::sqrt(0.75f)));
}

TEST_CASE("strata24-warped: each warped stratum holds 1/24 of the cosine measure") {
    // i.i.d. cosine-weighted directions, classified by the stratum of their unwarped direction:
    // 24 equally likely cells.
    constexpr int kSamples = 240000;
    std::vector<int> counts(kStrataCount, 0);
    for (int k = 0; k < kSamples; ++k) {
        ++counts[static_cast<size_t>(classifyStratum(warpCosineToUniform(sampleCosineHemisphere(test::hashedPoint(0x5eed0000ull + k)))))];
    }
    const double expected = static_cast<double>(kSamples) / kStrataCount;
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    INFO("chi2 " << chi2 << " over 23 degrees of freedom");
    CHECK(chi2 < test::chiSquareCritical(kStrataCount - 1));
}

TEST_CASE("strata24-warped: one sample per stratum is cosine-distributed overall (chi-square)") {
    // Cells of equal cosine measure: 10 bins of cos^2(theta) by 32 of azimuth. Each round takes
    // one random point in every stratum, as a pass does.
    constexpr int kZBins = 10;
    constexpr int kPhiBins = 32;
    constexpr int kRounds = 8000;
    std::vector<int> counts(kZBins * kPhiBins, 0);
    for (int round = 0; round < kRounds; ++round) {
        for (int id = 0; id < kStrataCount; ++id) {
            const glm::vec3 d = sampleWarpedStratum(id, test::hashedPoint(hashCombine(0xc0501e5ull + round, id)));
            const int zb = std::min(kZBins - 1, static_cast<int>(d.z * d.z * kZBins));
            const double phi = std::atan2(d.y, d.x) + M_PI;
            const int pb = std::min(kPhiBins - 1, static_cast<int>(phi / (2.0 * M_PI) * kPhiBins));
            ++counts[static_cast<size_t>(zb * kPhiBins + pb)];
        }
    }
    const double expected = static_cast<double>(kRounds) * kStrataCount / counts.size();
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    INFO("chi2 " << chi2 << " over " << counts.size() - 1 << " degrees of freedom");
    CHECK(chi2 < test::chiSquareCritical(counts.size() - 1));
}
