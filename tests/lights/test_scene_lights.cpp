// A scene's lights (scene_lights.h): emitting triangles become area lights found by their
// triangle, point lights are added after them, and the choice among all of them is by power; and
// the default sky's rule for a scene given no environment.
#include <doctest/doctest.h>

#include <filesystem>
#include <memory>

#include "lights/scene_lights.h"
#include "scene/scene_loader.h"
#include "textures/texture.h"
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

namespace {
// A grey floor of side 10 under a lamp quad of side 1 emitting `radiance`, as `lamp` gives it.
MeshData floorUnderLamp(const Material& lamp) {
    Material floor;
    floor.diffuse = glm::vec3(0.5f);
    MeshData mesh;
    mesh.materials = {floor, lamp};
    test::addQuad(mesh, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, 0);
    test::addQuad(mesh, {0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1}, 1);  // faces down
    return mesh;
}

Material emitting(const glm::vec3& radiance) {
    Material m;
    m.emission = radiance;
    return m;
}
}  // namespace

TEST_CASE("scene lights: emitters no brighter than the sky leave the default sky on, brighter ones or many turn it off") {
    // A small emitter of radiance 1 (a glowing label): the sky lights the scene, and the note says why.
    const SceneLights label(floorUnderLamp(emitting(glm::vec3(1.0f))));
    CHECK(label.litByDefault());
    CHECK(label.lightsAtInfinity().size() == 1);
    CHECK(label.lightOnTriangle(2) >= 0);  // the label is a light still
    CHECK(defaultEnvironmentNote(label) ==
          "the scene's only lights are emitters no brighter than a white sky of radiance 1; lighting it "
          "with a uniform white environment (--env none for black)");
    // Brighter than the sky in one channel: a lamp, the outside stays dark.
    const SceneLights lamp(floorUnderLamp(emitting({0.2f, 1.01f, 0.2f})));
    CHECK_FALSE(lamp.litByDefault());
    CHECK(lamp.lightsAtInfinity().empty());
    CHECK(lamp.defaultSkyReason().empty());
    // A textured emitter by its brightest texel times its factor.
    Material textured = emitting(glm::vec3(1.0f));
    textured.textures.emission = std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.0f, 1.0f});
    CHECK(SceneLights(floorUnderLamp(textured)).litByDefault());
    textured.emission = glm::vec3(1.5f);
    CHECK_FALSE(SceneLights(floorUnderLamp(textured)).litByDefault());
    // A point light turns it off, however faint.
    MeshData pointLit = floorUnderLamp(emitting(glm::vec3(0.5f)));
    pointLit.pointLights = {PointLight({0, 1, 0}, glm::vec3(1e-3f))};
    CHECK_FALSE(SceneLights(pointLit).litByDefault());
    // Dim emitters that make up half of the scene's area are its light (a furnace of Le 1).
    Material dim = emitting(glm::vec3(0.5f));
    dim.diffuse = glm::vec3(0.5f);
    CHECK_FALSE(SceneLights(test::furnaceMesh(dim)).litByDefault());
    MeshData halfLit = floorUnderLamp(dim);
    test::addQuad(halfLit, {-5, 3, -5}, {5, 3, -5}, {5, 3, 5}, {-5, 3, 5}, 1);  // 101 of 201 emit
    CHECK_FALSE(SceneLights(halfLit).litByDefault());
    // An environment given stands either way.
    MeshData given = floorUnderLamp(emitting(glm::vec3(1.0f)));
    given.environment.kind = Environment::Kind::None;
    CHECK_FALSE(SceneLights(given).litByDefault());
}

TEST_CASE("scene lights: ClearCoatTest's glowing labels get the default sky, the Cornell boxes do not") {
    CHECK_FALSE(loadScene(test::sourceDir() / "assets" / "cornell" / "cornell.obj").scene.lights().litByDefault());
    for (const char* name : {"cornell", "cornell_small", "cornell_glossy"}) {
        const auto path = test::sharedDir() / "scenes" / name / "scene.obj";
        if (std::filesystem::is_regular_file(path)) CHECK_FALSE(loadScene(path).scene.lights().litByDefault());
    }
    const std::filesystem::path clearCoat = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
    if (!std::filesystem::is_regular_file(clearCoat)) {
        MESSAGE("skipped: " << clearCoat << " is absent (apt-get install assimp-testmodels)");
        return;
    }
    const LoadedScene loaded = loadScene(clearCoat);
    CHECK(loaded.scene.summary().emitters > 0);
    CHECK(loaded.scene.summary().maxEmission == 1.0f);  // the labels: factor 1 times white texels
    CHECK(loaded.scene.lights().litByDefault());
}
