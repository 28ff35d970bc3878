// A directional light (directional_light.h): a delta light at infinity giving E along its
// direction everywhere, power pi r^2 E for a scene of radius r.
#include <doctest/doctest.h>

#include <cmath>

#include "lights/directional_light.h"
#include "util/constants.h"

using namespace strata;

TEST_CASE("directional light: E from the opposite of its direction at any point, power pi r^2 E") {
    const DirectionalLight light({0.0f, -0.6f, -0.8f}, glm::vec3(1.0f, 2.0f, 3.0f), 2.0f);
    for (const glm::vec3 point : {glm::vec3(0.0f), glm::vec3(100.0f, -5.0f, 7.0f)}) {
        const auto s = light.sample(point, {0.25f, 0.75f});
        REQUIRE(s);
        CHECK(s->direction == glm::vec3(0.0f, 0.6f, 0.8f));
        CHECK(std::isinf(s->distance));
        CHECK(s->radiance == glm::vec3(1.0f, 2.0f, 3.0f));
        CHECK(s->pdf == 0.0f);
        CHECK_FALSE(s->onSurface);
    }
    CHECK(light.isDelta());
    CHECK(light.pdf({0, 0, 0}, {0.0f, 0.6f, 0.8f}, LightHit{}) == 0.0f);
    CHECK(light.emitted({0.0f, 0.6f, 0.8f}, LightHit{}) == glm::vec3(0.0f));  // no ray can find it
    CHECK(light.power().x == doctest::Approx(4.0f * kPi));
    CHECK(light.power().z == doctest::Approx(12.0f * kPi));
    CHECK(DirectionalLight({0.0f, 0.0f, -1.0f}, glm::vec3(1.0f)).power() == glm::vec3(0.0f));
}
