// The light tree (light_tree.h) over a scene of many emitting triangles, a point light and a
// uniform sky: its probabilities sum to one at every point, choose() draws each light with the
// probability probability() gives and reports exactly that, no light that can reach a point is
// passed over, and next-event estimation by the tree gives the irradiance Lambert's formula does.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <vector>
#include <glm/geometric.hpp>

#include "lights/scene_lights.h"
#include "sampling/random.h"
#include "test_support.h"

using namespace strata;

namespace {

constexpr int kTriangles = 240;

struct Stream {
    uint64_t key;
    uint64_t count = 0;
    float next() { return uniformFloat(mixBits(key * 0x100000001b3ull + count++)); }
    glm::vec3 inBox(float half) { return {half * (2 * next() - 1), half * (2 * next() - 1), half * (2 * next() - 1)}; }
    glm::vec3 direction() {
        const float z = 2 * next() - 1;
        const float phi = 6.2831853f * next();
        const float r = std::sqrt(std::max(0.0f, 1 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
};

// Small triangles scattered through [-1,1]^3, turned every way, their radiance log-uniform over
// two orders of magnitude; a point light; a uniform sky (sampled power 0: never chosen).
struct ManyLights {
    std::vector<Material> materials;
    LightDescriptions descriptions;
    explicit ManyLights(uint64_t seed) {
        Stream random{seed};
        materials.resize(kTriangles);
        for (int i = 0; i < kTriangles; ++i) {
            materials[i].emission = glm::vec3(0.2f * std::pow(100.0f, random.next()));
            const glm::vec3 centre = random.inBox(1.0f);
            const std::array<glm::vec3, 3> corners{centre + 0.08f * random.direction(),
                                                   centre + 0.08f * random.direction(),
                                                   centre + 0.08f * random.direction()};
            descriptions.emitters.push_back({static_cast<uint32_t>(i), corners, &materials[i]});
        }
        descriptions.triangles = kTriangles;
        descriptions.surfaceArea = 1.0;
        descriptions.pointLights = {PointLight({0.3f, -0.2f, 0.5f}, glm::vec3(0.4f))};
        descriptions.environment.kind = Environment::Kind::Uniform;
        descriptions.environment.radiance = glm::vec3(0.5f);
        descriptions.sceneRadius = 2.0f;
    }
};

// Whether any point of the light's triangle can send light to `point` above the plane of
// `normal` (zero: any side): `point` in front of the triangle and a corner above that plane.
bool canReach(const std::array<glm::vec3, 3>& corners, const glm::vec3& point, const glm::vec3& normal) {
    const glm::vec3 facing = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
    if (!(glm::dot(facing, point - corners[0]) > 0.0f)) return false;
    if (normal == glm::vec3(0.0f)) return true;
    for (const glm::vec3& corner : corners) {
        if (glm::dot(corner - point, normal) > 0.0f) return true;
    }
    return false;
}

struct Receiver {
    glm::vec3 point;
    glm::vec3 normal;
};
// Points through and around the lights, one in four with a zero normal (a transmitting surface).
std::vector<Receiver> receivers(int count, uint64_t seed) {
    Stream random{seed};
    std::vector<Receiver> result;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 point = random.inBox(1.3f);
        result.push_back({point, i % 4 == 3 ? glm::vec3(0.0f) : random.direction()});
    }
    return result;
}

}  // namespace

TEST_CASE("light tree: the lights with extent are in it, the others keep their share by power") {
    const ManyLights scene(1);
    const SceneLights lights(scene.descriptions);
    REQUIRE(lights.size() == kTriangles + 2);
    const LightTree& tree = lights.tree();
    CHECK(tree.treeLights() == kTriangles);
    const uint32_t pointLight = kTriangles;
    const uint32_t sky = kTriangles + 1;
    for (const Receiver& r : receivers(20, 2)) {
        CHECK(tree.probability(pointLight, r.point, r.normal) == lights.sampler().probability(pointLight));
        CHECK(tree.probability(sky, r.point, r.normal) == 0.0f);
    }
    CHECK(lights.usesTree(LightSamplerKind::Auto));
    CHECK_FALSE(lights.usesTree(LightSamplerKind::Power));
}

TEST_CASE("light tree: at every point the probabilities sum to one, and no light that can reach it has 0") {
    const ManyLights scene(3);
    const SceneLights lights(scene.descriptions);
    for (const Receiver& r : receivers(200, 4)) {
        double sum = 0.0;
        int passedOver = 0;
        for (uint32_t light = 0; light < lights.size(); ++light) {
            const float p = lights.tree().probability(light, r.point, r.normal);
            CHECK(p >= 0.0f);
            sum += p;
            if (light < kTriangles && p == 0.0f &&
                canReach(scene.descriptions.emitters[light].corners, r.point, r.normal)) {
                ++passedOver;
            }
        }
        CHECK(sum == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(passedOver == 0);
    }
}

TEST_CASE("light tree: choose() draws each light as often as probability() says, and reports it exactly") {
    const ManyLights scene(5);
    const SceneLights lights(scene.descriptions);
    const LightTree& tree = lights.tree();
    constexpr int kSamples = 200000;
    int receiver = 0;
    for (const Receiver& r : receivers(4, 6)) {
        std::vector<int> counts(lights.size(), 0);
        int misreported = 0;
        for (int k = 0; k < kSamples; ++k) {
            const float u = uniformFloat(mixBits(static_cast<uint64_t>(receiver) * kSamples + k + 11));
            const LightChoice choice = tree.choose(u, r.point, r.normal);
            REQUIRE(choice.probability > 0.0f);
            if (choice.probability != tree.probability(choice.light, r.point, r.normal)) ++misreported;
            ++counts[choice.light];
        }
        CHECK(misreported == 0);
        // Chi-square over the lights expected at least 5 times; the rest pooled in one bin.
        double chi = 0.0;
        size_t bins = 0;
        double pooledExpected = 0.0;
        int pooledCount = 0;
        for (uint32_t light = 0; light < lights.size(); ++light) {
            const double expected = kSamples * static_cast<double>(tree.probability(light, r.point, r.normal));
            if (expected == 0.0) CHECK(counts[light] == 0);
            if (expected < 5.0) {
                pooledExpected += expected;
                pooledCount += counts[light];
                continue;
            }
            chi += (counts[light] - expected) * (counts[light] - expected) / expected;
            ++bins;
        }
        if (pooledExpected >= 5.0) {
            chi += (pooledCount - pooledExpected) * (pooledCount - pooledExpected) / pooledExpected;
            ++bins;
        }
        REQUIRE(bins > 20);
        INFO("receiver " << receiver << ": chi-square " << chi << " over " << bins << " bins");
        CHECK(chi < test::chiSquareCritical(bins - 1));
        ++receiver;
    }
}

TEST_CASE("light tree: next-event estimation of the irradiance from many triangles and a point light is exact") {
    // Triangles above the receiver plane z = 0 (normal +z) turned every way, some facing away
    // from the origin (they send nothing there); a point light above. The exact irradiance at the
    // origin: Lambert's formula per triangle that faces it, plus I cos / r^2.
    Stream random{21};
    std::vector<Material> materials(kTriangles);
    LightDescriptions descriptions;
    double exact = 0.0;
    for (int i = 0; i < kTriangles; ++i) {
        materials[i].emission = glm::vec3(0.2f * std::pow(100.0f, random.next()));
        glm::vec3 centre = random.inBox(2.0f);
        centre.z = 0.4f + std::abs(centre.z);
        std::array<glm::vec3, 3> corners{};
        for (glm::vec3& corner : corners) corner = centre + 0.15f * random.direction();
        descriptions.emitters.push_back({static_cast<uint32_t>(i), corners, &materials[i]});
        const glm::vec3 facing = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
        if (glm::dot(facing, -corners[0]) > 0.0f) {
            exact += materials[i].emission.x *
                     test::lambertIrradiance({0, 0, 0}, {corners[2], corners[1], corners[0]});
        }
    }
    const glm::vec3 lamp(0.5f, -0.4f, 1.2f);
    descriptions.pointLights = {PointLight(lamp, glm::vec3(0.3f))};
    exact += 0.3 * lamp.z / std::pow(glm::length(lamp), 3.0);
    descriptions.triangles = kTriangles;
    descriptions.surfaceArea = 1.0;
    const SceneLights lights(descriptions);
    const glm::vec3 origin(0.0f), up(0.0f, 0.0f, 1.0f);
    double variance[2];
    for (int byTree = 0; byTree < 2; ++byTree) {
        std::vector<double> values;
        for (uint64_t k = 0; k < 200000; ++k) {
            const uint64_t bits = mixBits(k + 99);
            const float u = uniformFloat(mixBits(bits));
            const LightChoice choice =
                byTree ? lights.tree().choose(u, origin, up) : lights.sampler().choose(u);
            double value = 0.0;
            if (choice.probability > 0.0f) {
                const Light& light = lights.light(choice.light);
                const auto s = light.sample(origin, {uniformFloat(bits), uniformFloat(bits << 24)});
                if (s && s->direction.z > 0.0f) {
                    const double density = light.isDelta() ? 1.0 : s->pdf;
                    value = s->radiance.x * s->direction.z / (choice.probability * density);
                }
            }
            values.push_back(value);
        }
        const auto estimate = test::estimateMean(values);
        INFO((byTree ? "tree" : "power") << ": " << estimate.mean << " +- " << estimate.standardError
                                         << ", exact " << exact);
        CHECK(std::abs(estimate.mean - exact) < 4.0 * estimate.standardError);
        variance[byTree] = estimate.standardError * estimate.standardError * values.size();
    }
    MESSAGE("irradiance per sample: variance by power " << variance[0] << ", by the tree " << variance[1]);
    // The tree sends the samples to the near triangles facing the origin.
    CHECK(variance[1] < 0.5 * variance[0]);
}
