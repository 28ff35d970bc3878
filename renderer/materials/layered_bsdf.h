#pragma once
// The reflectance model of a Material (material.h): a Cook-Torrance GGX specular layer (Ks, roughness
// Pr; microfacet.h) over a Lambertian base (Kd), combined so that energy is never created.
//
// Layering (Kelemen & Szirmay-Kalos 2001, "A microfacet based coupled specular-matte BRDF model
// with importance sampling"): the matte term gets the energy the specular lobe does not reflect,
// symmetrically in both directions so the sum stays reciprocal,
//   f_r = f_spec + Kd (1 - E_F(mu_o)) (1 - E_F(mu_i)) / (pi (1 - Eavg_F)),
// where E_F is the specular lobe's directional albedo with its Schlick Fresnel (per channel,
// GgxAlbedoTable) and Eavg_F its cosine-weighted average. The matte term's albedo is then exactly
// Kd (1 - E_F(mu_o)), so the total albedo E_F + Kd (1 - E_F) never exceeds 1 for Kd <= 1.
// Without Ks the model is the Lambertian Kd / pi the paper uses.
//
// The diffuse lobe is sampled by the warp the direction sampler hands it (diffuse_warp.h): the
// paper's strata, uniform or cosine directions; the specular one by GGX visible normals.
//
// Directions are in the local frame of the shading point, normal +z; the model reflects on the
// side above it (wo.z > 0; bsdf.h makes it two-sided). A LayeredBsdf is a small value the
// integrator builds at every hit (MaterialTable::bsdf); what is costly to compute, the GGX albedo
// tables, lives in a SpecularLobe shared by every hit and material of the same roughness.
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/microfacet.h"

namespace strata {

// A GGX lobe of one roughness and its directional albedo tables.
struct SpecularLobe {
    explicit SpecularLobe(float alpha) : distribution(alpha), albedo(distribution) {}
    float alpha() const { return distribution.alpha(); }
    GgxDistribution distribution;
    GgxAlbedoTable albedo;
};

class LayeredBsdf {
public:
    // `lobe` is the specular layer's, needed (and outliving the BSDF) when `specular` is not zero.
    LayeredBsdf(const glm::vec3& diffuse, const glm::vec3& specular, const SpecularLobe* lobe);

    // Whether the material reflects nothing (a path ends there).
    bool isBlack() const { return !hasDiffuse_ && !hasSpecular_; }
    bool hasSpecular() const { return hasSpecular_; }
    BsdfFlags flags() const {
        return static_cast<BsdfFlags>(kReflection | (hasDiffuse_ ? kDiffuse : 0) | (hasSpecular_ ? kGlossy : 0));
    }
    // The specular layer's lobe (null when the BSDF was made without one).
    const SpecularLobe* lobe() const { return lobe_; }

    // f_r(wo, wi); 0 when wi is below the surface. Reflection alone, so the same for radiance
    // and importance. Inline for the Lambertian case, which every light sample calls.
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi,
                       TransportMode = TransportMode::Radiance) const {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        return hasSpecular_ ? evaluateLayered(wo, wi) : diffuseNormalisation_;
    }
    // A direction by the lobes' importance: a lobe is chosen with `numbers.lobeChoice` (by the
    // lobes' albedos at wo), then the diffuse lobe's direction is its warp of numbers.diffuse,
    // the specular one's is drawn from GGX visible normals at numbers.lobePoint. Empty when the
    // direction falls below the surface (the sample counts, with weight 0).
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode = TransportMode::Radiance) const;
    // Density of sample()'s direction wi, the mixture of both lobes' densities, the diffuse one's
    // by `warp`.
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const;

    // The directional albedo the layering assigns at wo: E_F(mu_o) + Kd (1 - E_F(mu_o)), from the
    // tables (the white-furnace test integrates evaluate() to check it).
    glm::vec3 albedo(const glm::vec3& wo) const;

private:
    // The probability that sample() takes the specular lobe at wo: lobeChoice below it does.
    float specularProbability(const glm::vec3& wo) const;
    // The sample of a model without a diffuse base (a conductor): a direction by GGX visible
    // normals, whose weight f cos / pdf is F G2 / G1(wo) in closed form (Heitz 2018),
    // cheaper than working out f and the pdf from the direction, as a mixture must.
    std::optional<BsdfSample> conductorSample(const glm::vec3& wo, glm::vec2 u) const;
    // The specular lobe alone: a direction by GGX visible normals, with the microfacet normal it
    // reflects off and wo's cosine to it (empty when the direction falls below the surface).
    struct SpecularDirection {
        glm::vec3 wi;
        glm::vec3 h;
        float cosOH;
    };
    std::optional<SpecularDirection> sampleSpecular(const glm::vec3& wo, glm::vec2 u) const;
    glm::vec3 specularAlbedo(float mu) const;  // E_F(mu), per channel
    glm::vec3 evaluateLayered(const glm::vec3& wo, const glm::vec3& wi) const;  // both lobes

    glm::vec3 diffuse_;
    glm::vec3 specular_;  // F0 of Schlick's Fresnel
    bool hasDiffuse_;
    bool hasSpecular_;
    const SpecularLobe* lobe_;
    glm::vec3 diffuseNormalisation_{0.0f};  // Kd / (pi (1 - Eavg_F))
};

}  // namespace strata
