// A scene's lights (scene_lights.h): emitting triangles become area lights found by their
// triangle, point lights are added after them, and the choice among all of them is by power.
#include <doctest/doctest.h>

#include "lights/scene_lights.h"
#include "util/constants.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("scene lights: emitting triangles and point lights, chosen by power") {
    MeshData mesh;
    Material dark;
    dark.diffuse = glm::vec3(0.5f);
    Material bright;
    bright.emission = glm::vec3(3.0f);
    Material blue;
    blue.emission = glm::vec3(0.0f, 0.0f, 3.0f);  // mean radiance 1
    mesh.materials = {dark, bright, blue};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);  // area 1, not emitting
    test::addQuad(mesh, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}, 1);  // area 2, power 6 pi
    test::addQuad(mesh, {0, 0, 2}, {0, 1, 2}, {2, 1, 2}, {2, 0, 2}, 2);  // area 2, power 2 pi
    mesh.pointLights = {PointLight({0, 0, 5}, glm::vec3(0.5f))};    // power 2 pi
    const SceneLights lights(mesh);
    REQUIRE(lights.size() == 5);
    CHECK(lights.deltaLights() == 1);
    CHECK(lights.lightOnTriangle(0) == -1);
    CHECK(lights.lightOnTriangle(1) == -1);
    REQUIRE(lights.lightOnTriangle(2) >= 0);
    CHECK(lights.light(static_cast<uint32_t>(lights.lightOnTriangle(2))).power().x ==
          doctest::Approx(3.0f * kPi));
    CHECK(lights.lightsAtInfinity().empty());
    // Total mean power 10 pi: each bright triangle 3/10, each blue one 1/10, the point light 2/10.
    CHECK(lights.sampler().probability(static_cast<uint32_t>(lights.lightOnTriangle(2))) ==
          doctest::Approx(0.3f));
    CHECK(lights.sampler().probability(static_cast<uint32_t>(lights.lightOnTriangle(4))) ==
          doctest::Approx(0.1f));
    CHECK(lights.sampler().probability(4) == doctest::Approx(0.2f));
    CHECK(lights.light(4).isDelta());
}

TEST_CASE("scene lights: a scene without emitters gets the default sky, or none with --env none") {
    Material dark;
    dark.diffuse = glm::vec3(0.5f);
    MeshData mesh;
    mesh.materials = {dark};
    test::addQuad(mesh, {0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}, 0);
    const SceneLights lit(mesh);
    REQUIRE(lit.size() == 1);
    CHECK(lit.litByDefault());
    CHECK(lit.lightsAtInfinity() == std::vector<uint32_t>{0});
    CHECK(lit.maxRadianceAtInfinity() == 1.0f);
    // Radiance 1 through the bounding sphere of radius 5/2: pi r^2 4 pi.
    CHECK(lit.light(0).power().x == doctest::Approx(kPi * 6.25f * 4.0f * kPi));
    mesh.environment.kind = Environment::Kind::None;
    const SceneLights lights(mesh);
    CHECK(lights.size() == 0);
    CHECK(lights.sampler().empty());
    CHECK_FALSE(lights.litByDefault());
}

namespace {
// A unit square emitting Le = 2: power 2 pi, bounding radius 1/sqrt 2.
MeshData unitLampQuad() {
    Material lamp;
    lamp.emission = glm::vec3(2.0f);
    MeshData mesh;
    mesh.materials = {lamp};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
    return mesh;
}
}  // namespace

TEST_CASE("scene lights: an environment comes after the triangles' lights and is chosen by power") {
    MeshData mesh = unitLampQuad();
    mesh.environment.kind = Environment::Kind::Uniform;
    mesh.environment.radiance = glm::vec3(1.0f / kPi);                   // power pi (1/2) 4 pi / pi = 2 pi
    const SceneLights lights(mesh);
    REQUIRE(lights.size() == 3);
    CHECK(lights.lightsAtInfinity() == std::vector<uint32_t>{2});
    CHECK_FALSE(lights.litByDefault());
    CHECK(lights.sampler().probability(2) == doctest::Approx(0.5f));
}

TEST_CASE("scene lights: a new environment replaces the old one's light alone and re-weighs the choice") {
    MeshData mesh = unitLampQuad();
    SceneLights lights(mesh);  // no environment given: the lamp keeps the outside black
    REQUIRE(lights.size() == 2);
    const Light* triangleLight = &lights.light(0);
    CHECK(lights.lightsAtInfinity().empty());
    CHECK(lights.environment().kind == Environment::Kind::None);

    Environment sky;
    sky.kind = Environment::Kind::Uniform;
    sky.radiance = glm::vec3(3.0f / kPi);  // power pi (1/2) 4 pi (3 / pi) = 6 pi: 3/4 of the total
    lights.setEnvironment(sky);
    REQUIRE(lights.size() == 3);
    CHECK(&lights.light(0) == triangleLight);  // the triangles' lights are not rebuilt
    CHECK(lights.lightOnTriangle(0) == 0);
    CHECK(lights.lightsAtInfinity() == std::vector<uint32_t>{2});
    CHECK(lights.maxRadianceAtInfinity() == doctest::Approx(3.0f / kPi));
    CHECK(lights.sampler().probability(0) == doctest::Approx(0.125f));
    CHECK(lights.sampler().probability(2) == doctest::Approx(0.75f));
    CHECK(lights.environment().kind == Environment::Kind::Uniform);

    sky.kind = Environment::Kind::None;
    lights.setEnvironment(sky);
    CHECK(lights.size() == 2);
    CHECK(lights.lightsAtInfinity().empty());
    CHECK(lights.maxRadianceAtInfinity() == 0.0f);
    CHECK(lights.sampler().probability(0) == doctest::Approx(0.5f));
    CHECK(&lights.light(0) == triangleLight);
}
