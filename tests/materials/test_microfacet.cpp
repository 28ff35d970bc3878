// The GGX Cook-Torrance lobe (microfacet.h): normalisation, and the white furnace of notes
// section 5.4 (F = 1, GGX + height-correlated Smith): the directional albedo, integrated
// numerically from evaluate(), matches the notes' independently computed table within 1%.
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <tbb/task_arena.h>

#include "materials/bsdf.h"
#include "materials/layered_bsdf.h"
#include "materials/material_table.h"
#include "materials/microfacet.h"

using namespace strata;

namespace {

glm::vec3 directionAt(double thetaDegrees) {
    const double t = thetaDegrees * M_PI / 180.0;
    return glm::vec3(static_cast<float>(std::sin(t)), 0.0f, static_cast<float>(std::cos(t)));
}

// Integral of f_r(wo, wi) cos(theta_i) over the hemisphere, f_r from evaluate(), lobe by lobe
// with the midpoint rule on an n x n grid of a sampler of each (importance sampling as a change
// of variables, so the sharp lobes are resolved):
//   - the specular layer (the material without Kd) through its own sampler, f cos / pdf with
//     pdf(), so the three are checked against each other; the grid is graded toward u.x = 1, the
//     lobe's tail, by u.x = 1 - (1 - w)^3. Lost samples (below the surface) contribute 0;
//   - the rest, f_r minus the specular layer, on a grid in (cos theta_i, phi).
// `specular` is `full`'s material without Kd.
glm::dvec3 directionalAlbedo(const Bsdf& full, const Bsdf& specular,
                             const glm::vec3& wo, int n) {
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const double w = 1.0 - (i + 0.5) / n;
        const double jacobian = 3.0 * w * w;
        for (int j = 0; j < n; ++j) {
            const glm::vec2 graded(static_cast<float>(1.0 - w * w * w), (j + 0.5f) / n);
            if (const auto s = specular.sample(wo, graded, 0.0f)) {
                sum += jacobian * glm::dvec3(specular.evaluate(wo, s->wi)) *
                       (static_cast<double>(s->wi.z) / specular.pdf(wo, s->wi));
            }
            // d(omega) = d(mu) d(phi), midpoint rule in (mu, phi).
            const double mu = (i + 0.5) / n;
            const double phi = 2.0 * M_PI * (j + 0.5) / n;
            const double r = std::sqrt((1.0 - mu) * (1.0 + mu));
            const glm::vec3 wi(static_cast<float>(r * std::cos(phi)),
                               static_cast<float>(r * std::sin(phi)), static_cast<float>(mu));
            sum += 2.0 * M_PI * mu * glm::dvec3(full.evaluate(wo, wi) - specular.evaluate(wo, wi));
        }
    }
    return sum / static_cast<double>(n * n);
}

Material specularOnly(float alpha) {
    Material m;
    m.specular = glm::vec3(1.0f);  // F0 = 1: Schlick's F is 1 everywhere
    m.roughness = std::sqrt(alpha);
    return m;
}

}  // namespace

TEST_CASE("microfacet: GGX D is normalised and G1 satisfies the visible-area identity") {
    // Notes section 5.4: integral of D(h) cos(theta_h) = 1, and
    // integral of G1(v) <v,h>+ D(h) dw_h = cos(theta_v). Midpoint rule in (s, phi) after the
    // substitution tan^2 theta = alpha^2 s / (1 - s) that flattens D cos.
    for (float alpha : {0.1f, 0.5f, 1.0f}) {
        const GgxDistribution ggx(alpha);
        const glm::vec3 v = glm::normalize(glm::vec3(0.6f, 0.2f, 0.5f));
        constexpr int n = 800;
        double normalisation = 0.0;
        double projected = 0.0;
        for (int i = 0; i < n; ++i) {
            // s = 1 - (1 - w)^2 on a uniform w grid: ds = 2 (1 - w) dw cancels the 1/sqrt(1 - s)
            // growth of (v.h) / cos(theta_h) in the tail.
            const double w = 1.0 - (i + 0.5) / n;
            const double s = 1.0 - w * w;
            const double dsDw = 2.0 * w;
            const double tan2 = alpha * alpha * s / (1.0 - s);
            const double cosT = 1.0 / std::sqrt(1.0 + tan2);
            const double sinT = std::sqrt(tan2) * cosT;
            // dw = sin dtheta dphi; d(s)/d(theta) gives the Jacobian below.
            const double dThetaDs = 0.5 * alpha / (std::sqrt(s * (1.0 - s)) * (1.0 + tan2) * (1.0 - s));
            for (int j = 0; j < n; ++j) {
                const double phi = 2.0 * M_PI * (j + 0.5) / n;
                const glm::vec3 h(static_cast<float>(sinT * std::cos(phi)),
                                  static_cast<float>(sinT * std::sin(phi)), static_cast<float>(cosT));
                const double area = sinT * dThetaDs * dsDw * (1.0 / n) * (2.0 * M_PI / n);
                normalisation += ggx.density(h) * cosT * area;
                projected += ggx.masking(v) * std::max(0.0f, glm::dot(v, h)) * ggx.density(h) * area;
            }
        }
        INFO("alpha " << alpha);
        CHECK(normalisation == doctest::Approx(1.0).epsilon(1e-4));
        CHECK(projected == doctest::Approx(v.z).epsilon(1e-4));
    }
}

