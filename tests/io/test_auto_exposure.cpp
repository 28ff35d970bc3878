// The display's automatic exposure (auto_exposure.h): middle grey 0.18 for the log-average
// luminance of 8 x 8 blocks' means, black blocks left out.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "io/auto_exposure.h"

using namespace strata;

namespace {
Image uniform(int width, int height, const glm::vec3& value) {
    return Image{width, height, std::vector<glm::vec3>(static_cast<size_t>(width) * height, value)};
}
}  // namespace

TEST_CASE("auto exposure: the key 0.18 over the log-average of the blocks' luminance") {
    CHECK(autoExposure(uniform(16, 16, glm::vec3(0.18f))) == doctest::Approx(0.0f).epsilon(1e-5));
    CHECK(autoExposure(uniform(16, 16, glm::vec3(0.72f))) == doctest::Approx(-2.0f).epsilon(1e-5));
    CHECK(autoExposure(uniform(5, 3, glm::vec3(0.045f))) == doctest::Approx(2.0f).epsilon(1e-5));
    // Luminance, Rec. 709: pure green of 0.18 / 0.7152 is middle grey.
    CHECK(autoExposure(uniform(8, 8, glm::vec3(0.0f, 0.18f / 0.7152f, 0.0f))) == doctest::Approx(0.0f).epsilon(1e-4));
    // Half the image at 0.045, half at 0.72: the geometric mean 0.18, weighted by pixels.
    Image halves = uniform(16, 16, glm::vec3(0.045f));
    for (size_t p = 128; p < 256; ++p) halves.pixels[p] = glm::vec3(0.72f);
    CHECK(autoExposure(halves) == doctest::Approx(0.0f).epsilon(1e-5));
    // Black blocks are left out; an image with none above black keeps exposure 0; the limit holds.
    Image framed = uniform(32, 32, glm::vec3(0.0f));
    for (int y = 8; y < 16; ++y) {
        for (int x = 8; x < 16; ++x) framed.pixels[static_cast<size_t>(y) * 32 + x] = glm::vec3(0.72f);
    }
    CHECK(autoExposure(framed) == doctest::Approx(-2.0f).epsilon(1e-5));
    CHECK(autoExposure(uniform(8, 8, glm::vec3(0.0f))) == 0.0f);
    CHECK(autoExposure(uniform(8, 8, glm::vec3(1e-30f))) == kExposureLimit);
}

TEST_CASE("auto exposure: one noisy sample per pixel meters within a fifth of a stop of the converged image") {
    // Each pixel 0 or 2 x 0.36 with probability 1/2, mean 0.36 (one stop above the key): the
    // plain log-average of the non-zero pixels would meter 0.72, a stop off.
    std::mt19937_64 rng(7);
    std::bernoulli_distribution coin(0.5);
    Image noisy = uniform(128, 96, glm::vec3(0.0f));
    for (auto& p : noisy.pixels) p = glm::vec3(coin(rng) ? 0.72f : 0.0f);
    CHECK(std::abs(autoExposure(noisy) - -1.0f) < 0.2f);
}
