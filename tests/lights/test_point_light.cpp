// A point light (point_light.h): a delta light giving I / r^2, power 4 pi I.
#include <doctest/doctest.h>

#include "lights/point_light.h"
#include "util/constants.h"

using namespace strata;

TEST_CASE("point light: I / r^2 toward the light, a delta light of power 4 pi I") {
    const PointLight light({0.0f, 3.0f, 4.0f}, glm::vec3(10.0f, 20.0f, 50.0f));
    const auto s = light.sample({0.0f, 0.0f, 0.0f}, {0.25f, 0.75f});
    REQUIRE(s);
    CHECK(s->distance == doctest::Approx(5.0f));
    CHECK(s->direction.y == doctest::Approx(0.6f));
    CHECK(s->direction.z == doctest::Approx(0.8f));
    CHECK(s->radiance.z == doctest::Approx(2.0f));
    CHECK_FALSE(s->onSurface);
    CHECK(light.isDelta());
    CHECK(light.pdf({0, 0, 0}, s->direction, LightHit{}) == 0.0f);
    CHECK(light.emitted(s->direction, LightHit{}).x == 0.0f);  // no ray can find it
    CHECK(light.power().y == doctest::Approx(80.0f * kPi));
    CHECK_FALSE(light.sample({0.0f, 3.0f, 4.0f}, {0.5f, 0.5f}));  // at the light itself
}
