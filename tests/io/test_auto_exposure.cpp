// The display's automatic exposure (auto_exposure.h): middle grey 0.18 for the log-average
// luminance of 8 x 8 blocks' means, black blocks left out, unless the brightest tenth would
// burn out.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "io/auto_exposure.h"

using namespace strata;

namespace {
Image uniform(int width, int height, const glm::vec3& value) {
    return Image{width, height, std::vector<glm::vec3>(static_cast<size_t>(width) * height, value)};
}

// A 80 x 80 image (100 blocks) at `background`, its first `blocks` blocks, row by row, at `value`.
Image withBlocks(float background, int blocks, float value) {
    Image image = uniform(80, 80, glm::vec3(background));
    for (int b = 0; b < blocks; ++b) {
        for (int y = 0; y < kExposureBlock; ++y) {
            for (int x = 0; x < kExposureBlock; ++x) {
                const int px = (b % 10) * kExposureBlock + x;
                const int py = (b / 10) * kExposureBlock + y;
                image.pixels[static_cast<size_t>(py) * 80 + px] = glm::vec3(value);
            }
        }
    }
    return image;
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

TEST_CASE("auto exposure: a bright part of the image is kept off white, a small lamp is not") {
    // A stage: 80% of it at 0.001, 20% in pools of light at 1. The log-average (2^-7.97) would
    // take +5.50 stops and show the pools at 45, white; the brightest tenth is held at 1 instead.
    CHECK(autoExposure(withBlocks(0.001f, 20, 1.0f)) == doctest::Approx(std::log2(kHighlightLimit / 1.0)).epsilon(1e-5));
    CHECK(autoExposure(withBlocks(0.001f, 20, 4.0f)) == doctest::Approx(std::log2(kHighlightLimit / 4.0)).epsilon(1e-5));
    // A lamp on 5% of a mid-grey image is left to burn out: the keyed exposure, log2 0.18 less
    // the log-average 0.95 log2 0.18 + 0.05 log2 100.
    const double keyed = std::log2(0.18) - (0.95 * std::log2(0.18) + 0.05 * std::log2(100.0));
    CHECK(autoExposure(withBlocks(0.18f, 5, 100.0f)) == doctest::Approx(keyed).epsilon(1e-5));
    // The tenth counts pixels above black only: 10 blocks of 1 in an otherwise black frame are
    // all of it, and their key decides (-2.47 stops, under the highlight limit's 0).
    CHECK(autoExposure(withBlocks(0.0f, 10, 1.0f)) == doctest::Approx(std::log2(0.18)).epsilon(1e-5));
}