TEST_CASE("microfacet: white furnace albedo matches the notes' table (GGX, height-correlated Smith)") {
    // Notes section 5.4, columns theta_o = 0, 30, 60, 75, 85 degrees.
    const float alphas[] = {0.10f, 0.25f, 0.50f, 0.75f, 1.00f};
    const double angles[] = {0.0, 30.0, 60.0, 75.0, 85.0};
    const double table[5][5] = {{0.98831, 0.98609, 0.96920, 0.92442, 0.88638},
                                {0.91581, 0.90415, 0.85726, 0.83933, 0.90075},
                                {0.68785, 0.68305, 0.69825, 0.76137, 0.87202},
                                {0.46392, 0.48165, 0.56462, 0.67462, 0.82660},
                                {0.30685, 0.33519, 0.45069, 0.59060, 0.78005}};
    for (int a = 0; a < 5; ++a) {
        const MaterialTable bsdfMaterials({specularOnly(alphas[a])});
        const Bsdf bsdf = bsdfMaterials.bsdf(0);
        for (int t = 0; t < 5; ++t) {
            const glm::vec3 wo = directionAt(angles[t]);
            const double albedo = directionalAlbedo(bsdf, bsdf, wo, 256).x;
            INFO("alpha " << alphas[a] << " theta_o " << angles[t] << ": " << albedo << " vs "
                          << table[a][t]);
            CHECK(std::abs(albedo / table[a][t] - 1.0) < 0.01);
            CHECK(albedo <= 1.0);
            // The layering's table (used to couple the matte layer) agrees as well.
            CHECK(std::abs(bsdf.as<LayeredBsdf>()->albedo(wo).x / table[a][t] - 1.0) < 0.01);
        }
    }
}

TEST_CASE("microfacet: the layered material never reflects more than it receives") {
    // Kd = 1 under a specular layer: the coupling gives the matte layer exactly the energy the
    // specular one leaves, so the albedo approaches but never exceeds 1, at every angle,
    // roughness and F0. What remains is the albedo table's interpolation error (at most 1.6e-4,
    // at Pr 0.05 and 89 degrees) plus this quadrature's (~1e-4 at n = 128).
    for (float f0 : {0.04f, 1.0f}) {
        for (float roughness : {0.05f, 0.3f, 1.0f}) {
            Material m;
            m.diffuse = glm::vec3(1.0f, 0.5f, 0.0f);
            m.specular = glm::vec3(f0);
            m.roughness = roughness;
            const MaterialTable bsdfMaterials({m});
            const Bsdf bsdf = bsdfMaterials.bsdf(0);
            m.diffuse = glm::vec3(0.0f);
            const MaterialTable specularMaterials({m});
            const Bsdf specular = specularMaterials.bsdf(0);
            for (double theta : {0.0, 45.0, 70.0, 85.0, 89.0}) {
                const glm::vec3 wo = directionAt(theta);
                const glm::dvec3 albedo = directionalAlbedo(bsdf, specular, wo, 128);
                INFO("F0 " << f0 << " Pr " << roughness << " theta " << theta << ": " << albedo.x
                           << " " << albedo.y << " " << albedo.z);
                CHECK(albedo.x <= 1.0 + 4e-4);
                CHECK(albedo.x == doctest::Approx(bsdf.as<LayeredBsdf>()->albedo(wo).x).epsilon(0.01));
                CHECK(albedo.y == doctest::Approx(bsdf.as<LayeredBsdf>()->albedo(wo).y).epsilon(0.01));
                CHECK(albedo.y < albedo.x);
            }
        }
    }
}

