#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "util/error.h"
#include "film/image_metrics.h"

using namespace strata;

namespace {
Image filled(int width, int height, const glm::vec3& value) {
    return Image{width, height, std::vector<glm::vec3>(size_t(width) * height, value)};
}
}  // namespace

TEST_CASE("image metrics: RMSE and relMSE of known images") {
    // Reference: half the pixels 0, half 1; the render is 0.1 too bright everywhere.
    Image reference = filled(2, 1, glm::vec3(0.0f));
    reference.pixels[1] = glm::vec3(1.0f);
    Image image = reference;
    for (auto& p : image.pixels) p += glm::vec3(0.1f);
    const ImageError error = imageError(image, reference);
    CHECK(error.mse == doctest::Approx(0.01).epsilon(1e-6));
    CHECK(error.rmse == doctest::Approx(0.1).epsilon(1e-6));
    // mean of 0.01 / (0 + 0.01) and 0.01 / (1 + 0.01)
    CHECK(error.relMse == doctest::Approx((1.0 + 0.01 / 1.01) / 2.0).epsilon(1e-6));
    CHECK(imageError(reference, reference).rmse == 0.0);
}

TEST_CASE("image metrics: a constant reference, a channel error and size mismatches") {
    Image image = filled(3, 2, glm::vec3(2.0f));
    image.pixels[0].y = 5.0f;  // one channel of six pixels off by 3: MSE = 9 / 18
    const ImageError error = imageError(image, glm::vec3(2.0f));
    CHECK(error.mse == doctest::Approx(0.5));
    CHECK(error.relMse == doctest::Approx(9.0 / (4.0 + 0.01) / 18.0));
    CHECK_THROWS_AS(imageError(image, filled(2, 3, glm::vec3(2.0f))), Error);
    CHECK(efficiency(0.5, 4.0) == doctest::Approx(0.5));
}

TEST_CASE("image metrics: a non-finite pixel makes the error non-finite") {
    Image image = filled(2, 2, glm::vec3(1.0f));
    image.pixels[3].x = std::numeric_limits<float>::quiet_NaN();
    CHECK(std::isnan(imageError(image, glm::vec3(1.0f)).rmse));
}
