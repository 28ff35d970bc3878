// An emitting triangle as a light (area_light.h): uniform by area or by solid angle, one-sided,
// its solid-angle density consistent between sample() and pdf() in both regimes and where they
// switch, the irradiance it gives equal to Lambert's formula, and the power pi Le A.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include <glm/geometric.hpp>

#include "lights/area_light.h"
#include "sampling/spherical_triangle.h"
#include "test_support.h"
#include "util/constants.h"

using namespace strata;

namespace {
constexpr double kAreaOnly = std::numeric_limits<double>::infinity();
constexpr double kSolidAngleOnly = 0.0;

// A right triangle of area 2 in the plane z = 1, counter-clockwise seen from below: it faces -z.
AreaLight downwardLight(double minSphericalSolidAngle = AreaLight::kMinSphericalSolidAngle) {
    return AreaLight({0, 0, 1}, {0, 2, 1}, {2, 0, 1}, glm::vec3(1.0f, 2.0f, 3.0f), minSphericalSolidAngle);
}

}  // namespace

TEST_CASE("area light: points uniform by area, density d^2 / (A cos) and the same from pdf()") {
    const AreaLight light = downwardLight(kAreaOnly);
    CHECK(light.area() == doctest::Approx(2.0f));
    const glm::vec3 receiver(0.3f, 0.4f, 0.0f);
    constexpr int kSamples = 40000;
    double sumX = 0.0;
    double inverseDensity = 0.0;  // estimates the solid angle the triangle subtends
    for (int k = 0; k < kSamples; ++k) {
        const auto s = light.sample(receiver, test::hashedPoint(k));
        REQUIRE(s);
        const glm::vec3 point = receiver + s->distance * s->direction;
        CHECK(point.z == doctest::Approx(1.0f));
        CHECK(s->onSurface);
        CHECK(s->radiance.z == 3.0f);
        sumX += point.x;
        const float cosLight = s->direction.z;  // the light faces -z
        CHECK(s->pdf == doctest::Approx(s->distance * s->distance / (2.0f * cosLight)).epsilon(1e-5));
        const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f)};
        CHECK(light.pdf(receiver, s->direction, hit) == doctest::Approx(s->pdf).epsilon(1e-5));
        inverseDensity += 1.0 / s->pdf;
    }
    // The triangle's centroid has x = 2/3; x of a uniform point has variance 2/9 here.
    CHECK(std::abs(sumX / kSamples - 2.0 / 3.0) < 4.5 * std::sqrt(2.0 / 9.0 / kSamples));
    // E[1/pdf] is the subtended solid angle: compare with a fine midpoint quadrature over the
    // triangle of cos / d^2.
    double solidAngle = 0.0;
    constexpr int kGrid = 400;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            const double x = 2.0 * (i + 0.5) / kGrid, y = 2.0 * (j + 0.5) / kGrid;
            if (x + y > 2.0) continue;
            const glm::dvec3 d(x - 0.3, y - 0.4, 1.0);
            const double r2 = glm::dot(d, d);
            solidAngle += (1.0 / std::sqrt(r2)) / r2 * (4.0 / (kGrid * kGrid));
        }
    }
    CHECK(inverseDensity / kSamples == doctest::Approx(solidAngle).epsilon(0.01));
}

TEST_CASE("area light: emits from its front only, and its power is pi Le A") {
    const AreaLight light = downwardLight();
    const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f)};
    CHECK(light.emitted({0, 0, 1}, hit).y == 2.0f);  // a ray going up meets the front
    CHECK(light.emitted({0, 0, -1}, hit).y == 0.0f);
    CHECK(light.pdf({0, 0, 2}, {0, 0, -1}, hit) == 0.0f);
    CHECK_FALSE(light.sample({0.5f, 0.5f, 2.0f}, {0.5f, 0.5f}));  // above it sees its back
    CHECK(light.power().x == doctest::Approx(kPi * 2.0f));
    CHECK_FALSE(light.isDelta());
}

