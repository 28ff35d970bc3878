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
// Directions are in the local frame of the shading point, normal +z; wo is the direction toward
// the viewer (wo.z > 0). A LayeredBsdf is a small value the integrator builds at every hit
// (MaterialTable::bsdf); what is costly to compute, the GGX albedo tables, lives in a
// SpecularLobe shared by every hit and material of the same roughness.
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "materials/microfacet.h"

namespace strata {

struct BsdfSample {
    glm::vec3 direction;  // wi, unit, in the local frame
    float pdf;            // solid-angle density of wi under sample(), for MIS
    glm::vec3 weight;     // f_r(wo, wi) cos(theta_i) / pdf
};

// A GGX lobe of one roughness and its directional albedo tables.
struct SpecularLobe {
    explicit SpecularLobe(float alpha) : distribution(alpha), albedo(distribution) {}
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
    // The specular layer's lobe (null when the BSDF was made without one).
    const SpecularLobe* lobe() const { return lobe_; }

    // f_r(wo, wi); 0 when wi is below the surface.
    // Inline for the Lambertian case, which every hemisphere sampler's weight calls.
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi) const {
        if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
        return hasSpecular_ ? evaluateLayered(wo, wi) : diffuseNormalisation_;
    }
    // Importance sampling of f_r cos: a lobe is chosen with `lobeChoice` in [0,1) (by the lobes'
    // albedos at wo), then the diffuse lobe is sampled by cosine, the specular one by GGX visible
    // normals. Empty when the sampled direction falls below the surface (the sample counts, with
    // weight 0).
    std::optional<BsdfSample> sample(const glm::vec3& wo, glm::vec2 u, float lobeChoice) const;
    // The probability that sample() takes the specular lobe at wo: lobeChoice below it does.
    float specularProbability(const glm::vec3& wo) const;
    // Density of sample()'s direction wi, the mixture of both lobes' densities.
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    // The specular lobe alone, for samplers that take the diffuse layer's direction elsewhere:
    // a direction by GGX visible normals (empty when it falls below the surface) and its density.
    // Only for a BSDF with a specular layer.
    std::optional<glm::vec3> sampleSpecular(const glm::vec3& wo, glm::vec2 u) const;
    float specularPdf(const glm::vec3& wo, const glm::vec3& wi) const;

    // The directional albedo the layering assigns at wo: E_F(mu_o) + Kd (1 - E_F(mu_o)), from the
    // tables (the white-furnace test integrates evaluate() to check it).
    glm::vec3 tabulatedAlbedo(const glm::vec3& wo) const;

private:
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
