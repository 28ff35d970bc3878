// The contract every scattering model of bsdf.h keeps, checked over every model, lobe and side
// (as pbrt-v4's bsdfs_test.cpp and Mitsuba's chi2 tests do): sample() draws directions with the
// density pdf() reports over the whole sphere (chi-square), evaluate() is reciprocal for
// reflection and obeys the eta^2 rule for transmission (radiance compressed by 1/eta^2,
// importance not), and no lobe returns more energy than it receives (white furnace per lobe and
// angle, in importance, which carries energy).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "materials/bsdf.h"
#include "materials/material_table.h"
#include "materials/metallic_roughness.h"
#include "textures/texture.h"
#include "test_support.h"

using namespace strata;

namespace {

struct Case {
    std::string name;
    Material material;
    bool front = true;  // the side the BSDF is seen from
    glm::vec3 coatNormal{0.0f, 0.0f, 1.0f};  // a clear coat's own normal (Bsdf::tiltCoat), local
};

Material make(const std::function<void(Material&)>& set) {
    Material m;
    m.name = "contract";
    set(m);
    return m;
}

std::vector<Case> cases() {
    std::vector<Case> c;
    c.push_back({"lambertian", make([](Material& m) { m.diffuse = glm::vec3(0.8f, 0.5f, 0.2f); })});
    c.push_back({"layered ggx", make([](Material& m) {
                     m.diffuse = glm::vec3(0.5f);
                     m.specular = glm::vec3(0.3f);
                     m.roughness = 0.6f;
                 })});
    c.push_back({"rough conductor", make([](Material& m) {
                     m.specular = glm::vec3(0.95f, 0.8f, 0.5f);
                     m.roughness = 0.3f;
                 })});
    c.push_back({"smooth conductor", make([](Material& m) {
                     m.specular = glm::vec3(0.9f, 0.6f, 0.3f);
                     m.roughness = 0.0f;
                 })});
    c.push_back({"smooth coat over lambertian", make([](Material& m) {
                     m.diffuse = glm::vec3(0.7f);
                     m.specular = glm::vec3(0.2f);
                     m.roughness = 0.0f;
                 })});
    c.push_back({"rough clear coat over layered", make([](Material& m) {
                     m.diffuse = glm::vec3(0.6f, 0.1f, 0.1f);
                     m.specular = glm::vec3(0.04f);
                     m.roughness = 0.5f;
                     m.clearcoat = 0.8f;
                     m.clearcoatRoughness = 0.4f;
                 })});
    c.push_back({"sheen over layered", make([](Material& m) {
                     m.diffuse = glm::vec3(0.3f, 0.1f, 0.5f);
                     m.specular = glm::vec3(0.04f);
                     m.roughness = 0.7f;
                     m.sheenColour = glm::vec3(1.0f, 0.8f, 0.9f);
                     m.sheenRoughness = 0.5f;
                 })});
    c.push_back({"sheen of roughness 0.1 over black", make([](Material& m) {
                     m.sheenColour = glm::vec3(0.9f);
                     m.sheenRoughness = 0.1f;
                 })});
    c.push_back({"rough clear coat over sheen over lambertian", make([](Material& m) {
                     m.diffuse = glm::vec3(0.8f);
                     m.sheenColour = glm::vec3(1.0f);
                     m.sheenRoughness = 1.0f;
                     m.clearcoat = 1.0f;
                     m.clearcoatRoughness = 0.3f;
                 })});
    c.push_back({"smooth clear coat over mirror", make([](Material& m) {
                     m.specular = glm::vec3(0.9f);
                     m.roughness = 0.0f;
                     m.clearcoat = 1.0f;
                 })});
    // Coats with a normal of their own, 30 and 60 degrees off the surface's.
    const auto named = [&](const std::string& name) {
        return std::find_if(c.begin(), c.end(), [&](const Case& k) { return k.name == name; })->material;
    };
    const glm::vec3 tilted30(0.5f * std::cos(1.0f), 0.5f * std::sin(1.0f), std::sqrt(0.75f));
    const glm::vec3 tilted60(std::sqrt(0.75f) * std::cos(4.0f), std::sqrt(0.75f) * std::sin(4.0f), 0.5f);
    c.push_back({"rough clear coat over layered, tilted 30 degrees", named("rough clear coat over layered"), true,
                 tilted30});
    c.push_back({"rough clear coat over sheen, tilted 60 degrees", named("rough clear coat over sheen over lambertian"),
                 true, tilted60});
    c.push_back({"smooth clear coat over lambertian, tilted 30 degrees", make([](Material& m) {
                     m.diffuse = glm::vec3(0.8f, 0.6f, 0.4f);
                     m.clearcoat = 1.0f;
                 }),
                 true, tilted30});
    c.push_back({"smooth clear coat over mirror, tilted 60 degrees", named("smooth clear coat over mirror"), true,
                 tilted60});
    for (bool front : {true, false}) {
        const std::string side = front ? " (outside)" : " (inside)";
        c.push_back({"smooth dielectric" + side, make([](Material& m) {
                         m.transmission = 1.0f;
                         m.roughness = 0.0f;
                         m.transmissionFilter = glm::vec3(0.9f, 0.8f, 1.0f);
                     }),
                     front});
        for (float roughness : {0.5f, 0.85f}) {
            c.push_back({"rough dielectric Pr " + std::to_string(roughness) + side, make([roughness](Material& m) {
                             m.transmission = 1.0f;
                             m.roughness = roughness;
                             m.ior = 1.33f;
                         }),
                         front});
        }
        c.push_back({"rough dielectric blend" + side, make([](Material& m) {
                         m.diffuse = glm::vec3(0.5f);
                         m.specular = glm::vec3(0.04f);
                         m.roughness = 0.6f;
                         m.transmission = 0.6f;
                     }),
                     front});
    }
    c.push_back({"thin dielectric", make([](Material& m) {
                     m.transmission = 1.0f;
                     m.thinWalled = true;
                     m.transmissionFilter = glm::vec3(0.5f, 1.0f, 1.0f);
                 })});
    c.push_back({"smooth dielectric blend", make([](Material& m) {
                     m.diffuse = glm::vec3(0.8f);
                     m.roughness = 0.0f;
                     m.transmission = 0.3f;
                 })});
    return c;
}

bool tilted(const Case& c) { return c.coatNormal != glm::vec3(0.0f, 0.0f, 1.0f); }

Bsdf bsdfOf(const MaterialTable& table, const Case& c) {
    Bsdf bsdf = table.bsdf(0, glm::vec2(0.0f), c.front);
    if (tilted(c)) bsdf.tiltCoat(c.coatNormal);
    return bsdf;
}

glm::vec3 direction(double cosTheta, double phi) {
    const double r = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(cosTheta)};
}

