// An emitting triangle as a light (area_light.h): uniform by area, one-sided, its solid-angle
// density consistent between sample() and pdf(), and the power pi Le A.
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "lights/area_light.h"
#include "sampling/random.h"
#include "util/constants.h"

using namespace strata;

namespace {
// A right triangle of area 2 in the plane z = 1, counter-clockwise seen from below: it faces -z.
AreaLight downwardLight() {
    return AreaLight({0, 0, 1}, {0, 2, 1}, {2, 0, 1}, glm::vec3(1.0f, 2.0f, 3.0f));
}
glm::vec2 randomPoint(uint64_t k) {
    const uint64_t bits = mixBits(k);
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}
}  // namespace

TEST_CASE("area light: points uniform by area, density d^2 / (A cos) and the same from pdf()") {
    const AreaLight light = downwardLight();
    CHECK(light.area() == doctest::Approx(2.0f));
    const glm::vec3 receiver(0.3f, 0.4f, 0.0f);
    constexpr int kSamples = 40000;
    double sumX = 0.0;
    double inverseDensity = 0.0;  // estimates the solid angle the triangle subtends
    for (int k = 0; k < kSamples; ++k) {
        const auto s = light.sample(receiver, randomPoint(k));
        REQUIRE(s);
        const glm::vec3 point = receiver + s->distance * s->direction;
        CHECK(point.z == doctest::Approx(1.0f));
        CHECK(s->onSurface);
        CHECK(s->radiance.z == 3.0f);
        sumX += point.x;
        const float cosLight = s->direction.z;  // the light faces -z
        CHECK(s->pdf == doctest::Approx(s->distance * s->distance / (2.0f * cosLight)).epsilon(1e-5));
        const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f), s->distance};
        CHECK(light.pdf(receiver, s->direction, hit) == doctest::Approx(s->pdf).epsilon(1e-5));
        inverseDensity += 1.0 / s->pdf;
    }
    // The triangle's centroid has x = 2/3; x of a uniform point has variance 2/9 here.
    CHECK(std::abs(sumX / kSamples - 2.0 / 3.0) < 4.5 * std::sqrt(2.0 / 9.0 / kSamples));
    // E[1/pdf] is the subtended solid angle: compare with a fine midpoint quadrature over the
    // triangle of cos / d^2.
    double solidAngle = 0.0;
    constexpr int kGrid = 400;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            const double x = 2.0 * (i + 0.5) / kGrid, y = 2.0 * (j + 0.5) / kGrid;
            if (x + y > 2.0) continue;
            const glm::dvec3 d(x - 0.3, y - 0.4, 1.0);
            const double r2 = glm::dot(d, d);
            solidAngle += (1.0 / std::sqrt(r2)) / r2 * (4.0 / (kGrid * kGrid));
        }
    }
    CHECK(inverseDensity / kSamples == doctest::Approx(solidAngle).epsilon(0.01));
}

TEST_CASE("area light: emits from its front only, and its power is pi Le A") {
    const AreaLight light = downwardLight();
    const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f), 1.0f};
    CHECK(light.emitted({0, 0, 1}, hit).y == 2.0f);  // a ray going up meets the front
    CHECK(light.emitted({0, 0, -1}, hit).y == 0.0f);
    CHECK(light.pdf({0, 0, 2}, {0, 0, -1}, hit) == 0.0f);
    CHECK_FALSE(light.sample({0.5f, 0.5f, 2.0f}, {0.5f, 0.5f}));  // above it sees its back
    CHECK(light.power().x == doctest::Approx(kPi * 2.0f));
    CHECK_FALSE(light.isDelta());
}
