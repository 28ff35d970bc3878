#include "materials/rough_dielectric.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "materials/fresnel.h"

namespace strata {
namespace {
float square(float x) { return x * x; }
}  // namespace

RoughDielectric::RoughDielectric(float eta, float alpha, const glm::vec3& transmittance)
    : eta_(eta), distribution_(alpha), filter_(glm::sqrt(glm::max(transmittance, glm::vec3(0.0f)))) {}

float RoughDielectric::visibleNormalPdf(const glm::vec3& w, const glm::vec3& m) const {
    return distribution_.masking(w) * distribution_.density(m) * std::abs(glm::dot(w, m)) / std::abs(w.z);
}

std::optional<RoughDielectric::Microfacet> RoughDielectric::microfacetBetween(const glm::vec3& wo,
                                                                              const glm::vec3& wi) const {
    if (wo.z == 0.0f || wi.z == 0.0f) return std::nullopt;
    const bool reflection = wo.z * wi.z > 0.0f;
    const float etaCrossed = reflection ? 1.0f : (wo.z > 0.0f ? eta_ : 1.0f / eta_);
    glm::vec3 m = wi * etaCrossed + wo;
    const float length2 = glm::dot(m, m);
    if (!(length2 > 0.0f)) return std::nullopt;
    m /= std::sqrt(length2);
    if (m.z < 0.0f) m = -m;
    // A microfacet seen from the back by either direction scatters nothing between them.
    if (glm::dot(m, wi) * wi.z <= 0.0f || glm::dot(m, wo) * wo.z <= 0.0f) return std::nullopt;
    return Microfacet{m, etaCrossed, reflection};
}

glm::vec3 RoughDielectric::evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode) const {
    const auto facet = microfacetBetween(wo, wi);
    if (!facet) return glm::vec3(0.0f);
    const glm::vec3& m = facet->normal;
    const float cosOM = glm::dot(wo, m);
    const float fresnel = dielectricFresnel(cosOM, eta_);
    const float dg = distribution_.density(m) * distribution_.maskingShadowing(wo, wi);
    if (facet->reflection) return glm::vec3(dg * fresnel / std::abs(4.0f * wo.z * wi.z));
    const float cosIM = glm::dot(wi, m);
    const float denominator = square(cosIM + cosOM / facet->etaCrossed) * wo.z * wi.z;
    float ft = dg * (1.0f - fresnel) * std::abs(cosIM * cosOM / denominator);
    if (mode == TransportMode::Radiance) ft /= square(facet->etaCrossed);
    return filter_ * ft;
}

float RoughDielectric::pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp) const {
    const auto facet = microfacetBetween(wo, wi);
    if (!facet) return 0.0f;
    const glm::vec3& m = facet->normal;
    const float cosOM = glm::dot(wo, m);
    const float fresnel = dielectricFresnel(cosOM, eta_);
    const float normalPdf = visibleNormalPdf(wo, m);
    if (facet->reflection) return normalPdf / (4.0f * std::abs(cosOM)) * fresnel;
    const float cosIM = glm::dot(wi, m);
    // The Jacobian of the refracted direction's map to the microfacet normal.
    const float dmDwi = std::abs(cosIM) / square(cosIM + cosOM / facet->etaCrossed);
    return normalPdf * dmDwi * (1.0f - fresnel);
}

std::optional<BsdfSample> RoughDielectric::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                                  TransportMode mode) const {
    if (wo.z == 0.0f) return std::nullopt;
    // The visible normals of the side wo is on are those the flipped view sees from above.
    const glm::vec3 m = distribution_.sampleVisibleNormal(wo.z > 0.0f ? wo : -wo, numbers.lobePoint);
    const float cosOM = glm::dot(wo, m);
    if (cosOM == 0.0f) return std::nullopt;
    const float fresnel = dielectricFresnel(cosOM, eta_);
    glm::vec3 wi;
    float etaCrossed = 1.0f;
    BsdfFlags lobe = kReflection | kGlossy;
    glm::vec3 weight(1.0f);
    if (numbers.lobeChoice < fresnel) {
        wi = reflect(wo, m);
        if (wo.z * wi.z <= 0.0f) return std::nullopt;
    } else {
        const bool entering = cosOM > 0.0f;
        etaCrossed = entering ? eta_ : 1.0f / eta_;
        const auto refracted = refract(wo, entering ? m : -m, etaCrossed);
        if (!refracted || wo.z * refracted->z >= 0.0f) return std::nullopt;
        wi = *refracted;
        lobe = kTransmission | kGlossy;
        weight = filter_;
        if (mode == TransportMode::Radiance) weight /= square(etaCrossed);
    }
    // f |cos_i| / pdf: D, the Fresnel factor, the Jacobian and cosines cancel, G2 / G1(wo) stays.
    weight *= distribution_.maskingShadowing(wo, wi) / distribution_.masking(wo);
    const float density = pdf(wo, wi);
    if (!(density > 0.0f)) return std::nullopt;
    return BsdfSample{wi, weight * (density / std::abs(wi.z)), density, weight, lobe, etaCrossed, -1};
}

}  // namespace strata
