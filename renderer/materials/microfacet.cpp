#include "materials/microfacet.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/constants.h"
#include "util/tbb_hand_off.h"
#include "util/turns.h"

namespace strata {

float ggxAlphaFromRoughness(float roughness) {
    return std::clamp(roughness * roughness, kMinGgxAlpha, 1.0f);
}

float roughnessFromShininess(float shininess) {
    const float alpha = std::sqrt(2.0f / (std::max(shininess, 0.0f) + 2.0f));
    return std::sqrt(alpha);
}

float GgxDistribution::density(const glm::vec3& h) const {
    if (h.z <= 0.0f) return 0.0f;
    // D = alpha^2 / (pi ((h.z^2 (alpha^2 - 1) + 1)^2), written with the in-plane part so that
    // nothing cancels for a sharp lobe.
    const float a2 = alpha_ * alpha_;
    const float t = h.x * h.x + h.y * h.y + h.z * h.z * a2;
    return a2 / (kPi * t * t);
}

float GgxDistribution::lambda(const glm::vec3& w) const {
    const float sin2 = w.x * w.x + w.y * w.y;
    const float cos2 = w.z * w.z;
    if (sin2 == 0.0f) return 0.0f;
    const float alpha2Tan2 = alpha_ * alpha_ * sin2 / cos2;
    return 0.5f * (std::sqrt(1.0f + alpha2Tan2) - 1.0f);
}

float GgxDistribution::reflectance(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const glm::vec3 h = glm::normalize(wo + wi);
    return density(h) * maskingShadowing(wo, wi) / (4.0f * wo.z * wi.z);
}

glm::vec3 GgxDistribution::sampleVisibleNormal(const glm::vec3& wo, glm::vec2 u) const {
    // Heitz 2018, listing 1: stretch the view to the configuration of a unit-roughness
    // hemisphere, sample the projected disk of visible normals (half of it warped toward the
    // part seen), lift onto the hemisphere and unstretch.
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha_ * wo.x, alpha_ * wo.y, wo.z));
    const float lengthSquared = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lengthSquared > 0.0f
                             ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lengthSquared)
                             : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x);
    const glm::vec2 azimuth = cosSinOfTurns(u.y);
    const float p1 = r * azimuth.x;
    float p2 = r * azimuth.y;
    const float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 nh =
        p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha_ * nh.x, alpha_ * nh.y, std::max(0.0f, nh.z)));
}

float GgxDistribution::reflectionPdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const glm::vec3 h = glm::normalize(wo + wi);
    const float cosOH = glm::dot(wo, h);
    if (cosOH <= 0.0f) return 0.0f;
    // D_wo(h) / (4 wo.h) = G1(wo) D(h) / (4 wo.z).
    return masking(wo) * density(h) / (4.0f * wo.z);
}

namespace {

// E1 and E5 at mu = cos(theta_o) by the midpoint rule on a 64 x 64 grid of the visible-normal
// sampler's square: its weight f cos / pdf = G2(wo, wi) / G1(wo) (times the Fresnel factor) is
// continuous (G2 -> 0 at the horizon). The weight falls off only in the distribution's tail,
// u.x -> 1 (for alpha = 0.1 the last 1% of the square), so the grid is graded there:
// u.x = 1 - (1 - w)^3 with w on the uniform grid and Jacobian 3 (1 - w)^2. This reaches ~1e-4
// where a uniform grid is 1% off (tests/materials/test_microfacet.cpp checks the notes' table,
// section 5.4).
glm::vec2 albedoByQuadrature(const GgxDistribution& distribution, float mu) {
    constexpr int kGrid = 64;
    const glm::vec3 wo(std::sqrt((1.0f - mu) * (1.0f + mu)), 0.0f, mu);
    const float inverseMasking = 1.0f / distribution.masking(wo);
    double e1 = 0.0;
    double e5 = 0.0;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            const double w = 1.0 - (i + 0.5) / kGrid;  // 1 - the uniform grid point
            const glm::vec2 u(static_cast<float>(1.0 - w * w * w), (j + 0.5f) / kGrid);
            const glm::vec3 h = distribution.sampleVisibleNormal(wo, u);
            const float cosOH = glm::dot(wo, h);
            const glm::vec3 wi = 2.0f * cosOH * h - wo;
            if (wi.z <= 0.0f) continue;
            const double weight = 3.0 * w * w * distribution.maskingShadowing(wo, wi) * inverseMasking;
            const double m = 1.0 - std::clamp(cosOH, 0.0f, 1.0f);
            e1 += weight;
            e5 += weight * m * m * m * m * m;
        }
    }
    return glm::vec2(e1, e5) / static_cast<float>(kGrid * kGrid);
}

}  // namespace

GgxAlbedoTable::GgxAlbedoTable(const GgxDistribution& distribution) {
    // Each entry is its own quadrature, and a scene can need many tables: a material with a
    // roughness texture builds kRoughnessLevels of them at load, which on one thread take 70% of
    // the time of a 32x32 render of assimp's ClearCoatTest.gltf. The entries are computed in
    // parallel, each by the same arithmetic on whichever thread takes it, so the table is the same
    // bit for bit. (The hand-off and the partitioner: util/tbb_hand_off.h.)
    const auto computeEntries = [&](const tbb::blocked_range<int>& entries) {
        for (int entry = entries.begin(); entry != entries.end(); ++entry) {
            // mu = 0 exactly has no visible normals; its albedo is the limit, taken at a tiny angle.
            table_[entry] = albedoByQuadrature(distribution, std::max(entryCosine(entry), 1e-4f));
        }
    };
    tbb::parallel_for(tbb::blocked_range<int>(0, kEntries, 4), handedOff(computeEntries), tbb::simple_partitioner());
    receiveHandOff();
    // 2 * integral of E mu dmu of the piecewise-linear table, exactly: on each interval the
    // integrand is a quadratic, integrated by Simpson's rule.
    glm::dvec2 sum(0.0);
    for (int i = 0; i + 1 < kEntries; ++i) {
        const double m0 = entryCosine(i);
        const double m1 = entryCosine(i + 1);
        const glm::dvec2 e0(table_[i]);
        const glm::dvec2 e1(table_[i + 1]);
        const glm::dvec2 middle = 0.5 * (e0 + e1) * (0.5 * (m0 + m1));
        sum += (m1 - m0) / 6.0 * (e0 * m0 + 4.0 * middle + e1 * m1);
    }
    average_ = glm::vec2(2.0 * sum);
}

float GgxAlbedoTable::entryCosine(int entry) {
    const float s = static_cast<float>(entry) / (kEntries - 1);
    return s * s;
}

glm::vec2 GgxAlbedoTable::albedo(float mu) const {
    mu = std::clamp(mu, 0.0f, 1.0f);
    const int i = std::min(static_cast<int>(std::sqrt(mu) * (kEntries - 1)), kEntries - 2);
    const float m0 = entryCosine(i);
    const float m1 = entryCosine(i + 1);
    const float t = std::clamp((mu - m0) / (m1 - m0), 0.0f, 1.0f);
    return table_[i] * (1.0f - t) + table_[i + 1] * t;
}

}  // namespace strata
