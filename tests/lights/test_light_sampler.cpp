// The choice among lights by power (light_sampler.h).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "lights/light_sampler.h"
#include "sampling/random.h"

using namespace strata;

TEST_CASE("light sampler: each light with probability proportional to its power") {
    const LightSampler sampler({6.0, 0.0, 2.0});
    REQUIRE_FALSE(sampler.empty());
    CHECK(sampler.probability(0) == doctest::Approx(0.75f));
    CHECK(sampler.probability(1) == 0.0f);
    CHECK(sampler.probability(2) == doctest::Approx(0.25f));
    constexpr int kSamples = 100000;
    std::vector<int> counts(3, 0);
    for (int k = 0; k < kSamples; ++k) {
        const LightChoice c = sampler.choose(uniformFloat(mixBits(k)));
        CHECK(c.probability == sampler.probability(c.light));
        ++counts[c.light];
    }
    CHECK(counts[1] == 0);  // a zero-power light is never chosen
    const double p = static_cast<double>(counts[0]) / kSamples;
    CHECK(std::abs(p - 0.75) < 4.5 * std::sqrt(0.75 * 0.25 / kSamples));
    // The ends of [0,1): the first and the last light of positive power.
    CHECK(sampler.choose(0.0f).light == 0);
    CHECK(sampler.choose(0.99999994f).light == 2);
}

TEST_CASE("light sampler: nothing to choose without power") {
    CHECK(LightSampler({}).empty());
    CHECK(LightSampler({0.0, 0.0}).empty());
}
