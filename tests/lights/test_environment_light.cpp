// The environment lights (uniform_environment_light.h, environment_map_light.h): sample() gives
// the density pdf() reports (a chi-square over the map's texels, with expected counts integrated
// from pdf() itself, and E[1/pdf] = the solid angle it covers), MIS-compensated (environment_map.h:
// only what rises above the mean is sampled, a uniform sky not at all), the radiance emitted()
// reports, the documented direction convention and rotation, and the power pi r^2 * integral of L
// over the sphere; and readEnvironmentMap's checks.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "io/image_io.h"
#include "lights/environment.h"
#include "lights/environment_map_light.h"
#include "lights/uniform_environment_light.h"
#include "util/constants.h"
#include "util/error.h"
#include "util/luminance.h"
#include "test_support.h"

using namespace strata;

namespace {

constexpr LightHit kMiss{glm::vec3(0.0f)};

// The world direction of the map's angles (theta from +y, phi from -z toward +x), the map turned
// by `degrees` about +y (right-handed), as environment_map_light.h documents it.
glm::dvec3 worldDirection(double theta, double phi, double degrees) {
    const glm::dvec3 local(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
    const double a = degrees * M_PI / 180.0;
    return {std::cos(a) * local.x + std::sin(a) * local.z, local.y,
            -std::sin(a) * local.x + std::cos(a) * local.z};
}

// A 16 x 8 map whose red channel names the texel (1 + its index), with a bright spot.
constexpr int kWidth = 16, kHeight = 8;
Image labelledMap() {
    Image map{kWidth, kHeight, std::vector<glm::vec3>(kWidth * kHeight)};
    for (int i = 0; i < kWidth * kHeight; ++i) map.pixels[i] = glm::vec3(1.0f + i, 0.5f, 0.25f);
    map.pixels[2 * kWidth + 11].y = 500.0f;
    return map;
}
int texelIndex(const glm::vec3& radiance) { return static_cast<int>(radiance.x) - 1; }

}  // namespace

TEST_CASE("uniform environment: never sampled (nothing above its mean), power pi r^2 4 pi L") {
    const UniformEnvironmentLight light(glm::vec3(1.0f, 2.0f, 3.0f), 2.0f);
    for (uint64_t k = 0; k < 16; ++k) CHECK_FALSE(light.sample(glm::vec3(0.0f), test::hashedPoint(k + 0xe27)).has_value());
    CHECK(light.pdf({}, {0, 1, 0}, kMiss) == 0.0f);
    CHECK(light.emitted({0, -1, 0}, kMiss) == glm::vec3(1.0f, 2.0f, 3.0f));
    CHECK(light.power().z == doctest::Approx(kPi * 4.0f * 4.0f * kPi * 3.0f));
    CHECK(light.sampledPower() == glm::vec3(0.0f));
    CHECK_FALSE(light.isDelta());
}

TEST_CASE("environment map: sample() has the density pdf() gives and the radiance emitted() gives") {
    const double rotation = 30.0;
    const auto map = std::make_shared<const EnvironmentMap>(labelledMap(), "labelled");
    const EnvironmentMapLight light(map, rotation, 1.0f);
    // Expected counts: pdf() integrated over each texel by the midpoint rule in (theta, phi),
    // d(omega) = sin(theta) d(theta) d(phi).
    constexpr int kSub = 8;
    constexpr int kSamples = 200000;
    std::vector<double> expected(kWidth * kHeight, 0.0);
    double total = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            for (int i = 0; i < kSub; ++i) {
                for (int j = 0; j < kSub; ++j) {
                    const double theta = M_PI * (y + (i + 0.5) / kSub) / kHeight;
                    const double phi = 2.0 * M_PI * ((x + (j + 0.5) / kSub) / kWidth - 0.5);
                    const glm::vec3 d(worldDirection(theta, phi, rotation));
                    // The midpoints name the texel through emitted(): the convention holds.
                    REQUIRE(texelIndex(light.emitted(d, kMiss)) == y * kWidth + x);
                    const double cell = (M_PI / (kHeight * kSub)) * (2.0 * M_PI / (kWidth * kSub));
                    expected[y * kWidth + x] += light.pdf({}, d, kMiss) * std::sin(theta) * cell;
                }
            }
            total += expected[y * kWidth + x];
        }
    }
    CHECK(total == doctest::Approx(1.0).epsilon(1e-4));
    // Compensation: the texels at or below the mean luminance have no density, those above it
    // density in proportion to their excess (texel 43 is the bright spot).
    const double mean = luminance(map->sphereIntegral()) / (4.0 * M_PI);
    double sampledSolidAngle = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const double excess = luminance(glm::dvec3(map->image().pixels[y * kWidth + x])) - mean;
            CAPTURE(y * kWidth + x);
            if (excess > 0.0) {
                sampledSolidAngle += 2.0 * M_PI / kWidth *
                                     (std::cos(M_PI * y / kHeight) - std::cos(M_PI * (y + 1) / kHeight));
            }
            CHECK((expected[y * kWidth + x] > 0.0) == (excess > 0.0));
        }
    }
    CHECK(expected[43] > 0.0);
    CHECK(expected[42] == 0.0);
    // Texels with excesses 1 and 2 (red 1 apart is 0.2126 apart in luminance) in one row.
    const int first = kWidth * kHeight - 2;
    const double excess0 = luminance(glm::dvec3(map->image().pixels[first])) - mean;
    CHECK(expected[first + 1] / expected[first] == doctest::Approx((excess0 + 0.2126) / excess0).epsilon(1e-3));

    std::vector<double> counts(kWidth * kHeight, 0.0);
    double inverseDensity = 0.0;
    int pdfMismatches = 0;
    for (int k = 0; k < kSamples; ++k) {
        const auto s = light.sample(glm::vec3(0.0f), test::hashedPoint(k + 0xe27));
        REQUIRE(s);
        REQUIRE(glm::length(s->direction) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(std::isinf(s->distance));
        CHECK(s->radiance == light.emitted(s->direction, kMiss));
        const float pdf = light.pdf({}, s->direction, kMiss);
        if (std::abs(pdf - s->pdf) > 1e-4f * s->pdf) ++pdfMismatches;
        counts[texelIndex(s->radiance)] += 1.0;
        inverseDensity += 1.0 / s->pdf;
    }
    CHECK(pdfMismatches == 0);
    double chiSquare = 0.0;
    size_t sampledTexels = 0;
    for (size_t i = 0; i < counts.size(); ++i) {
        const double e = kSamples * expected[i];
        if (e == 0.0) {
            CHECK(counts[i] == 0.0);
            continue;
        }
        chiSquare += (counts[i] - e) * (counts[i] - e) / e;
        ++sampledTexels;
    }
    CHECK(chiSquare < test::chiSquareCritical(sampledTexels - 1));
    // E[1/pdf] is the solid angle of the texels with density (to the accuracy of the samples'
    // spread: 1/pdf varies about 10^3-fold here, hence the loose bound).
    CHECK(inverseDensity / kSamples == doctest::Approx(sampledSolidAngle).epsilon(0.05));
    CHECK(counts[43] > 0.0);
}

