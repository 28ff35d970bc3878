// A scene's lights (scene_lights.h), from the light descriptions a scene hands them: emitting
// triangles become area lights found by their triangle, point lights are added after them, and
// the choice among all of them is by the power their samples draw; and the default sky's rule for a scene given no
// environment.
#include <cmath>
#include <doctest/doctest.h>

#include <filesystem>
#include <memory>
#include <glm/geometric.hpp>

#include "lights/scene_lights.h"
#include "scene/scene_loader.h"
#include "textures/texture.h"
#include "util/constants.h"
#include "test_support.h"

using namespace strata;

namespace {
// The scene's next two triangles, the quad a b c d (counter-clockwise) split as (a b c) (a c d),
// emitting by `material` when it emits.
void addQuad(LightDescriptions& lights, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
             const glm::vec3& d, const Material& material) {
    const auto first = static_cast<uint32_t>(lights.triangles);
    lights.triangles += 2;
    lights.surfaceArea += 0.5 * (glm::length(glm::cross(b - a, c - a)) + glm::length(glm::cross(c - a, d - a)));
    if (!emitsLight(material)) return;
    lights.emitters.push_back({first, {a, b, c}, &material});
    lights.emitters.push_back({first + 1, {a, c, d}, &material});
}
}  // namespace

TEST_CASE("scene lights: emitting triangles and point lights, chosen by power") {
    LightDescriptions descriptions;
    Material dark;
    dark.diffuse = glm::vec3(0.5f);
    Material bright;
    bright.emission = glm::vec3(3.0f);
    Material blue;
    blue.emission = glm::vec3(0.0f, 0.0f, 3.0f);  // mean radiance 1
    addQuad(descriptions, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, dark);    // area 1, not emitting
    addQuad(descriptions, {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}, bright);  // area 2, power 6 pi
    addQuad(descriptions, {0, 0, 2}, {0, 1, 2}, {2, 1, 2}, {2, 0, 2}, blue);    // area 2, power 2 pi
    descriptions.pointLights = {PointLight({0, 0, 5}, glm::vec3(0.5f))};        // power 2 pi
    const SceneLights lights(descriptions);
    REQUIRE(lights.size() == 5);
    CHECK(lights.deltaLights() == 1);
    CHECK(lights.raysFindLight());  // the emitting triangles
    LightDescriptions pointOnly;
    pointOnly.pointLights = descriptions.pointLights;
    CHECK_FALSE(SceneLights(pointOnly).raysFindLight());  // no default sky beside a point light
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
    LightDescriptions descriptions;
    addQuad(descriptions, {0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}, dark);
    descriptions.sceneRadius = 2.5f;
    const SceneLights lit(descriptions);
    REQUIRE(lit.size() == 1);
    CHECK(lit.litByDefault());
    CHECK(lit.lightsAtInfinity() == std::vector<uint32_t>{0});
    CHECK(lit.maxRadianceAtInfinity() == 1.0f);
    // Radiance 1 through the bounding sphere of radius 5/2: pi r^2 4 pi.
    CHECK(lit.light(0).power().x == doctest::Approx(kPi * 6.25f * 4.0f * kPi));
    descriptions.environment.kind = Environment::Kind::None;
    const SceneLights lights(descriptions);
    CHECK(lights.size() == 0);
    CHECK(lights.sampler().empty());
    CHECK_FALSE(lights.litByDefault());
}

namespace {
// A unit square emitting Le = 2: power 2 pi, bounding radius 1/sqrt 2.
LightDescriptions unitLampQuad(const Material& lamp) {
    LightDescriptions descriptions;
    addQuad(descriptions, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, lamp);
    descriptions.sceneRadius = 0.5f * std::sqrt(2.0f);
    return descriptions;
}

Material lampOf(float radiance) {
    Material lamp;
    lamp.emission = glm::vec3(radiance);
    return lamp;
}
}  // namespace

// A sky of radiance `upper` over the upper hemisphere and black below: its mean is upper / 2, so
// its light samples the upper half, where the excess is upper / 2 (environment_map.h).
Environment twoLevelSky(float upper) {
    Image image{8, 4, std::vector<glm::vec3>(32, glm::vec3(0.0f))};
    for (int i = 0; i < 16; ++i) image.pixels[i] = glm::vec3(upper);
    Environment sky;
    sky.kind = Environment::Kind::Map;
    sky.map = std::make_shared<const EnvironmentMap>(std::move(image), "two-level");
    return sky;
}

TEST_CASE("scene lights: an environment comes after the triangles' lights and is chosen by the power it samples") {
    const Material lamp = lampOf(2.0f);
    LightDescriptions descriptions = unitLampQuad(lamp);
    // Sampled power pi r^2 * (upper / 2) * 2 pi = pi (1/2) (2 / pi) 2 pi = 2 pi, the lamp's.
    descriptions.environment = twoLevelSky(4.0f / kPi);
    const SceneLights lights(descriptions);
    REQUIRE(lights.size() == 3);
    CHECK(lights.lightsAtInfinity() == std::vector<uint32_t>{2});
    CHECK_FALSE(lights.litByDefault());
    CHECK(lights.sampler().probability(2) == doctest::Approx(0.5f));
    // A uniform sky gives its light samples nothing to draw: the lamp takes them all.
    descriptions.environment.kind = Environment::Kind::Uniform;
    descriptions.environment.radiance = glm::vec3(1.0f / kPi);
    const SceneLights uniform(descriptions);
    REQUIRE(uniform.size() == 3);
    CHECK(uniform.sampler().probability(2) == 0.0f);
    CHECK(uniform.sampler().probability(0) == doctest::Approx(0.5f));
    // Alone, it leaves next-event estimation nothing to sample.
    descriptions.emitters.clear();
    CHECK(SceneLights(descriptions).sampler().empty());
}

