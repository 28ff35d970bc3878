// Light sampling for next-event estimation (emitter_sampler.h): triangles by power, points
// uniform by area, densities that integrate to 1.
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "lights/emitter_sampler.h"
#include "sampling/random.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("emitter sampler: triangles by power, points uniform on them, density per area") {
    MeshData mesh;
    Material dark;
    Material bright;
    bright.emission = glm::vec3(3.0f, 3.0f, 3.0f);
    Material dim;
    dim.emission = glm::vec3(0.0f, 0.0f, 3.0f);  // mean radiance 1
    mesh.materials = {dark, bright, dim};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);  // area 1, not emitting
    test::addQuad(mesh, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}, 1);  // area 2, power 6
    test::addQuad(mesh, {0, 0, 2}, {0, 1, 2}, {2, 1, 2}, {2, 0, 2}, 2);  // area 2, power 2
    const EmitterSampler sampler(mesh);
    REQUIRE_FALSE(sampler.empty());
    CHECK(sampler.areaPdf(0) == 0.0f);
    // P(bright quad) = 6/8 over area 2; P(dim quad) = 2/8 over area 2.
    CHECK(sampler.areaPdf(2) == doctest::Approx(0.75 / 2.0));
    CHECK(sampler.areaPdf(4) == doctest::Approx(0.25 / 2.0));

    constexpr int kSamples = 80000;
    int bright_ = 0;
    double sumX = 0.0;
    for (int k = 0; k < kSamples; ++k) {
        const uint64_t a = mixBits(k);
        const uint64_t b = mixBits(a);
        const EmitterSample s = sampler.sample({uniformFloat(a), uniformFloat(b), uniformFloat(b << 24)});
        const bool onBright = std::abs(s.point.z - 1.0f) < 1e-5f;
        REQUIRE((onBright || std::abs(s.point.z - 2.0f) < 1e-5f));
        if (onBright) {
            ++bright_;
            sumX += s.point.x;
            CHECK(s.normal.z == doctest::Approx(1.0f));
            CHECK(s.areaPdf == doctest::Approx(0.375));
        } else {
            CHECK(s.normal.z == doctest::Approx(-1.0f));
        }
    }
    // Binomial: 0.75 +- 4.5 sd; uniform by area: mean x on [0,2] is 1 (sd of x is 1/sqrt 3).
    const double p = static_cast<double>(bright_) / kSamples;
    CHECK(std::abs(p - 0.75) < 4.5 * std::sqrt(0.75 * 0.25 / kSamples));
    CHECK(std::abs(sumX / bright_ - 1.0) < 4.5 / std::sqrt(3.0 * bright_));
}

TEST_CASE("emitter sampler: a scene without emitters is empty") {
    Material dark;
    dark.diffuse = glm::vec3(0.5f);
    MeshData mesh;
    mesh.materials = {dark};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
    CHECK(EmitterSampler(mesh).empty());
}
