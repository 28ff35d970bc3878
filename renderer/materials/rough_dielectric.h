#pragma once
// A rough interface between two dielectrics (frosted glass): the microfacet model of reflection
// and refraction of Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", with the GGX distribution and height-correlated Smith masking of the GGX layer
// (microfacet.h; alpha = roughness^2). For a pair of directions on one side of the surface the
// microfacet normal is the half vector wo + wi; across the surface it is the generalised half
// vector eta' wi + wo (eta' the index of wi's side over wo's), and
//   f_r = D G2 F / (4 |cos_o cos_i|),
//   f_t = D G2 (1 - F) |wi.m| |wo.m| / (|cos_o cos_i| (wi.m + wo.m / eta')^2)   (/ eta'^2 for radiance),
// F being the exact dielectric Fresnel reflectance at the microfacet. Sampling draws a microfacet
// normal from the normals visible from wo (Heitz 2018), then reflects with probability F and
// refracts otherwise, so the weight is G2 / G1(wo) (times the filter and 1/eta'^2 across).
// `eta` and the transmission filter mean what they mean for the smooth dielectric
// (smooth_dielectric.h). A single-scattering model: light that would scatter between microfacets
// more than once is lost, which is what the furnace test measures.
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/microfacet.h"

namespace strata {

class RoughDielectric {
public:
    RoughDielectric(float eta, float alpha, const glm::vec3& transmittance);

    bool isBlack() const { return false; }
    BsdfFlags flags() const { return kReflection | kTransmission | kGlossy; }
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi,
                       TransportMode mode = TransportMode::Radiance) const;
    // A microfacet normal from numbers.lobePoint, reflection or refraction by numbers.lobeChoice.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp = DiffuseWarp::Cosine) const;

private:
    // The microfacet normal (z > 0) that scatters wo into wi, with eta' for a refraction (1 for a
    // reflection); empty where no microfacet facing both does.
    struct Microfacet {
        glm::vec3 normal;
        float etaCrossed;
        bool reflection;
    };
    std::optional<Microfacet> microfacetBetween(const glm::vec3& wo, const glm::vec3& wi) const;
    // Density of the microfacet normal m among those visible from w: G1(w) D(m) |w.m| / |w.z|.
    float visibleNormalPdf(const glm::vec3& w, const glm::vec3& m) const;

    float eta_;
    GgxDistribution distribution_;
    glm::vec3 filter_;  // sqrt(Tf), per crossing
};

}  // namespace strata