TEST_CASE("environment map: MIS compensation samples a two-level sky's bright half uniformly, a flat one not at all") {
    // Radiance 3 over the upper hemisphere, 1 below: the mean is 2, so the light samples the upper
    // half alone (with the excess 1 everywhere on it: uniformly over the map's rows of texels,
    // weighed by their sin(theta)) and draws pi r^2 * 1 * 2 pi of power.
    Image twoLevel{16, 8, std::vector<glm::vec3>(128, glm::vec3(1.0f))};
    for (int i = 0; i < 64; ++i) twoLevel.pixels[i] = glm::vec3(3.0f);
    const EnvironmentMapLight sky(std::make_shared<const EnvironmentMap>(twoLevel, "two-level"), 0.0f, 2.0f);
    CHECK(sky.sampledPower().x == doctest::Approx(M_PI * 4.0 * 2.0 * M_PI).epsilon(1e-4));
    CHECK(sky.power().x == doctest::Approx(M_PI * 4.0 * (3.0 + 1.0) * 2.0 * M_PI).epsilon(1e-4));
    // E[1/pdf] is the upper hemisphere's solid angle, 2 pi, and E[cos / pdf] its projected one, pi.
    constexpr int kSamples = 20000;
    std::vector<double> inverse, projected;
    for (uint64_t k = 0; k < kSamples; ++k) {
        const auto s = sky.sample(glm::vec3(0.0f), test::hashedPoint(k + 0xe27));
        REQUIRE(s);
        REQUIRE(s->direction.y > 0.0f);
        CHECK(s->radiance == glm::vec3(3.0f));
        CHECK(sky.pdf({}, s->direction, kMiss) == doctest::Approx(s->pdf).epsilon(1e-3));
        inverse.push_back(1.0 / s->pdf);
        projected.push_back(s->direction.y / s->pdf);
    }
    const auto solidAngle = test::estimateMean(inverse);
    const auto projectedSolidAngle = test::estimateMean(projected);
    CHECK(std::abs(solidAngle.mean - 2.0 * M_PI) < 4.0 * solidAngle.standardError);
    CHECK(std::abs(projectedSolidAngle.mean - M_PI) < 4.0 * projectedSolidAngle.standardError);
    CHECK(sky.pdf({}, glm::normalize(glm::vec3(0.3f, -0.5f, 0.1f)), kMiss) == 0.0f);

    const Image uniform{8, 4, std::vector<glm::vec3>(32, glm::vec3(2.0f))};
    const auto flatMap = std::make_shared<const EnvironmentMap>(uniform, "flat");
    CHECK_FALSE(flatMap->sampled());
    const EnvironmentMapLight flat(flatMap, 0.0f, 3.0f);
    CHECK_FALSE(flat.sample(glm::vec3(0.0f), test::hashedPoint(1 + 0xe27)).has_value());
    CHECK(flat.pdf({}, {0, 1, 0}, kMiss) == 0.0f);
    CHECK(flat.sampledPower() == glm::vec3(0.0f));
}

