// A spot light (spot_light.h): I t^2 / r^2 inside its cone, nothing outside, and the power its
// closed form gives against a quadrature of the falloff over the sphere.
#include <doctest/doctest.h>

#include <cmath>

#include "lights/spot_light.h"
#include "util/constants.h"

using namespace strata;

namespace {

float radians(float degrees) { return degrees * kPi / 180.0f; }

// A point at `degrees` from the axis of a light at (0, 0, 4) pointing down -z, `distance` from it.
glm::vec3 pointAt(float degrees, float distance) {
    return glm::vec3(distance * std::sin(radians(degrees)), 0.0f, 4.0f - distance * std::cos(radians(degrees)));
}

}  // namespace

TEST_CASE("spot light: I / r^2 within the inner cone, I t^2 / r^2 across the ramp, nothing outside") {
    const SpotLight light({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, -1.0f}, glm::vec3(10.0f, 20.0f, 40.0f), radians(20.0f),
                          radians(40.0f));
    const auto onAxis = light.sample({0.0f, 0.0f, 0.0f}, {0.5f, 0.5f});
    REQUIRE(onAxis);
    CHECK(onAxis->distance == doctest::Approx(4.0f));
    CHECK(onAxis->direction.z == doctest::Approx(1.0f));
    CHECK(onAxis->radiance.z == doctest::Approx(40.0f / 16.0f));
    CHECK(light.isDelta());
    CHECK(light.pdf({0, 0, 0}, onAxis->direction, LightHit{}) == 0.0f);
    const auto inner = light.sample(pointAt(19.9f, 2.0f), {0.5f, 0.5f});
    REQUIRE(inner);
    CHECK(inner->radiance.x == doctest::Approx(10.0f / 4.0f));
    const auto ramp = light.sample(pointAt(30.0f, 5.0f), {0.5f, 0.5f});
    REQUIRE(ramp);
    const double t = (std::cos(M_PI / 6.0) - std::cos(2.0 * M_PI / 9.0)) / (std::cos(M_PI / 9.0) - std::cos(2.0 * M_PI / 9.0));
    CHECK(ramp->radiance.x == doctest::Approx(10.0 * t * t / 25.0).epsilon(1e-4));
    CHECK_FALSE(light.sample(pointAt(40.5f, 3.0f), {0.5f, 0.5f}));
    CHECK_FALSE(light.sample(pointAt(150.0f, 3.0f), {0.5f, 0.5f}));  // behind it
    CHECK_FALSE(light.sample({0.0f, 0.0f, 4.0f}, {0.5f, 0.5f}));     // at the light itself
}

TEST_CASE("spot light: the power is I times the falloff's integral over the sphere") {
    // (inner, outer) in degrees: a cone with a ramp, glTF's default (0, 45), a hard edge whose
    // ramp is widened to 1e-3 in cos theta, and a hemisphere.
    for (const auto& [inner, outer] : {std::pair{20.0f, 40.0f}, std::pair{0.0f, 45.0f}, std::pair{30.0f, 30.0f},
                                       std::pair{0.0f, 90.0f}}) {
        const SpotLight light({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, glm::vec3(3.0f), radians(inner), radians(outer));
        constexpr int kSteps = 1000000;
        double integral = 0.0;
        for (int i = 0; i < kSteps; ++i) {
            const double c = -1.0 + 2.0 * (i + 0.5) / kSteps;
            integral += light.falloff(static_cast<float>(c));
        }
        integral *= 2.0 * M_PI * 2.0 / kSteps;
        CAPTURE(inner);
        CAPTURE(outer);
        CHECK(light.power().x == doctest::Approx(3.0 * integral).epsilon(1e-4));
    }
}
