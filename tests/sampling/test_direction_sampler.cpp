// The estimators of direction_sampler.h, end to end through the path integrator, on the exact
// cases of the notes (section 5): all unbiased with and without next-event estimation, cosine
// sampling of the furnace with zero variance, and the densities they report.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "sampling/direction_sampler.h"
#include "sampling/hemisphere.h"
#include "integrator/path_integrator.h"
#include "scene/scene.h"
#include "sampling/strata24.h"
#include "sampling/strata24_warped.h"
#include "materials/bsdf.h"
#include "materials/material_table.h"
#include "test_support.h"

using namespace strata;

namespace {

using test::kSigmas;

Material lambertian(float albedo, float emission = 0.0f) {
    Material m;
    m.name = "lambertian";
    m.diffuse = glm::vec3(albedo);
    m.emission = glm::vec3(emission);
    return m;
}

void checkUnbiased(const std::vector<double>& estimates, double exact, const std::string& what) {
    const test::MeanEstimate e = test::estimateMean(estimates);
    INFO(what << ": mean " << e.mean << " +- " << e.standardError << ", exact " << exact);
    CHECK(std::abs(e.mean - exact) <= kSigmas * e.standardError + 1e-6 * exact);
}

}  // namespace

TEST_CASE("direction sampler: every name parses back to its kind and the list is complete") {
    for (SamplerKind kind : kSamplerKinds) {
        CHECK(parseSamplerKind(samplerName(kind)) == kind);
        CHECK(samplerNames().find(std::string(samplerName(kind))) != std::string::npos);
    }
    CHECK_FALSE(parseSamplerKind("strata25").has_value());
}

TEST_CASE("direction sampler: cosine sampling of the Lambertian furnace has zero variance") {
    // Notes section 5.1: the weight per bounce is exactly rho, so every path carries L_K; the
    // warped strata of strata24-bsdf sample the same density.
    const Scene scene(test::furnaceMesh(lambertian(0.5f, 1.0f)));
    for (SamplerKind kind : {SamplerKind::Cosine, SamplerKind::Strata24Bsdf, SamplerKind::Bsdf}) {
        for (int depth : {1, 5, 10}) {
            const PathIntegrator integrator(scene, {depth, kind, false});
            const double exact = test::furnaceRadiance(0.5, 1.0, depth);
            uint64_t rays = 0;
            const float first = integrator.radiance(test::furnaceRay(), PathSamples(1, 0, 0, 0), rays).x;
            for (uint32_t pass = 0; pass < 20; ++pass) {
                for (int step = 0; step < 24; ++step) {
                    const glm::vec3 value =
                        integrator.radiance(test::furnaceRay(), PathSamples(1, 7, pass, step), rays);
                    // Bit-identical on every path: the variance is exactly 0.
                    REQUIRE(value.x == first);
                    REQUIRE(value.y == first);
                }
            }
            INFO(samplerName(kind) << " depth " << depth);
            CHECK(first == doctest::Approx(exact).epsilon(1e-6));
        }
    }
}

TEST_CASE("direction sampler: every sampler is unbiased on the furnace, with and without NEE") {
    const Scene scene(test::furnaceMesh(lambertian(0.8f, 1.0f)));
    for (SamplerKind kind : kSamplerKinds) {
        for (bool nee : {false, true}) {
            for (int depth : {1, 4}) {
                const PathIntegrator integrator(scene, {depth, kind, nee});
                const auto estimates = test::pixelEstimates(integrator, test::furnaceRay(), 200, 1, 3);
                const std::string what = std::string(samplerName(kind)) + (nee ? " --nee" : "") +
                                         " depth " + std::to_string(depth);
                checkUnbiased(estimates, test::furnaceRadiance(0.8, 1.0, depth), what);
            }
        }
    }
}

TEST_CASE("direction sampler: every sampler is unbiased on Lambert's polygon, with and without NEE") {
    // Notes section 5.2: receiver radiance rho E / pi at depth 1.
    const float rho = 0.7f;
    const Scene scene(test::lambertSquareMesh(lambertian(rho)));
    const Ray ray = test::rayToOrigin({0.2f, 0.1f, 0.5f});
    const double exact = rho * test::kLambertSquareIrradiance / M_PI;
    for (SamplerKind kind : kSamplerKinds) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {1, kind, nee});
            const auto estimates = test::pixelEstimates(integrator, ray, 400, 2, 5);
            const std::string what = std::string(samplerName(kind)) + (nee ? " --nee" : "");
            checkUnbiased(estimates, exact, what);
        }
    }
}

