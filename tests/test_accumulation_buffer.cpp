#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "accumulation_buffer.h"

using namespace strata;

TEST_CASE("accumulation: mean, counts and the two standard errors") {
    AccumulationBuffer buffer(2, 1);
    // Pixel 0: passes of 2 samples each with pass means 1 and 3.
    buffer.addSample(0, glm::vec3(0.0f));
    buffer.addSample(0, glm::vec3(2.0f));
    buffer.completePass(0);
    buffer.addSample(0, glm::vec3(2.0f));
    buffer.addSample(0, glm::vec3(4.0f));
    buffer.completePass(0);
    CHECK(buffer.mean(0).x == 2.0);
    CHECK(buffer.sampleCount(0) == 4);
    CHECK(buffer.completedPasses(0) == 2);
    // Samples 0,2,2,4 (luminance = value for grey): variance 8/3, SE sqrt(8/3/4).
    CHECK(buffer.sampleStandardError(0) == doctest::Approx(std::sqrt(8.0 / 3.0 / 4.0)));
    // Pass means 1, 3: variance 2, SE sqrt(2/2) = 1.
    CHECK(buffer.passStandardError(0) == doctest::Approx(1.0));
    CHECK(buffer.mean(1).x == 0.0);  // no samples: zero, not NaN
    CHECK(buffer.passStandardError(1) == 0.0);
}

TEST_CASE("accumulation: non-finite samples are dropped and counted, never added") {
    AccumulationBuffer buffer(1, 1);
    buffer.addSample(0, glm::vec3(1.0f));
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    buffer.addSample(0, glm::vec3(nan, 0.0f, 0.0f));
    buffer.addSample(0, glm::vec3(0.0f, inf, 0.0f));
    buffer.addSample(0, glm::vec3(0.0f, 0.0f, -inf));
    CHECK(buffer.mean(0) == glm::dvec3(1.0));
    CHECK(buffer.sampleCount(0) == 1);
    CHECK(buffer.droppedSamples() == 3);
    buffer.clear();
    CHECK(buffer.droppedSamples() == 0);
    CHECK(buffer.sampleCount(0) == 0);
}
