// The sheen layer (sheen.h): the Charlie distribution is normalised, the tabulated directional
// albedo is the lobe's integral, and the material table puts the sheen where glTF's layering
// does (between the base and the coat). The bsdf contract tests (test_bsdf.cpp) check the layered
// models' sampling, reciprocity and energy.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "materials/bsdf.h"
#include "materials/material_table.h"
#include "materials/sheen.h"
#include "sampling/hemisphere.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("sheen: the Charlie distribution is normalised, from roughness 0 to 1") {
    for (float roughness : {0.0f, 0.1f, 0.5f, 1.0f}) {
        const SheenLobe lobe(sheenAlphaFromRoughness(roughness));
        // 2 pi * integral of D(theta) cos sin dtheta over [0, pi/2], midpoint rule.
        constexpr int kSteps = 200000;
        double sum = 0.0;
        for (int i = 0; i < kSteps; ++i) {
            const double theta = (i + 0.5) / kSteps * M_PI / 2.0;
            const glm::vec3 h(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta)));
            sum += lobe.density(h) * std::cos(theta) * std::sin(theta);
        }
        CAPTURE(roughness);
        CHECK(sum * 2.0 * M_PI * (M_PI / 2.0) / kSteps == doctest::Approx(1.0).epsilon(1e-3));
    }
}

TEST_CASE("sheen: the albedo table is the lobe's integral (Monte Carlo, k standard errors)") {
    for (float roughness : {0.3f, 0.7f, 1.0f}) {
        const SheenLobe lobe(sheenAlphaFromRoughness(roughness));
        for (int entry : {1, 10, 22, 31}) {  // table nodes: no interpolation between them
            const float mu = static_cast<float>(entry) / 31.0f;
            const glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            constexpr int kSamples = 400000;
            double sum = 0.0;
            double squares = 0.0;
            for (int i = 0; i < kSamples; ++i) {
                const glm::vec3 wi = sampleUniformHemisphere(test::hashedPoint(static_cast<uint64_t>(i) * 7919u + entry));
                const double value = lobe.reflectance(wo, wi) * wi.z * kHemisphereSolidAngle;
                sum += value;
                squares += value * value;
            }
            const double mean = sum / kSamples;
            const double standardError = std::sqrt((squares / kSamples - mean * mean) / kSamples);
            CAPTURE(roughness);
            CAPTURE(mu);
            CHECK(std::abs(lobe.albedo(mu) - mean) <= test::kSigmas * standardError);
            CHECK(lobe.albedo(mu) < 1.0f);
        }
    }
}

TEST_CASE("sheen: the material table layers it over the layered model and under the coat, nowhere else") {
    Material velvet;
    velvet.diffuse = glm::vec3(0.2f, 0.05f, 0.1f);
    velvet.sheenColour = glm::vec3(1.0f, 0.6f, 0.8f);
    velvet.sheenRoughness = 0.4f;
    Material coated = velvet;
    coated.clearcoat = 1.0f;
    coated.clearcoatRoughness = 0.2f;
    Material plain = velvet;
    plain.sheenColour = glm::vec3(0.0f);
    Material glass = velvet;
    glass.transmission = 1.0f;
    Material blackVelvet;
    blackVelvet.sheenColour = glm::vec3(0.5f);
    blackVelvet.sheenRoughness = 0.5f;
    const MaterialTable table({velvet, coated, plain, glass, blackVelvet});
    CHECK(table.bsdf(0).as<Sheened>() != nullptr);
    CHECK(table.bsdf(1).as<Coated<Sheened>>() != nullptr);
    CHECK(table.bsdf(2).as<LayeredBsdf>() != nullptr);
    CHECK(table.bsdf(3).as<Sheened>() == nullptr);
    // A black base under a sheen is not black: the fibres reflect.
    CHECK_FALSE(table.isBlack(4));
    CHECK(table.bsdf(4).as<Sheened>() != nullptr);
    // The fibres reflect most at grazing angles: back toward a grazing viewer far more than at
    // normal incidence.
    const Bsdf bsdf = table.bsdf(4);
    const glm::vec3 grazing(0.985f, 0.0f, 0.1723f);
    CHECK(bsdf.evaluate(grazing, grazing).x > 10.0f * bsdf.evaluate({0, 0, 1}, {0, 0, 1}).x);
}