TEST_CASE("direction sampler: on a glossy receiver all samplers and NEE agree") {
    // No closed form here, so the estimators are checked against each other: the uniform
    // sampler without NEE (no MIS) is the reference.
    Material glossy = lambertian(0.4f);
    glossy.specular = glm::vec3(0.6f);
    glossy.roughness = 0.5f;  // alpha 0.25
    const Scene scene(test::lambertSquareMesh(glossy));
    // Seen at 60 degrees from the normal, opposite the square's highlight side.
    const Ray ray = test::rayToOrigin({-0.7f, 0.0f, 0.4f});
    const PathIntegrator reference(scene, {2, SamplerKind::Uniform, false});
    const test::MeanEstimate ref =
        test::estimateMean(test::pixelEstimates(reference, ray, 400, 8, 11));
    for (SamplerKind kind : kSamplerKinds) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {2, kind, nee});
            const test::MeanEstimate e =
                test::estimateMean(test::pixelEstimates(integrator, ray, 400, 2, 13));
            INFO(samplerName(kind) << (nee ? " --nee" : "") << ": " << e.mean << " +- "
                                   << e.standardError << ", reference " << ref.mean << " +- "
                                   << ref.standardError);
            CHECK(std::abs(e.mean - ref.mean) <=
                  kSigmas * std::hypot(e.standardError, ref.standardError));
        }
    }
}

TEST_CASE("direction sampler: the reported density is the marginal density of the direction") {
    // A layered material's sample reports the mixture's density, its diffuse lobe's by the
    // sampler's warp; pdf() must give the same value for the same direction (MIS relies on it).
    Material m = lambertian(0.5f);
    m.specular = glm::vec3(0.3f);
    m.roughness = 0.6f;
    const MaterialTable bsdfMaterials({m});
    const Bsdf bsdf = bsdfMaterials.bsdf(0);
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f));
    for (SamplerKind kind : kSamplerKinds) {
        int diffuseSamples = 0;
        for (int step = 0; step < 24; ++step) {
            const PathSamples samples(9, 4, 2, step);
            const glm::vec3 lobe = samples.lobeSample(0);
            const BsdfNumbers numbers{diffuseNumbers(kind, samples, 0), {lobe.y, lobe.z}, lobe.x};
            const auto s = bsdf.sample(wo, numbers);
            if (!s) continue;
            INFO(samplerName(kind));
            CHECK(std::abs(glm::length(s->wi) - 1.0f) < 1e-5f);
            CHECK(s->wi.z >= 0.0f);
            CHECK(bsdf.pdf(wo, s->wi, samplerChoice(kind).warp) == doctest::Approx(s->pdf).epsilon(1e-4));
            if (s->flags & kGlossy) continue;
            ++diffuseSamples;
            CHECK(s->stratum == numbers.diffuse.stratum);
            // strata24-bsdf's diffuse directions lie in the warped image of their stratum.
            const glm::vec3 inStratum = kind == SamplerKind::Strata24Bsdf ? warpCosineToUniform(s->wi) : s->wi;
            if (s->stratum >= 0) CHECK(stratumContains(s->stratum, inStratum));
        }
        CHECK(diffuseSamples > 0);
    }
}

TEST_CASE("direction sampler: cosine-weighted hemisphere passes a chi-square test") {
    // Under cos / pi, 1 - z^2 (= r^2 on the disk) and the azimuth are independent and uniform, so
    // a 16 x 16 grid in (1 - z^2, azimuth) has equal expected counts.
    constexpr int kBins = 16;
    constexpr int kSamples = 256000;
    std::vector<int> counts(kBins * kBins, 0);
    for (int i = 0; i < kSamples; ++i) {
        const PathSamples samples(21, static_cast<uint64_t>(i), 0, 0);
        const glm::vec3 d = sampleCosineHemisphere(samples.bouncePoint(0));
        const double r2 = std::min(1.0, static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y);
        const double phi = std::atan2(d.y, d.x) + M_PI;
        const int a = std::min(kBins - 1, static_cast<int>(r2 * kBins));
        const int b = std::min(kBins - 1, static_cast<int>(phi / (2.0 * M_PI) * kBins));
        ++counts[a * kBins + b];
    }
    const double expected = static_cast<double>(kSamples) / (kBins * kBins);
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    // 255 degrees of freedom: mean 255, sd 22.6; 360 is p ~ 1e-5.
    INFO("chi2 = " << chi2);
    CHECK(chi2 < 360.0);
}

TEST_CASE("direction sampler: depth 10000 with NEE runs as a loop and converges to Le / (1 - rho)") {
    const Scene scene(test::furnaceMesh(lambertian(0.5f, 1.0f)));
    for (bool nee : {false, true}) {
        const PathIntegrator integrator(scene, {10000, SamplerKind::Cosine, nee});
        const auto estimates = test::pixelEstimates(integrator, test::furnaceRay(), 24, 1, 2);
        checkUnbiased(estimates, test::furnaceRadiance(0.5, 1.0, 10000),
                      nee ? "depth 10000 --nee" : "depth 10000");
    }
}