// Numbers for sample(): a fixed-seed generator of independent uniform numbers.
struct Uniforms {
    uint64_t state;
    float next() {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<float>(state >> 40) * 0x1p-24f;
    }
    BsdfNumbers numbers() {
        const glm::vec2 u(next(), next());
        return BsdfNumbers::independent(u, next());
    }
};

float average(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }

// The viewing directions of the checks: above the normal and, for a model that transmits, below.
std::vector<glm::vec3> viewDirections(const Bsdf& bsdf) {
    std::vector<glm::vec3> wos{direction(0.95, 0.3), direction(0.5, 1.9), direction(0.12, 4.0)};
    if (isTransmission(bsdf.flags())) {
        for (double c : {-0.9, -0.45, -0.15}) wos.push_back(direction(c, 2.5));
    }
    return wos;
}

}  // namespace

TEST_CASE("bsdf contract: sample() draws the density pdf() reports, over the whole sphere (chi-square)") {
    // Bins of equal solid angle on a grid in (cos theta, phi) over the sphere; expected counts are
    // pdf() integrated over each bin by the midpoint rule, refined until it settles (a glossy
    // transmission lobe is steep beside the horizon). Directions from delta lobes, and samples
    // that are lost, fall in one more bin, expected to hold what pdf() leaves of 1.
    constexpr int kZBins = 20;
    constexpr int kPhiBins = 10;
    constexpr int kSamples = 150000;
    for (const Case& c : cases()) {
        const MaterialTable table({c.material});
        const Bsdf bsdf = bsdfOf(table, c);
        for (const glm::vec3& wo : viewDirections(bsdf)) {
            const auto binIntegral = [&](int zBin, int phiBin, int n) {
                double sum = 0.0;
                for (int i = 0; i < n; ++i) {
                    for (int j = 0; j < n; ++j) {
                        const double z = -1.0 + 2.0 * (zBin + (i + 0.5) / n) / kZBins;
                        const double phi = 2.0 * M_PI * (phiBin + (j + 0.5) / n) / kPhiBins;
                        sum += bsdf.pdf(wo, direction(z, phi));
                    }
                }
                return sum * (2.0 / kZBins) * (2.0 * M_PI / kPhiBins) / (n * n);
            };
            std::vector<double> expected(kZBins * kPhiBins + 1, 0.0);
            double total = 0.0;
            for (int a = 0; a < kZBins; ++a) {
                for (int b = 0; b < kPhiBins; ++b) {
                    int n = 16;
                    double coarse = binIntegral(a, b, n);
                    double fine = binIntegral(a, b, 2 * n);
                    while (std::abs(fine - coarse) > 1e-5 + 1e-3 * fine && n < 512) {
                        n *= 2;
                        coarse = fine;
                        fine = binIntegral(a, b, 2 * n);
                    }
                    expected[static_cast<size_t>(a * kPhiBins + b)] = fine;
                    total += fine;
                }
            }
            expected.back() = std::max(0.0, 1.0 - total);
            std::vector<int> counts(expected.size(), 0);
            Uniforms u{7};
            for (int s = 0; s < kSamples; ++s) {
                const auto sample = bsdf.sample(wo, u.numbers());
                if (!sample || isSpecular(sample->flags)) {
                    ++counts.back();
                    continue;
                }
                const double phi = std::atan2(sample->wi.y, sample->wi.x);
                const int a = std::clamp(static_cast<int>((sample->wi.z + 1.0) / 2.0 * kZBins), 0, kZBins - 1);
                const int b = std::clamp(static_cast<int>((phi < 0 ? phi + 2 * M_PI : phi) / (2 * M_PI) * kPhiBins), 0,
                                         kPhiBins - 1);
                ++counts[static_cast<size_t>(a * kPhiBins + b)];
            }
            double chi2 = 0.0;
            int cells = 0;
            double pooledExpected = 0.0;
            int pooledCount = 0;
            for (size_t k = 0; k < counts.size(); ++k) {
                const double e = expected[k] * kSamples;
                if (e < 5.0) {  // too few for the chi-square approximation: pooled
                    pooledExpected += e;
                    pooledCount += counts[k];
                    continue;
                }
                chi2 += (counts[k] - e) * (counts[k] - e) / e;
                ++cells;
            }
            if (pooledExpected >= 5.0) {
                chi2 += (pooledCount - pooledExpected) * (pooledCount - pooledExpected) / pooledExpected;
                ++cells;
            } else {
                // Nothing may land where the density says almost nothing can.
                CHECK(pooledCount <= 5.0 + 5.0 * std::sqrt(pooledExpected + 1.0));
            }
            const double limit = test::chiSquareCritical(static_cast<size_t>(std::max(1, cells - 1)));
            INFO(c.name << ", wo (" << wo.x << ", " << wo.y << ", " << wo.z << "): chi2 " << chi2 << " over "
                        << cells << " cells (limit " << limit << "), pdf integral " << total);
            CHECK(chi2 < limit);
            CHECK(total <= 1.0 + 2e-3);
        }
    }
}