TEST_CASE("environment map: image centre along -z, top row up, rotation right-handed about +y") {
    Image map{4, 2, std::vector<glm::vec3>(8, glm::vec3(0.0f))};
    map.pixels[2] = glm::vec3(7.0f);      // top row, just right of the centre: up, toward -z/+x
    map.pixels[4 + 1] = glm::vec3(3.0f);  // bottom row, left of the centre: down, toward -z/-x
    const auto shared = std::make_shared<const EnvironmentMap>(map, "map");
    const EnvironmentMapLight unturned(shared, 0.0f, 1.0f);
    CHECK(unturned.emitted(glm::normalize(glm::vec3(0.1f, 0.5f, -1.0f)), kMiss).x == 7.0f);
    CHECK(unturned.emitted(glm::normalize(glm::vec3(-0.1f, -0.5f, -1.0f)), kMiss).x == 3.0f);
    CHECK(unturned.emitted(glm::normalize(glm::vec3(0.1f, 0.5f, 1.0f)), kMiss).x == 0.0f);
    // Turned by 90 degrees counter-clockwise seen from above, the centre moves from -z to -x.
    const EnvironmentMapLight turned(shared, 90.0f, 1.0f);
    CHECK(turned.emitted(glm::normalize(glm::vec3(-1.0f, 0.5f, -0.1f)), kMiss).x == 7.0f);
    CHECK(turned.emitted(glm::normalize(glm::vec3(-1.0f, -0.5f, 0.1f)), kMiss).x == 3.0f);
}

TEST_CASE("environment map: a turned map samples the unturned map's directions, turned, at their densities") {
    // One distribution, in the map's frame, serves every rotation: a sample of the turned light
    // is the unturned light's sample for the same u turned about +y, with the same radiance and
    // density, and pdf() agrees with it.
    const auto map = std::make_shared<const EnvironmentMap>(labelledMap(), "labelled");
    CHECK(map->maxRadiance() == 500.0f);
    const EnvironmentMapLight unturned(map, 0.0f, 1.0f);
    const EnvironmentMapLight turned(map, 35.0f, 1.0f);
    const double a = 35.0 * M_PI / 180.0;
    for (uint64_t k = 0; k < 200; ++k) {
        const auto u = test::hashedPoint(k + 0xe27);
        const auto s0 = unturned.sample(glm::vec3(0.0f), u);
        const auto s1 = turned.sample(glm::vec3(0.0f), u);
        REQUIRE(s0.has_value());
        REQUIRE(s1.has_value());
        const glm::dvec3 d(s0->direction);
        const glm::dvec3 expected(std::cos(a) * d.x + std::sin(a) * d.z, d.y, -std::sin(a) * d.x + std::cos(a) * d.z);
        CHECK(glm::length(glm::dvec3(s1->direction) - expected) < 1e-5);
        CHECK(s1->radiance == s0->radiance);
        CHECK(s1->pdf == doctest::Approx(s0->pdf).epsilon(1e-5));
        CHECK(turned.pdf(glm::vec3(0.0f), s1->direction, kMiss) == doctest::Approx(s1->pdf).epsilon(1e-3));
    }
}

