// cosSinOfTurns against the double-precision cosine and sine: absolute error, the relative error
// of small sines and cosines near the quarter turns, and the exact values at the quarter turns.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "util/turns.h"

using namespace strata;

TEST_CASE("turns: cos and sin of 2 pi t within 2e-7 over [0, 1], on a grid and at random") {
    std::mt19937_64 rng(20261206);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    double worst = 0.0;
    double worstNorm = 0.0;
    for (int i = 0; i <= 2000000; ++i) {
        const float t = i % 2 == 0 ? static_cast<float>(i / 2) / 1000000.0f : uniform(rng);
        const glm::vec2 cs = cosSinOfTurns(t);
        const double angle = 2.0 * M_PI * static_cast<double>(t);
        worst = std::max({worst, std::abs(double(cs.x) - std::cos(angle)), std::abs(double(cs.y) - std::sin(angle))});
        worstNorm = std::max(worstNorm, std::abs(double(cs.x) * cs.x + double(cs.y) * cs.y - 1.0));
    }
    CAPTURE(worst);
    CAPTURE(worstNorm);
    CHECK(worst < 2e-7);
    CHECK(worstNorm < 4e-7);
}

TEST_CASE("turns: small sines and cosines keep their relative precision") {
    // Near each quarter turn the component that vanishes there is the remainder's sine.
    for (float quarter : {0.0f, 0.25f, 0.5f, 0.75f}) {
        for (float offset = 1e-7f; offset < 1e-2f; offset *= 1.7f) {
            for (float sign : {1.0f, -1.0f}) {
                const float t = quarter + sign * offset;
                if (t < 0.0f) continue;
                const glm::vec2 cs = cosSinOfTurns(t);
                const double angle = 2.0 * M_PI * static_cast<double>(t);
                const double exactCos = std::cos(angle);
                const double exactSin = std::sin(angle);
                const double small = std::abs(exactCos) < std::abs(exactSin) ? exactCos : exactSin;
                const double computed = std::abs(exactCos) < std::abs(exactSin) ? cs.x : cs.y;
                CAPTURE(t);
                CHECK(std::abs(computed - small) <= 4e-7 * std::abs(small));
            }
        }
    }
}

TEST_CASE("turns: the quarter turns are exact") {
    CHECK(cosSinOfTurns(0.0f) == glm::vec2(1.0f, 0.0f));
    CHECK(cosSinOfTurns(0.25f) == glm::vec2(-0.0f, 1.0f));
    CHECK(cosSinOfTurns(0.5f) == glm::vec2(-1.0f, -0.0f));
    CHECK(cosSinOfTurns(0.75f) == glm::vec2(0.0f, -1.0f));
    CHECK(cosSinOfTurns(1.0f) == glm::vec2(1.0f, 0.0f));
}