TEST_CASE("bsdf contract: a sample reports the f, pdf and weight that evaluate() and pdf() give") {
    for (const Case& c : cases()) {
        const MaterialTable table({c.material});
        const Bsdf bsdf = bsdfOf(table, c);
        Uniforms u{11};
        for (const glm::vec3& wo : viewDirections(bsdf)) {
            for (int s = 0; s < 2000; ++s) {
                const auto sample = bsdf.sample(wo, u.numbers());
                if (!sample) continue;
                INFO(c.name << ", wo.z " << wo.z << ", wi (" << sample->wi.x << ", " << sample->wi.y << ", "
                            << sample->wi.z << ")");
                REQUIRE(std::abs(glm::length(sample->wi) - 1.0f) < 1e-4f);
                CHECK(isTransmission(sample->flags) == (wo.z * sample->wi.z < 0.0f));
                CHECK(sample->pdf > 0.0f);
                const glm::vec3 weight = sample->f * std::abs(sample->wi.z) / sample->pdf;
                CHECK(average(weight) == doctest::Approx(average(sample->weight)).epsilon(1e-3));
                if (isSpecular(sample->flags)) {
                    CHECK(sample->pdf <= 1.0f);
                    continue;
                }
                CHECK(bsdf.pdf(wo, sample->wi) == doctest::Approx(sample->pdf).epsilon(2e-3));
                CHECK(average(bsdf.evaluate(wo, sample->wi)) == doctest::Approx(average(sample->f)).epsilon(2e-3));
            }
        }
    }
}

