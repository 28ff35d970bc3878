// A light cluster's bounds and importance (light_bounds.h): zero exactly where the cluster can
// send nothing (behind its emitters, below the receiving surface), and a cone union that holds
// both cones.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "lights/light_bounds.h"
#include "sampling/random.h"

using namespace strata;

namespace {
// A unit square at z = 1 emitting downward.
LightBounds downwardSquare() {
    LightBounds b;
    b.lower = {-0.5f, -0.5f, 1.0f};
    b.upper = {0.5f, 0.5f, 1.0f};
    b.axis = {0.0f, 0.0f, -1.0f};
    b.power = 2.0f;
    return b;
}
glm::vec3 randomDirection(uint64_t k) {
    const uint64_t bits = mixBits(k);
    const float z = 2.0f * uniformFloat(bits) - 1.0f;
    const float phi = 6.2831853f * uniformFloat(bits << 24);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}
}  // namespace

TEST_CASE("light bounds: importance is zero behind the emitters and below the surface, else positive") {
    const ImportanceBounds b = importanceBounds(downwardSquare());
    const glm::vec3 none(0.0f);
    CHECK(importance(b, {0, 0, -1}, none) > 0.0f);            // in front, below the square
    CHECK(importance(b, {0, 0, 3}, none) == 0.0f);            // behind it
    CHECK(importance(b, {5, 0, 0.99f}, none) > 0.0f);         // far beside it, just in front
    CHECK(importance(b, {0, 0, -1}, {0, 0, 1}) > 0.0f);       // facing it
    CHECK(importance(b, {0, 0, -1}, {0, 0, -1}) == 0.0f);     // turned away: the square is below
    CHECK(importance(b, {0, 0, -1}, {1, 0, 0}) > 0.0f);       // edge on: part of the square above
    // Nearer is more.
    CHECK(importance(b, {0, 0, 0}, none) > importance(b, {0, 0, -3}, none));
}

TEST_CASE("light bounds: the union of two cones holds both") {
    for (uint64_t k = 0; k < 2000; ++k) {
        LightBounds a, b;
        a.axis = randomDirection(2 * k);
        b.axis = randomDirection(2 * k + 1);
        a.cosSpread = std::cos(3.14159f * uniformFloat(mixBits(k + 5000)) * 0.5f);
        b.cosSpread = k % 3 == 0 ? 1.0f : std::cos(3.14159f * uniformFloat(mixBits(k + 9000)) * 0.5f);
        const LightBounds u = unite(a, b);
        for (const LightBounds* c : {&a, &b}) {
            const float between = std::acos(std::clamp(glm::dot(u.axis, c->axis), -1.0f, 1.0f));
            const float spread = std::acos(std::clamp(u.cosSpread, -1.0f, 1.0f));
            CHECK(between + std::acos(c->cosSpread) <= spread + 1e-3f);
        }
    }
}