TEST_CASE("scene lights: a new environment replaces the old one's light alone and re-weighs the choice") {
    const Material lamp = lampOf(2.0f);
    SceneLights lights(unitLampQuad(lamp));  // no environment given: the lamp keeps the outside black
    REQUIRE(lights.size() == 2);
    const Light* triangleLight = &lights.light(0);
    CHECK(lights.lightsAtInfinity().empty());
    CHECK(lights.environment().kind == Environment::Kind::None);

    Environment sky = twoLevelSky(12.0f / kPi);  // sampled power pi (1/2) (6 / pi) 2 pi = 6 pi: 3/4
    lights.setEnvironment(sky);
    REQUIRE(lights.size() == 3);
    CHECK(&lights.light(0) == triangleLight);  // the triangles' lights are not rebuilt
    CHECK(lights.lightOnTriangle(0) == 0);
    CHECK(lights.lightsAtInfinity() == std::vector<uint32_t>{2});
    CHECK(lights.maxRadianceAtInfinity() == doctest::Approx(12.0f / kPi));
    CHECK(lights.sampler().probability(0) == doctest::Approx(0.125f));
    CHECK(lights.sampler().probability(2) == doctest::Approx(0.75f));
    CHECK(lights.environment().kind == Environment::Kind::Map);

    sky.kind = Environment::Kind::None;
    lights.setEnvironment(sky);
    CHECK(lights.size() == 2);
    CHECK(lights.lightsAtInfinity().empty());
    CHECK(lights.maxRadianceAtInfinity() == 0.0f);
    CHECK(lights.sampler().probability(0) == doctest::Approx(0.5f));
    CHECK(&lights.light(0) == triangleLight);
}

namespace {
// A grey floor of side 10 under a downward lamp quad of side 1 emitting by `lamp`.
LightDescriptions floorUnderLamp(const Material& lamp) {
    static const Material floor = [] {
        Material m;
        m.diffuse = glm::vec3(0.5f);
        return m;
    }();
    LightDescriptions descriptions;
    addQuad(descriptions, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, floor);
    addQuad(descriptions, {0, 2, 0}, {1, 2, 0}, {1, 2, 1}, {0, 2, 1}, lamp);  // faces down
    descriptions.sceneRadius = 0.5f * std::sqrt(204.0f);
    return descriptions;
}

Material emitting(const glm::vec3& radiance) {
    Material m;
    m.emission = radiance;
    return m;
}
}  // namespace

TEST_CASE("scene lights: emitters no brighter than the sky leave the default sky on, brighter ones or many turn it off") {
    // A small emitter of radiance 1 (a glowing label): the sky lights the scene, and the note says why.
    const Material labelMaterial = emitting(glm::vec3(1.0f));
    const SceneLights label(floorUnderLamp(labelMaterial));
    CHECK(label.litByDefault());
    CHECK(label.lightsAtInfinity().size() == 1);
    CHECK(label.lightOnTriangle(2) >= 0);  // the label is a light still
    CHECK(defaultEnvironmentNote(label) ==
          "the scene's only lights are emitters no brighter than a white sky of radiance 1; lighting it "
          "with a uniform white environment (--env none for black)");
    // Brighter than the sky in one channel: a lamp, the outside stays dark.
    const Material lampMaterial = emitting({0.2f, 1.01f, 0.2f});
    const SceneLights lamp(floorUnderLamp(lampMaterial));
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
    const Material dim = emitting(glm::vec3(0.5f));
    LightDescriptions pointLit = floorUnderLamp(dim);
    pointLit.pointLights = {PointLight({0, 1, 0}, glm::vec3(1e-3f))};
    CHECK_FALSE(SceneLights(pointLit).litByDefault());
    // Dim emitters that make up half of the scene's area are its light: a ceiling as large as
    // the floor (101 of 201 square units emit), or a furnace, all of it emitting.
    LightDescriptions halfLit = floorUnderLamp(dim);
    addQuad(halfLit, {-5, 3, -5}, {5, 3, -5}, {5, 3, 5}, {-5, 3, 5}, dim);
    CHECK_FALSE(SceneLights(halfLit).litByDefault());
    LightDescriptions lessThanHalf = floorUnderLamp(dim);
    addQuad(lessThanHalf, {-5, 3, -5}, {4.8f, 3, -5}, {4.8f, 3, 5}, {-5, 3, 5}, dim);  // 99 of 199
    CHECK(SceneLights(lessThanHalf).litByDefault());
    // An environment given stands either way.
    LightDescriptions given = floorUnderLamp(labelMaterial);
    given.environment.kind = Environment::Kind::None;
    CHECK_FALSE(SceneLights(given).litByDefault());
}

TEST_CASE("scene lights: ClearCoatTest's glowing labels get the default sky, the Cornell boxes do not") {
    CHECK_FALSE(loadScene(test::cornellScene()).scene.lights().litByDefault());
    if (const auto shared = test::sharedDir()) {
        for (const char* name : {"cornell", "cornell_small", "cornell_glossy"}) {
            const auto path = *shared / "scenes" / name / "scene.obj";
            if (std::filesystem::is_regular_file(path)) CHECK_FALSE(loadScene(path).scene.lights().litByDefault());
        }
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

TEST_CASE("scene lights: every light choice's name is listed and parses back to it") {
    const std::string names = lightSamplerNames();
    CHECK(names == "auto|power|tree");
    for (LightSamplerKind kind : kLightSamplerKinds) {
        const std::string_view name = lightSamplerName(kind);
        CHECK(names.find(name) != std::string::npos);
        CHECK(parseLightSamplerKind(name) == kind);
    }
    CHECK_FALSE(parseLightSamplerKind("bvh").has_value());
}
