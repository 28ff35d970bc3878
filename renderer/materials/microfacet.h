#pragma once
// The Cook-Torrance microfacet reflection model with the GGX (Trowbridge-Reitz) distribution:
//   f_r(wo, wi) = F(wo.h) D(h) G2(wo, wi) / (4 cos(theta_o) cos(theta_i)),   h = normalize(wo + wi)
// (Cook & Torrance 1982 with the denominator 4 of Walter et al. 2007; pi there instead of 4 gives
// an albedo of 1.27 and breaks energy conservation, notes section 5.4). G2 is the height-correlated
// Smith masking-shadowing function (Heitz 2014) and F is Schlick's approximation. Directions are
// in the local frame of the surface (normal +z) and above it.
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

// The smallest GGX alpha used: a smooth MTL surface (Pr 0) becomes a very sharp, but finite, lobe.
inline constexpr float kMinGgxAlpha = 1e-3f;

// GGX alpha from the MTL roughness Pr: alpha = Pr^2 (Burley 2012's perceptual remapping, as
// ../shared/scenes/cornell_glossy uses), clamped to [kMinGgxAlpha, 1].
float ggxAlphaFromRoughness(float roughness);
// MTL roughness Pr from a Phong exponent Ns when Pr is absent: Walter et al. 2007's matching of
// Phong to Beckmann, alpha = sqrt(2 / (Ns + 2)), taken as the GGX alpha, so Pr = alpha^(1/2).
float roughnessFromShininess(float shininess);

class GgxDistribution {
public:
    explicit GgxDistribution(float alpha) : alpha_(alpha) {}

    float alpha() const { return alpha_; }
    // Microfacet normal density D(h), normalised so that the integral of D(h) h.z over the
    // hemisphere is 1.
    float density(const glm::vec3& h) const;
    // Smith's Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2(theta))) / 2.
    float lambda(const glm::vec3& w) const;
    float masking(const glm::vec3& w) const { return 1.0f / (1.0f + lambda(w)); }
    // Height-correlated Smith G2 = 1 / (1 + Lambda(wo) + Lambda(wi)).
    float maskingShadowing(const glm::vec3& wo, const glm::vec3& wi) const {
        return 1.0f / (1.0f + lambda(wo) + lambda(wi));
    }
    // f_r without Fresnel (F = 1): D G2 / (4 cos_o cos_i); 0 unless both are above the surface.
    float reflectance(const glm::vec3& wo, const glm::vec3& wi) const;

    // A microfacet normal drawn from the distribution of normals visible from wo,
    // D_wo(h) = G1(wo) max(0, wo.h) D(h) / wo.z (Heitz, "Sampling the GGX Distribution of
    // Visible Normals", JCGT 2018).
    glm::vec3 sampleVisibleNormal(const glm::vec3& wo, glm::vec2 u) const;
    // Density of wi = reflect(wo, h) with h from sampleVisibleNormal: D_wo(h) / (4 wo.h).
    float reflectionPdf(const glm::vec3& wo, const glm::vec3& wi) const;

private:
    float alpha_;
};

// Directional albedos of the GGX lobe, the input of the energy-consistent layering
// (material.h). For Schlick's F the albedo is linear in F0:
//   E_F(mu) = F0 E1(mu) + (1 - F0) E5(mu),
// E1 = integral of f_r(F = 1) cos d(wi)  and  E5 = the same with F = (1 - wo.h)^5, mu = cos(theta_o).
// Both are tabulated once per material by quadrature over the visible-normal sampler (whose
// weight f cos / pdf = G2 / G1(wo) is smooth) at mu = (i / 127)^2, dense toward grazing where
// they change fastest, and interpolated linearly in mu.
class GgxAlbedoTable {
public:
    explicit GgxAlbedoTable(const GgxDistribution& distribution);

    // E1 and E5 at mu = cos(theta_o) in [0, 1].
    glm::vec2 albedo(float mu) const;
    // Cosine-weighted hemispherical averages 2 * integral of E(mu) mu dmu, of the interpolated
    // table (so the layering's normalisation matches the table it divides).
    glm::vec2 averageAlbedo() const { return average_; }

private:
    static constexpr int kEntries = 128;
    static float entryCosine(int entry);  // mu of table entry `entry`
    std::array<glm::vec2, kEntries> table_{};
    glm::vec2 average_{0.0f};
};

}  // namespace strata
