#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "sampling/hemisphere.h"
#include "sampling/random.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("hemisphere: uniform samples are unit, above the surface, and uniform in (z, phi)") {
    // Uniform on the hemisphere <=> z and phi independent and uniform: chi-square on a 16x16 grid.
    constexpr int kBins = 16;
    constexpr int kSamples = 256000;
    std::array<int, kBins * kBins> counts{};
    for (int i = 0; i < kSamples; ++i) {
        const uint64_t bits = mixBits(static_cast<uint64_t>(i) + 12345);
        const glm::vec3 d = sampleUniformHemisphere({uniformFloat(bits), uniformFloat(bits << 24)});
        REQUIRE(std::abs(glm::length(d) - 1.0f) < 1e-6f);
        REQUIRE(d.z >= 0.0f);
        const double phi = std::atan2(d.y, d.x) + M_PI;
        const int zBin = std::min(kBins - 1, static_cast<int>(d.z * kBins));
        const int phiBin = std::min(kBins - 1, static_cast<int>(phi / (2 * M_PI) * kBins));
        ++counts[zBin * kBins + phiBin];
    }
    const double expected = static_cast<double>(kSamples) / counts.size();
    double chiSquare = 0.0;
    for (int c : counts) chiSquare += (c - expected) * (c - expected) / expected;
    CHECK(chiSquare < test::chiSquareCritical(counts.size() - 1));
}

TEST_CASE("hemisphere: corner inputs stay unit and above the surface") {
    const float almostOne = std::nextafter(1.0f, 0.0f);
    for (float u : {0.0f, almostOne}) {
        for (float v : {0.0f, almostOne}) {
            const glm::vec3 d = sampleUniformHemisphere({u, v});
            CHECK(std::abs(glm::length(d) - 1.0f) < 1e-6f);
            CHECK(d.z >= 0.0f);
        }
    }
}