TEST_CASE("bsdf contract: reflection is reciprocal, transmission obeys the eta^2 rule") {
    // For wi across the surface from wo, f_radiance(wo, wi) eta_i^2 = f_radiance(wi, wo) eta_o^2
    // (Veach 1997, 5.2), and f_radiance = f_importance / eta'^2 with eta' = eta_i / eta_o; for a
    // reflection f(wo, wi) = f(wi, wo) in both modes.
    Uniforms u{3};
    for (const Case& c : cases()) {
        // A tilted coat's lobe is reciprocal in its own frame (clear_coat.h), checked below.
        if (tilted(c)) continue;
        const MaterialTable table({c.material});
        const Bsdf bsdf = bsdfOf(table, c);
        // The index on each side: the outside 1, the inside the material's.
        const float above = c.front ? 1.0f : c.material.ior;
        const float below = c.front ? c.material.ior : 1.0f;
        int checked = 0;
        for (int s = 0; s < 400; ++s) {
            const glm::vec3 a = direction(2.0 * u.next() - 1.0, 2.0 * M_PI * u.next());
            const glm::vec3 b = direction(2.0 * u.next() - 1.0, 2.0 * M_PI * u.next());
            const glm::vec3 fab = bsdf.evaluate(a, b, TransportMode::Radiance);
            const glm::vec3 fba = bsdf.evaluate(b, a, TransportMode::Radiance);
            if (average(fab) < 1e-6f && average(fba) < 1e-6f) continue;
            ++checked;
            INFO(c.name << ": a.z " << a.z << ", b.z " << b.z);
            const bool across = a.z * b.z < 0.0f;
            const float etaA = a.z > 0.0f ? above : below;
            const float etaB = b.z > 0.0f ? above : below;
            const float rule = across && !c.material.thinWalled ? etaB * etaB / (etaA * etaA) : 1.0f;
            CHECK(average(fab) * rule == doctest::Approx(average(fba)).epsilon(1e-3));
            const glm::vec3 importance = bsdf.evaluate(a, b, TransportMode::Importance);
            CHECK(average(importance) == doctest::Approx(average(fab) * rule).epsilon(1e-3));
        }
        const bool onlyDeltas = !bsdf.hasNonSpecularLobe();
        INFO(c.name);
        CHECK((onlyDeltas || checked > 20));
    }
}

TEST_CASE("bsdf contract: no lobe returns more energy than it receives (white furnace per lobe and angle)") {
    // The albedo, estimated as the mean importance weight of sample() (its largest colour
    // component: a white version of the material would reach it) with its standard error, at
    // angles from normal to grazing and from both sides. Weights are never negative, so no lobe
    // alone exceeds the total either. The lossless models (the smooth and thin dielectrics in
    // their clear channel) return exactly what they receive.
    constexpr int kSamples = 40000;
    for (const Case& c : cases()) {
        const MaterialTable table({c.material});
        const Bsdf bsdf = bsdfOf(table, c);
        const bool lossless = c.name.rfind("smooth dielectric (", 0) == 0 || c.name == "thin dielectric";
        for (double cosTheta : {1.0, 0.7, 0.3, 0.05, -0.3, -0.8}) {
            if (cosTheta < 0.0 && !isTransmission(bsdf.flags())) continue;
            const glm::vec3 wo = direction(cosTheta, 0.7);
            Uniforms u{17};
            std::vector<double> weights;
            for (int s = 0; s < kSamples; ++s) {
                const auto sample = bsdf.sample(wo, u.numbers(), TransportMode::Importance);
                if (sample) CHECK(std::min({sample->weight.x, sample->weight.y, sample->weight.z}) >= 0.0f);
                weights.push_back(sample ? std::max({sample->weight.x, sample->weight.y, sample->weight.z}) : 0.0);
            }
            const test::MeanEstimate albedo = test::estimateMean(weights);
            INFO(c.name << ", cos theta_o " << cosTheta << ": albedo " << albedo.mean << " +- " << albedo.standardError);
            CHECK(albedo.mean <= 1.0 + 4.0 * albedo.standardError + 1e-4);
            if (lossless) CHECK(albedo.mean == doctest::Approx(1.0).epsilon(1e-5));
        }
    }
}