TEST_CASE("environment map: power is pi r^2 times the radiance integrated over the sphere") {
    const Image map = labelledMap();
    const EnvironmentMapLight light(std::make_shared<const EnvironmentMap>(map, "map"), 0.0f, 3.0f);
    glm::dvec3 integral(0.0);
    for (int y = 0; y < kHeight; ++y) {
        // The texel rows' exact solid angles.
        const double solidAngle = 2.0 * M_PI / kWidth *
                                  (std::cos(M_PI * y / kHeight) - std::cos(M_PI * (y + 1) / kHeight));
        for (int x = 0; x < kWidth; ++x) integral += solidAngle * glm::dvec3(map.pixels[y * kWidth + x]);
    }
    CHECK(light.power().x == doctest::Approx(M_PI * 9.0 * integral.x).epsilon(1e-5));
    CHECK(light.power().y == doctest::Approx(M_PI * 9.0 * integral.y).epsilon(1e-5));
    // A uniform map has the uniform light's power.
    const Image uniform{8, 4, std::vector<glm::vec3>(32, glm::vec3(2.0f))};
    const EnvironmentMapLight flat(std::make_shared<const EnvironmentMap>(uniform, "flat"), 0.0f, 3.0f);
    CHECK(flat.power().x == doctest::Approx(UniformEnvironmentLight(glm::vec3(2.0f), 3.0f).power().x).epsilon(1e-5));
}

TEST_CASE("environment: the default rule, and readEnvironmentMap refuses what is not a radiance map") {
    Environment given;
    CHECK(resolveEnvironment(given, false).kind == Environment::Kind::Uniform);
    CHECK(resolveEnvironment(given, false).radiance == glm::vec3(1.0f));
    CHECK(resolveEnvironment(given, true).kind == Environment::Kind::None);
    given.kind = Environment::Kind::Uniform;
    given.radiance = glm::vec3(0.0f);
    CHECK(resolveEnvironment(given, false).kind == Environment::Kind::None);
    given.radiance = glm::vec3(0.5f, 4.0f, 1.0f);
    CHECK(maxRadiance(resolveEnvironment(given, true)) == 4.0f);

    const auto dir = test::scratchDir("environment-maps");
    writeImage(dir / "good.exr", labelledMap());
    const EnvironmentMapFile good = readEnvironmentMap(dir / "good.exr");
    CHECK(good.map->image().pixels == labelledMap().pixels);
    CHECK(good.zeroedNegatives == 0);
    // From a bundle's bytes, borrowed or taken (then freed once decoded): the same map.
    std::string bytes = readExrFile(dir / "good.exr");
    const EnvironmentMapFile borrowed = readEnvironmentMap(std::string_view(bytes), "good.exr");
    CHECK(!bytes.empty());
    const EnvironmentMapFile taken = readEnvironmentMap(std::move(bytes), "good.exr");
    CHECK(bytes.empty());  // taken, and freed once decoded
    for (const EnvironmentMapFile* file : {&borrowed, &taken}) {
        CHECK(file->map->image().pixels == labelledMap().pixels);
        CHECK(file->bytes == good.bytes);
        CHECK(file->map->sampledIntegral() == good.map->sampledIntegral());
        CHECK(file->map->distribution().pdf(glm::vec2(0.3f, 0.6f)) == good.map->distribution().pdf(glm::vec2(0.3f, 0.6f)));
    }
    // Lossy-compression ringing (texels a little below 0) reads as 0: the mean radiance is about
    // 22 here, so -1 is within 5% of it.
    Image ringing = labelledMap();
    ringing.pixels[7].y = -1.0f;
    writeImage(dir / "ringing.exr", ringing);
    const EnvironmentMapFile zeroed = readEnvironmentMap(dir / "ringing.exr");
    CHECK(zeroed.zeroedNegatives == 1);
    CHECK(zeroed.map->image().pixels[7].y == 0.0f);
    writeImage(dir / "square.exr", Image{4, 4, std::vector<glm::vec3>(16, glm::vec3(1.0f))});
    Image negative = labelledMap();
    negative.pixels[kWidth + 3].z = -2.0f;
    writeImage(dir / "negative.exr", negative);
    Image infinite = labelledMap();
    infinite.pixels[5].x = INFINITY;
    writeImage(dir / "infinite.exr", infinite);
    const struct {
        const char* file;
        const char* expected;
    } cases[] = {{"square.exr", "square.exr: an environment map must be a latitude-longitude image twice as wide as high, got 4x4"},
                 {"negative.exr", "negative.exr: texel (3, 1) is negative beyond lossy-compression noise"},
                 {"infinite.exr", "infinite.exr: texel (5, 0) is not finite"},
                 {"absent.exr", "absent.exr: no such EXR file"}};
    for (const auto& c : cases) {
        CAPTURE(c.file);
        std::string message = "no error";
        try {
            readEnvironmentMap(dir / c.file);
        } catch (const Error& e) {
            message = e.what();
        }
        CHECK(message.find(c.expected) != std::string::npos);
    }
}
