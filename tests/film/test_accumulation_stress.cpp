// The accumulation buffer under load: 1e7 samples per pixel, 1e4 progressive passes, bursts of
// non-finite samples (accumulation_buffer.h promises all three).
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "film/accumulation_buffer.h"

using namespace strata;

TEST_CASE("accumulation stress: 1e7 samples of a constant average to it within 1e-9 relative") {
    // Constants whose float values have full mantissas, so every addition rounds.
    const glm::vec3 constant(0.1f, 1.0f / 3.0f, 123456.789f);
    AccumulationBuffer buffer(2, 1);
    for (int i = 0; i < 10'000'000; ++i) buffer.addSample(0, constant);
    REQUIRE(buffer.sampleCount(0) == 10'000'000u);
    const glm::dvec3 mean = buffer.mean(0);
    for (int c = 0; c < 3; ++c) {
        CAPTURE(c);
        CHECK(std::abs(mean[c] / static_cast<double>(constant[c]) - 1.0) < 1e-9);
    }
    // A constant has no spread: the estimated error is zero up to the rounding of the sums.
    CHECK(buffer.sampleStandardError(0) < 1e-9 * luminance(glm::dvec3(constant)));
    CHECK(buffer.sampleCount(1) == 0);
    CHECK(buffer.mean(1) == glm::dvec3(0.0));
}

TEST_CASE("accumulation stress: 1e4 progressive passes do not drift") {
    const glm::vec3 constant(0.7f, 0.2f, 0.05f);
    const double expected = luminance(glm::dvec3(constant));
    AccumulationBuffer buffer(1, 1);
    double worst = 0.0;
    for (int pass = 0; pass < 10'000; ++pass) {
        for (int step = 0; step < 24; ++step) buffer.addSample(0, constant);
        buffer.completePass(0);
        worst = std::max(worst, std::abs(luminance(buffer.mean(0)) / expected - 1.0));
    }
    CAPTURE(worst);
    CHECK(worst < 1e-12);
    CHECK(buffer.completedPasses(0) == 10'000u);
    CHECK(buffer.sampleCount(0) == 240'000u);
    // The pass error comes from sums of squares minus the squared sum, whose cancellation leaves a
    // floor near sqrt(n) u relative (measured 7e-9 here), far below any real image's error.
    CHECK(buffer.passStandardError(0) < 1e-7 * expected);
}

TEST_CASE("accumulation stress: a burst of non-finite samples is dropped, counted and leaves no trace") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    AccumulationBuffer clean(3, 1);
    AccumulationBuffer burst(3, 1);
    uint64_t injected = 0;
    for (int pass = 0; pass < 50; ++pass) {
        for (size_t pixel = 0; pixel < 3; ++pixel) {
            for (int step = 0; step < 24; ++step) {
                const glm::vec3 value(0.01f * static_cast<float>(pass + step), 0.5f, static_cast<float>(pixel));
                clean.addSample(pixel, value);
                burst.addSample(pixel, value);
                // Pass 20 brings a burst of every kind of non-finite value into pixel 1, including
                // one bad channel next to good ones.
                if (pass == 20 && pixel == 1) {
                    for (const glm::vec3& bad : {glm::vec3(nan), glm::vec3(inf), glm::vec3(-inf),
                                                 glm::vec3(1.0f, nan, 1.0f), glm::vec3(0.0f, 0.0f, inf)}) {
                        burst.addSample(pixel, bad);
                        ++injected;
                    }
                }
            }
            clean.completePass(pixel);
            burst.completePass(pixel);
        }
    }
    CHECK(clean.droppedSamples() == 0);
    CHECK(burst.droppedSamples() == injected);
    for (size_t pixel = 0; pixel < 3; ++pixel) {
        CAPTURE(pixel);
        // Bit-identical: the dropped samples touched no sum, count or pass statistic.
        CHECK(burst.mean(pixel) == clean.mean(pixel));
        CHECK(burst.sampleCount(pixel) == clean.sampleCount(pixel));
        CHECK(burst.completedPasses(pixel) == clean.completedPasses(pixel));
        CHECK(burst.sampleStandardError(pixel) == clean.sampleStandardError(pixel));
        CHECK(burst.passStandardError(pixel) == clean.passStandardError(pixel));
    }
    // A pass made only of non-finite samples is not a pass.
    AccumulationBuffer onlyBad(1, 1);
    for (int i = 0; i < 24; ++i) onlyBad.addSample(0, glm::vec3(nan));
    onlyBad.completePass(0);
    CHECK(onlyBad.completedPasses(0) == 0);
    CHECK(onlyBad.sampleCount(0) == 0);
    CHECK(onlyBad.mean(0) == glm::dvec3(0.0));
    CHECK(onlyBad.droppedSamples() == 24);
}
