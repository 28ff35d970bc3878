#include <doctest/doctest.h>

#include <cmath>

#include "bench/convergence.h"
#include "util/error.h"

using namespace strata;

TEST_CASE("convergence: the fitted slope of an exact power law") {
    std::vector<double> spp, rmse;
    for (double n = 24; n <= 24 * 64; n *= 2) {
        spp.push_back(n);
        rmse.push_back(3.0 * std::pow(n, -0.5));
    }
    const PowerLawFit fit = fitPowerLaw(spp, rmse);
    CHECK(fit.slope == doctest::Approx(-0.5).epsilon(1e-12));
    CHECK(fit.constant == doctest::Approx(3.0).epsilon(1e-12));
    CHECK(fit.slopeStandardError < 1e-12);
}

TEST_CASE("convergence: slope standard error of a known zig-zag") {
    // log y = -log x + r_i with residuals r = (+d, -d, +d, -d) at log x = 0, 1, 2, 3: the OLS
    // slope is -1 + sum (i - 1.5) r_i / sum (i - 1.5)^2, and sum (i - 1.5)^2 = 5.
    const double d = 0.1;
    std::vector<double> x, y;
    const double residual[] = {d, -d, d, -d};
    for (int i = 0; i < 4; ++i) {
        x.push_back(std::exp(double(i)));
        y.push_back(std::exp(-double(i) + residual[i]));
    }
    const PowerLawFit fit = fitPowerLaw(x, y);
    const double sxy = (-1.5 * d) + (-0.5 * -d) + (0.5 * d) + (1.5 * -d);  // -0.2
    CHECK(fit.slope == doctest::Approx(-1.0 + sxy / 5.0).epsilon(1e-12));
    double residuals = 0.0;
    for (int i = 0; i < 4; ++i) {
        const double predicted = std::log(fit.constant) + fit.slope * i;
        residuals += std::pow(std::log(y[i]) - predicted, 2);
    }
    CHECK(fit.slopeStandardError == doctest::Approx(std::sqrt(residuals / 2.0 / 5.0)).epsilon(1e-12));
}

TEST_CASE("convergence: bad input to a fit is refused") {
    CHECK_THROWS_AS(fitPowerLaw({1.0}, {1.0}), Error);
    CHECK_THROWS_AS(fitPowerLaw({1.0, 2.0}, {1.0, 0.0}), Error);
    CHECK_THROWS_AS(fitPowerLaw({2.0, 2.0}, {1.0, 3.0}), Error);
    CHECK_THROWS_AS(fitPowerLaw({1.0, 2.0}, {1.0, std::nan("")}), Error);
}

TEST_CASE("convergence: log-log interpolation and first reach") {
    CHECK(*interpolateLogLog({1.0, 100.0}, {1.0, 0.01}, 10.0) == doctest::Approx(0.1));
    CHECK(*interpolateLogLog({1.0, 100.0}, {1.0, 0.01}, 100.0) == doctest::Approx(0.01));
    CHECK_FALSE(interpolateLogLog({1.0, 100.0}, {1.0, 0.01}, 200.0));
    // Error halves from 4 to 16 seconds: it reaches 0.5/sqrt(2) at 8 seconds.
    const std::vector<double> seconds{1.0, 4.0, 16.0}, error{1.0, 0.5, 0.25};
    CHECK(*firstReach(seconds, error, 0.5 / std::sqrt(2.0)) == doctest::Approx(8.0));
    CHECK(*firstReach(seconds, error, 2.0) == doctest::Approx(1.0));
    CHECK_FALSE(firstReach(seconds, error, 0.1));
}

TEST_CASE("convergence: variance ratios and the paper's claims") {
    CHECK(varianceRatio({2.0, 8.0}, {1.0, 4.0}) == doctest::Approx(2.0));
    CHECK(varianceRatio({1.0, 4.0}, {4.0, 1.0}) == doctest::Approx(1.0));  // geometric mean
    CHECK_THROWS_AS(varianceRatio({1.0}, {1.0, 2.0}), Error);
    CHECK(paperSection4Ratio(24.0) == doctest::Approx(1.0 / 24.0));
    CHECK(paperSection4Ratio(1.0) == 0.0);
    CHECK(kPaperSection3Ratio == doctest::Approx(1.0 / 24.0));
}
