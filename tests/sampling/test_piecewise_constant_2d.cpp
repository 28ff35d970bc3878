// The piecewise-constant 2D distribution (piecewise_constant_2d.h): its samples follow its pdf
// (chi-square on cells split 2 x 2, so the point's uniformity inside a cell is checked too),
// cells of zero weight are never sampled, and the density integrates to 1.
#include <doctest/doctest.h>

#include <vector>

#include "sampling/piecewise_constant_2d.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("piecewise constant 2d: samples follow pdf(), zero cells never sampled") {
    constexpr int kWidth = 4, kHeight = 3;
    // Row 1 is all zero; cell (2, 0) is zero; the weights span two orders of magnitude.
    const std::vector<float> values = {1.0f, 5.0f, 0.0f, 0.2f,  //
                                       0.0f, 0.0f, 0.0f, 0.0f,  //
                                       20.0f, 3.0f, 0.5f, 8.0f};
    const PiecewiseConstant2D distribution(values, kWidth, kHeight);
    double integral = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const float pdf = distribution.pdf(glm::ivec2(x, y));
            CHECK((pdf > 0.0f) == (values[y * kWidth + x] > 0.0f));
            integral += pdf / (kWidth * kHeight);
        }
    }
    CHECK(integral == doctest::Approx(1.0).epsilon(1e-6));
    // The density is the weight over the mean weight: 37.7 / 12 in all.
    CHECK(distribution.pdf(glm::ivec2(0, 2)) == doctest::Approx(20.0 * 12.0 / 37.7).epsilon(1e-5));

    constexpr int kSub = 2;  // each cell split kSub x kSub
    constexpr int kSamples = 200000;
    std::vector<double> counts(kWidth * kSub * kHeight * kSub, 0.0);
    int mismatched = 0;
    for (int k = 0; k < kSamples; ++k) {
        const auto s = distribution.sample(test::hashedPoint(k + 0x51ab));
        REQUIRE(s.point.x >= 0.0f);
        REQUIRE(s.point.x < 1.0f);
        REQUIRE(s.point.y >= 0.0f);
        REQUIRE(s.point.y < 1.0f);
        if (s.pdf != distribution.pdf(s.point)) ++mismatched;
        const int x = static_cast<int>(s.point.x * kWidth * kSub);
        const int y = static_cast<int>(s.point.y * kHeight * kSub);
        counts[y * kWidth * kSub + x] += 1.0;
    }
    CHECK(mismatched == 0);
    double chiSquare = 0.0;
    size_t degrees = 0;
    for (int y = 0; y < kHeight * kSub; ++y) {
        for (int x = 0; x < kWidth * kSub; ++x) {
            const double expected = kSamples * distribution.pdf(glm::ivec2(x / kSub, y / kSub)) /
                                    (kWidth * kHeight * kSub * kSub);
            const double count = counts[y * kWidth * kSub + x];
            if (expected == 0.0) {
                CHECK(count == 0.0);
                continue;
            }
            chiSquare += (count - expected) * (count - expected) / expected;
            ++degrees;
        }
    }
    CHECK(chiSquare < test::chiSquareCritical(degrees - 1));
}

TEST_CASE("piecewise constant 2d: inputs 0 and 1 - ulp stay inside cells of positive weight") {
    const PiecewiseConstant2D distribution({0.0f, 2.0f, 0.0f, 0.0f, 0.0f, 0.0f}, 3, 2);
    for (float u : {0.0f, 0.5f, 1.0f - 0x1p-24f}) {
        for (float v : {0.0f, 0.5f, 1.0f - 0x1p-24f}) {
            const auto s = distribution.sample({u, v});
            CHECK(distribution.cellOf(s.point) == glm::ivec2(1, 0));
            CHECK(s.pdf == doctest::Approx(6.0f));
        }
    }
    // All zero: uniform.
    const PiecewiseConstant2D flat(std::vector<float>(6, 0.0f), 3, 2);
    CHECK(flat.pdf(glm::vec2(0.9f, 0.1f)) == 1.0f);
    CHECK(flat.sample({0.5f, 0.25f}).pdf == 1.0f);
}
