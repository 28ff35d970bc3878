// A clear coat with a normal of its own (clear_coat.h): its lobe is the coat's of its own frame,
// projected on its normal. The contract every model keeps (sampling, energy) is checked for tilted
// coats in test_bsdf.cpp.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/frame.h"
#include "materials/bsdf.h"
#include "materials/material_table.h"
#include "test_support.h"
#include "util/constants.h"

using namespace strata;

namespace {

// A direction of the unit sphere from two numbers in [0, 1).
glm::vec3 sphereDirection(glm::vec2 u) {
    const float z = 2.0f * u.x - 1.0f;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// A rough coat over a black base: the coat's lobe alone.
MaterialTable roughCoatAlone() {
    Material m;
    m.name = "coat alone";
    m.diffuse = glm::vec3(0.0f);
    m.clearcoat = 0.9f;
    m.clearcoatRoughness = 0.35f;
    return MaterialTable({m});
}

}  // namespace

TEST_CASE("clear coat: a tilted coat reflects as the coat of its own frame, projected on its normal") {
    const MaterialTable table = roughCoatAlone();
    const Bsdf untilted = table.bsdf(0);
    const glm::vec3 axis = glm::normalize(glm::vec3(0.4f, -0.3f, 0.85f));
    Bsdf tilted = table.bsdf(0);
    tilted.tiltCoat(axis);
    const Frame coat = Frame::fromNormal(axis);
    int checked = 0;
    for (uint64_t s = 0; s < 2000; ++s) {
        const glm::vec3 wo = sphereDirection(test::hashedPoint(2 * s));
        const glm::vec3 wi = sphereDirection(test::hashedPoint(2 * s + 1));
        const glm::vec3 coatWo = coat.toLocal(wo);
        const glm::vec3 coatWi = coat.toLocal(wi);
        const glm::vec3 f = tilted.evaluate(wo, wi);
        INFO("wo (" << wo.x << ", " << wo.y << ", " << wo.z << "), wi (" << wi.x << ", " << wi.y << ", " << wi.z << ")");
        if (wo.z <= 0.0f || wi.z <= 0.0f || coatWo.z <= 0.0f || coatWi.z <= 0.0f) {
            // Below the surface, or a direction the coat sees from below: nothing reflected.
            if (wo.z > 0.0f && wi.z > 0.0f) CHECK(f == glm::vec3(0.0f));
            continue;
        }
        ++checked;
        const glm::vec3 own = untilted.evaluate(coatWo, coatWi);
        CHECK(f.x * wi.z == doctest::Approx(own.x * coatWi.z).epsilon(1e-4));
        CHECK(tilted.pdf(wo, wi) == doctest::Approx(untilted.pdf(coatWo, coatWi)).epsilon(1e-4));
    }
    CHECK(checked > 100);
}

TEST_CASE("clear coat: a smooth tilted coat mirrors about its own normal") {
    Material m;
    m.name = "smooth coat";
    m.diffuse = glm::vec3(0.5f);
    m.clearcoat = 1.0f;
    const MaterialTable table({m});
    const glm::vec3 axis = glm::normalize(glm::vec3(-0.2f, 0.3f, 0.9f));
    Bsdf bsdf = table.bsdf(0);
    bsdf.tiltCoat(axis);
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 0.8f));
    // A lobe choice of 0 takes the coat (its probability is at least 0.05).
    const auto sample = bsdf.sample(wo, BsdfNumbers::independent(glm::vec2(0.5f), 0.0f));
    REQUIRE(sample);
    CHECK(isSpecular(sample->flags));
    const glm::vec3 mirrored = 2.0f * glm::dot(wo, axis) * axis - wo;
    CHECK(sample->wi.x == doctest::Approx(mirrored.x).epsilon(1e-5));
    CHECK(sample->wi.y == doctest::Approx(mirrored.y).epsilon(1e-5));
    CHECK(sample->wi.z == doctest::Approx(mirrored.z).epsilon(1e-5));
}