TEST_CASE("area light: by solid angle, density 1 / Omega from sample() and pdf(), points on the light") {
    const AreaLight light = downwardLight(kSolidAngleOnly);
    const glm::vec3 receiver(0.3f, 0.4f, 0.0f);
    const double solidAngle = sphericalTriangleSolidAngle(receiver, {0, 0, 1}, {0, 2, 1}, {2, 0, 1});
    CHECK(light.sphericalSolidAngle(receiver) == solidAngle);
    for (uint64_t k = 0; k < 4000; ++k) {
        const auto s = light.sample(receiver, test::hashedPoint(k));
        REQUIRE(s);
        const glm::vec3 point = receiver + s->distance * s->direction;
        CHECK(point.z == doctest::Approx(1.0f).epsilon(1e-6));
        CHECK(point.x >= -1e-5f);
        CHECK(point.y >= -1e-5f);
        CHECK(point.x + point.y <= 2.0f + 1e-5f);
        CHECK(s->onSurface);
        CHECK(s->radiance.y == 2.0f);
        CHECK(s->pdf == static_cast<float>(1.0 / solidAngle));
        const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f)};
        CHECK(light.pdf(receiver, s->direction, hit) == s->pdf);
    }
    // From behind, nothing: no sample, density 0, and a ray hitting its back has density 0.
    const glm::vec3 behind(0.3f, 0.4f, 2.0f);
    CHECK(light.sphericalSolidAngle(behind) == 0.0);
    CHECK_FALSE(light.sample(behind, {0.3f, 0.6f}));
    CHECK(light.pdf(behind, {0, 0, -1}, LightHit{glm::vec3(0, 0, -1)}) == 0.0f);
    CHECK(light.pdf(receiver, {0, 0, -1}, LightHit{glm::vec3(0, 0, -1)}) == 0.0f);
}

TEST_CASE("area light: the regime depends on the point only, and sample() and pdf() agree across it") {
    // Walking away from the light, the solid angle falls through the threshold: on each side the
    // sample's density is the one pdf() gives for its direction.
    constexpr double kThreshold = 0.05;
    const AreaLight light = downwardLight(kThreshold);
    int spherical = 0, byArea = 0;
    for (int step = 0; step < 40; ++step) {
        const glm::vec3 receiver(0.6f, 0.6f, 1.0f - 0.25f * static_cast<float>(step + 1));
        const double solidAngle = sphericalTriangleSolidAngle(receiver, {0, 0, 1}, {0, 2, 1}, {2, 0, 1});
        const bool bySolidAngle = solidAngle >= kThreshold;
        CHECK(light.sphericalSolidAngle(receiver) == (bySolidAngle ? solidAngle : 0.0));
        (bySolidAngle ? spherical : byArea) += 1;
        for (uint64_t k = 0; k < 200; ++k) {
            const auto s = light.sample(receiver, test::hashedPoint(k + 1000 * step));
            REQUIRE(s);
            const LightHit hit{glm::vec3(0.0f, 0.0f, -1.0f)};
            CHECK(light.pdf(receiver, s->direction, hit) == doctest::Approx(s->pdf).epsilon(1e-5));
            if (bySolidAngle) CHECK(s->pdf == static_cast<float>(1.0 / solidAngle));
        }
    }
    CHECK(spherical > 3);
    CHECK(byArea > 3);
}

TEST_CASE("area light: irradiance of a large close triangle is Lambert's, by area and by solid angle") {
    // A triangle 0.3 above the receiver, subtending about 3.6 sr. Estimates of E = int Le cos dw
    // by the light's own samples; the exact value by Lambert's formula (checked first against the
    // notes' tabulated 2 x 2 square at height 1).
    CHECK(test::lambertIrradiance({0, 0, 0}, {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}) ==
          doctest::Approx(1.740839502734).epsilon(1e-12));
    const glm::dvec3 p0(-1, -1, 0.3), p1(1.5, -1, 0.3), p2(-1, 1.5, 0.3);
    const double exact = test::lambertIrradiance({0, 0, 0}, {p0, p1, p2});
    // Counter-clockwise seen from below: faces the receiver.
    const glm::vec3 radiance(1.0f);
    double variance[2];
    for (int useSolidAngle = 0; useSolidAngle < 2; ++useSolidAngle) {
        const AreaLight light(p0, p2, p1, radiance, useSolidAngle ? kSolidAngleOnly : kAreaOnly);
        CHECK((light.sphericalSolidAngle({0, 0, 0}) > 3.0) == (useSolidAngle == 1));
        std::vector<double> values;
        for (uint64_t k = 0; k < 200000; ++k) {
            const auto s = light.sample({0, 0, 0}, test::hashedPoint(k + 77));
            values.push_back(s ? s->radiance.x * std::max(0.0f, s->direction.z) / s->pdf : 0.0);
        }
        const auto estimate = test::estimateMean(values);
        INFO((useSolidAngle ? "solid angle" : "area") << ": " << estimate.mean << " +- "
                                                       << estimate.standardError << ", exact " << exact);
        CHECK(std::abs(estimate.mean - exact) < 4.0 * estimate.standardError);
        variance[useSolidAngle] = estimate.standardError * estimate.standardError * values.size();
    }
    MESSAGE("irradiance per sample: variance by area " << variance[0] << ", by solid angle " << variance[1]);
    // Area sampling's 1/d^2 and cos_light weigh the rim's grazing directions; solid angle sampling
    // leaves only the receiver's cosine to vary.
    CHECK(variance[1] < 0.5 * variance[0]);
}