TEST_CASE("bsdf contract: a model reads the diffuse numbers exactly when it says so") {
    int without = 0;
    for (const Case& c : cases()) {
        const MaterialTable table({c.material});
        const Bsdf bsdf = bsdfOf(table, c);
        INFO(c.name);
        // The table knows it before a hit's BSDF is built: for an untextured material, the BSDF's own answer.
        CHECK(table.readsDiffuseNumbers(0) == bsdf.readsDiffuseNumbers());
        Uniforms u{29};
        if (bsdf.readsDiffuseNumbers()) {
            // A model that says it reads them does: another diffuse point moves some sample.
            int moved = 0;
            for (const glm::vec3& wo : viewDirections(bsdf)) {
                for (int s = 0; s < 500; ++s) {
                    BsdfNumbers numbers = u.numbers();
                    const auto first = bsdf.sample(wo, numbers);
                    numbers.diffuse.point = glm::vec2(u.next(), u.next());
                    const auto second = bsdf.sample(wo, numbers);
                    if (first && second && first->wi != second->wi) ++moved;
                }
            }
            CHECK(moved > 0);
            continue;
        }
        ++without;
        for (const glm::vec3& wo : viewDirections(bsdf)) {
            for (int s = 0; s < 500; ++s) {
                BsdfNumbers numbers = u.numbers();
                const auto drawn = bsdf.sample(wo, numbers);
                // What a path tracer passes where it draws none: the warp alone.
                numbers.diffuse = DiffuseSampling{numbers.diffuse.warp, -1, glm::vec2(0.0f)};
                const auto undrawn = bsdf.sample(wo, numbers);
                REQUIRE(drawn.has_value() == undrawn.has_value());
                if (!drawn) continue;
                CHECK(drawn->wi == undrawn->wi);
                CHECK(drawn->weight == undrawn->weight);
                CHECK(drawn->pdf == undrawn->pdf);
                CHECK(drawn->flags == undrawn->flags);
            }
        }
    }
    // The conductors and the dielectrics.
    CHECK(without >= 8);
}

TEST_CASE("material table: a textured material is taken to read the diffuse numbers") {
    // A glTF metal: metallic factor 1, so its constants have no diffuse base.
    Material metal;
    metal.name = "metal";
    metal.metallicRoughness = MetallicRoughness{glm::vec3(0.9f), 1.0f};
    const LayeredReflectance constants = fromMetallicRoughness(glm::vec3(0.9f), 1.0f);
    metal.diffuse = constants.diffuse;
    metal.specular = constants.specular;
    metal.roughness = 0.3f;
    CHECK_FALSE(MaterialTable({metal}).readsDiffuseNumbers(0));
    // A metallic texture of 0.5 under that factor gives it one.
    metal.textures.roughness = std::make_shared<Texture>(1, 1, 3, std::vector<float>{0.0f, 1.0f, 0.5f});
    metal.textures.metallic = metal.textures.roughness;
    const MaterialTable textured({metal});
    CHECK(textured.bsdf(0, glm::vec2(0.5f)).readsDiffuseNumbers());
    CHECK(textured.readsDiffuseNumbers(0));
}

TEST_CASE("material table: a vertex colour multiplies Kd, and a glTF base colour in both its lobes") {
    const glm::vec3 colour(0.2f, 1.0f, 0.5f);
    // Seen and lit along the normal: a Lambertian f is Kd / pi, a metal's GGX term F0 times a
    // number that does not depend on F0 (Schlick's F at normal incidence is F0).
    const glm::vec3 normal(0.0f, 0.0f, 1.0f);
    const auto ratio = [&](const Material& m) {
        const MaterialTable table({m});
        const glm::vec3 white = table.bsdf(0, glm::vec2(0.0f), true).evaluate(normal, normal);
        const glm::vec3 tinted = table.bsdf(0, glm::vec2(0.0f), true, colour).evaluate(normal, normal);
        // White is the untinted BSDF, bit for bit.
        CHECK(table.bsdf(0, glm::vec2(0.0f), true, glm::vec3(1.0f)).evaluate(normal, normal) == white);
        return tinted / white;
    };
    Material lambertian;
    lambertian.diffuse = glm::vec3(0.5f, 0.6f, 0.7f);
    const glm::vec3 diffuse = ratio(lambertian);
    for (int c = 0; c < 3; ++c) CHECK(diffuse[c] == doctest::Approx(colour[c]).epsilon(1e-6));

    Material metal;
    metal.metallicRoughness = MetallicRoughness{glm::vec3(0.9f), 1.0f};
    const LayeredReflectance constants = fromMetallicRoughness(glm::vec3(0.9f), 1.0f);
    metal.diffuse = constants.diffuse;
    metal.specular = constants.specular;
    metal.roughness = 0.3f;
    const glm::vec3 specular = ratio(metal);
    for (int c = 0; c < 3; ++c) CHECK(specular[c] == doctest::Approx(colour[c]).epsilon(1e-5));
}