TEST_CASE("microfacet: the layered material is reciprocal and Lambertian without Ks") {
    Material m;
    m.diffuse = glm::vec3(0.6f, 0.3f, 0.2f);
    m.specular = glm::vec3(0.3f);
    m.roughness = 0.4f;
    const MaterialTable layeredMaterials({m});
    const Bsdf layered = layeredMaterials.bsdf(0);
    const glm::vec3 a = glm::normalize(glm::vec3(0.3f, 0.1f, 0.9f));
    const glm::vec3 b = glm::normalize(glm::vec3(-0.5f, 0.4f, 0.3f));
    const glm::vec3 fab = layered.evaluate(a, b);
    const glm::vec3 fba = layered.evaluate(b, a);
    CHECK(fab.x == doctest::Approx(fba.x).epsilon(1e-5));
    CHECK(fab.z == doctest::Approx(fba.z).epsilon(1e-5));
    CHECK(layered.evaluate(a, glm::vec3(0.0f, 0.6f, -0.8f)).x == 0.0f);

    Material matte;
    matte.diffuse = glm::vec3(0.5f);
    const MaterialTable lambertianMaterials({matte});
    const Bsdf lambertian = lambertianMaterials.bsdf(0);
    CHECK(lambertian.evaluate(a, b).x == doctest::Approx(0.5 / M_PI));
    CHECK(lambertian.flags() == (kReflection | kDiffuse));
    CHECK(MaterialTable({Material{}}).isBlack(0));
    CHECK(MaterialTable({Material{}}).bsdf(0).isBlack());
}

TEST_CASE("microfacet: the material's sampler has the density it reports (chi-square)") {
    // Directions binned on a 12 x 12 grid in (cos theta, phi), where d(omega) = dz dphi; expected
    // counts from pdf() integrated over each bin by a fine midpoint rule, plus one bin for lost
    // samples (the visible-normal reflection can point below the surface).
    Material m;
    m.diffuse = glm::vec3(0.3f);
    m.specular = glm::vec3(0.5f);
    m.roughness = 0.6f;
    const MaterialTable bsdfMaterials({m});
    const Bsdf bsdf = bsdfMaterials.bsdf(0);
    const glm::vec3 wo = directionAt(50.0);
    constexpr int kBins = 12;
    constexpr int kFine = 24;
    std::vector<double> expected(kBins * kBins + 1, 0.0);
    double total = 0.0;
    for (int i = 0; i < kBins * kFine; ++i) {
        for (int j = 0; j < kBins * kFine; ++j) {
            const double z = (i + 0.5) / (kBins * kFine);
            const double phi = 2.0 * M_PI * (j + 0.5) / (kBins * kFine);
            const double r = std::sqrt(1.0 - z * z);
            const glm::vec3 wi(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                               static_cast<float>(z));
            const double p = bsdf.pdf(wo, wi) * (1.0 / (kBins * kFine)) * (2.0 * M_PI / (kBins * kFine));
            expected[(i / kFine) * kBins + j / kFine] += p;
            total += p;
        }
    }
    expected[kBins * kBins] = std::max(0.0, 1.0 - total);
    constexpr int kSamples = 200000;
    std::vector<int> counts(kBins * kBins + 1, 0);
    uint64_t state = 1;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<float>(state >> 40) * 0x1p-24f;
    };
    for (int s = 0; s < kSamples; ++s) {
        const glm::vec2 u(next(), next());
        const auto sample = bsdf.sample(wo, u, next());
        if (!sample) {
            ++counts[kBins * kBins];
            continue;
        }
        const double phi = std::atan2(sample->wi.y, sample->wi.x);
        const int a = std::min(kBins - 1, static_cast<int>(sample->wi.z * kBins));
        const int b = std::min(kBins - 1, static_cast<int>((phi < 0 ? phi + 2 * M_PI : phi) / (2 * M_PI) * kBins));
        ++counts[a * kBins + b];
    }
    double chi2 = 0.0;
    int cells = 0;
    for (size_t k = 0; k < counts.size(); ++k) {
        const double e = expected[k] * kSamples;
        if (e < 5.0) continue;  // too few for the chi-square approximation
        chi2 += (counts[k] - e) * (counts[k] - e) / e;
        ++cells;
    }
    // ~144 degrees of freedom: mean 144, sd 17; 235 is p ~ 1e-5.
    INFO("chi2 = " << chi2 << " over " << cells << " cells, expected total " << total);
    CHECK(cells > 100);
    CHECK(chi2 < 235.0);
}

TEST_CASE("microfacet threads: the albedo table is the same bit for bit on one thread and on many") {
    // Its entries are computed in parallel (a roughness texture needs 17 tables at load); each is
    // its own quadrature, so the thread count must not move a bit of it.
    for (float roughness : {0.05f, 0.5f, 1.0f}) {
        INFO("roughness " << roughness);
        const GgxDistribution distribution(ggxAlphaFromRoughness(roughness));
        const GgxAlbedoTable onMany(distribution);
        tbb::task_arena oneThread(1);
        const GgxAlbedoTable onOne = oneThread.execute([&] { return GgxAlbedoTable(distribution); });
        for (int i = 0; i <= 200; ++i) {
            const float mu = static_cast<float>(i) / 200.0f;
            CHECK(onMany.albedo(mu) == onOne.albedo(mu));
        }
        CHECK(onMany.averageAlbedo() == onOne.averageAlbedo());
    }
}
