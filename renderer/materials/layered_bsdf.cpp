#include "materials/layered_bsdf.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "materials/fresnel.h"
#include "util/components.h"
#include "util/constants.h"

namespace strata {
namespace {

// A reflection's sample, built field by field in the optional that returns it: a BsdfSample made
// first and then moved into the optional is copied through the stack in 16-byte words over its
// fields' narrower stores, a load that store-to-load forwarding cannot serve (perf annotate put
// 13% of the bounce loop's time there, without next-event estimation).
std::optional<BsdfSample> reflectionSample(const glm::vec3& wi, const glm::vec3& f, float pdf, const glm::vec3& weight,
                                           BsdfFlags lobe, int stratum) {
    std::optional<BsdfSample> sample(std::in_place);
    sample->wi = wi;
    sample->f = f;
    sample->pdf = pdf;
    sample->weight = weight;
    sample->flags = lobe;
    sample->eta = 1.0f;
    sample->stratum = stratum;
    return sample;
}

}  // namespace

LayeredBsdf::LayeredBsdf(const glm::vec3& diffuse, const glm::vec3& specular,
                         const SpecularLobe* lobe)
    : diffuse_(diffuse),
      specular_(specular),
      hasDiffuse_(!isZero(diffuse)),
      hasSpecular_(!isZero(specular)),
      lobe_(lobe) {
    if (hasSpecular_) {
        const glm::vec2 average = lobe_->albedo.averageAlbedo();
        const glm::vec3 averageF = specular_ * average.x + (glm::vec3(1.0f) - specular_) * average.y;
        diffuseNormalisation_ = diffuse_ / (kPi * glm::max(glm::vec3(1.0f) - averageF, 1e-6f));
    } else {
        diffuseNormalisation_ = diffuse_ / kPi;
    }
}

glm::vec3 LayeredBsdf::specularAlbedo(float mu) const {
    if (!hasSpecular_) return glm::vec3(0.0f);
    const glm::vec2 e = lobe_->albedo.albedo(mu);
    return specular_ * e.x + (glm::vec3(1.0f) - specular_) * e.y;
}

glm::vec3 LayeredBsdf::albedo(const glm::vec3& wo) const {
    const glm::vec3 e = specularAlbedo(wo.z);
    return e + diffuse_ * (glm::vec3(1.0f) - e);
}

glm::vec3 LayeredBsdf::evaluateLayered(const glm::vec3& wo, const glm::vec3& wi) const {
    glm::vec3 f(0.0f);
    if (hasDiffuse_) {
        f = diffuseNormalisation_ * (glm::vec3(1.0f) - specularAlbedo(wo.z)) *
            (glm::vec3(1.0f) - specularAlbedo(wi.z));
    }
    const glm::vec3 h = glm::normalize(wo + wi);
    return f + schlickFresnel(specular_, glm::dot(wo, h)) * lobe_->distribution.reflectance(wo, wi);
}

float LayeredBsdf::specularProbability(const glm::vec3& wo) const {
    if (!hasSpecular_) return 0.0f;
    if (!hasDiffuse_) return 1.0f;
    const glm::vec3 e = specularAlbedo(wo.z);
    const float specular = meanComponent(e);
    const float diffuse = meanComponent(diffuse_ * (glm::vec3(1.0f) - e));
    // Both lobes keep some probability so that the mixture's density covers each lobe.
    return std::clamp(specular / std::max(specular + diffuse, 1e-6f), 0.05f, 0.95f);
}

std::optional<BsdfSample> LayeredBsdf::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                              TransportMode) const {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const float pSpecular = specularProbability(wo);
    if (pSpecular == 0.0f) {
        // Lambertian: f cos / pdf is f times the warp's closed-form cos / pdf, with no division
        // by the density (so cosine sampling's weight is the same for every direction, and the
        // cosine-sampled furnace has zero variance, notes section 5.1).
        const WarpedDirection warped = warpDiffuse(numbers.diffuse);
        const glm::vec3& wi = warped.direction;
        if (!(wi.z > 0.0f)) return std::nullopt;
        return reflectionSample(wi, diffuseNormalisation_, wi.z / warped.cosOverPdf,
                                diffuseNormalisation_ * warped.cosOverPdf, kReflection | kDiffuse,
                                numbers.diffuse.stratum);
    }
    if (!hasDiffuse_) return conductorSample(wo, numbers.lobePoint);
    glm::vec3 wi;
    BsdfFlags lobe = kReflection | kDiffuse;
    int stratum = numbers.diffuse.stratum;
    if (numbers.lobeChoice < pSpecular) {
        const auto specular = sampleSpecular(wo, numbers.lobePoint);
        if (!specular) return std::nullopt;
        wi = specular->wi;
        lobe = kReflection | kGlossy;
        stratum = -1;  // the specular lobe's direction lies in no particular stratum
    } else {
        wi = warpDiffuse(numbers.diffuse).direction;
    }
    float density = (1.0f - pSpecular) * diffuseWarpPdf(numbers.diffuse.warp, wi);
    density += pSpecular * lobe_->distribution.reflectionPdf(wo, wi);
    if (!(density > 0.0f) || wi.z <= 0.0f) return std::nullopt;
    const glm::vec3 f = evaluate(wo, wi);
    return reflectionSample(wi, f, density, f * (wi.z / density), lobe, stratum);
}

float LayeredBsdf::pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float pSpecular = specularProbability(wo);
    float density = (1.0f - pSpecular) * diffuseWarpPdf(warp, wi);
    if (pSpecular > 0.0f) density += pSpecular * lobe_->distribution.reflectionPdf(wo, wi);
    return density;
}

std::optional<BsdfSample> LayeredBsdf::conductorSample(const glm::vec3& wo, glm::vec2 u) const {
    const auto specular = sampleSpecular(wo, u);
    if (!specular) return std::nullopt;
    const GgxDistribution& ggx = lobe_->distribution;
    const glm::vec3& wi = specular->wi;
    // With 1 / G1(wo) = 1 + Lambda(wo) and 1 / G2 = 1 + Lambda(wo) + Lambda(wi):
    //   pdf = G1(wo) D(h) / (4 wo.z),  f = F D G2 / (4 wo.z wi.z),  f wi.z / pdf = F G2 / G1(wo).
    const float inverseMasking = 1.0f + ggx.lambda(wo);
    const float inverseShadowing = inverseMasking + ggx.lambda(wi);
    const float quarterDensity = ggx.density(specular->h) / (4.0f * wo.z);
    const float pdf = quarterDensity / inverseMasking;
    if (!(pdf > 0.0f)) return std::nullopt;
    const glm::vec3 fresnel = schlickFresnel(specular_, specular->cosOH);
    return reflectionSample(wi, fresnel * (quarterDensity / (inverseShadowing * wi.z)), pdf,
                            fresnel * (inverseMasking / inverseShadowing), kReflection | kGlossy, -1);
}

std::optional<LayeredBsdf::SpecularDirection> LayeredBsdf::sampleSpecular(const glm::vec3& wo, glm::vec2 u) const {
    const glm::vec3 h = lobe_->distribution.sampleVisibleNormal(wo, u);
    const float cosOH = glm::dot(wo, h);
    const glm::vec3 wi = 2.0f * cosOH * h - wo;
    if (wi.z <= 0.0f) return std::nullopt;
    return SpecularDirection{glm::normalize(wi), h, cosOH};
}

}  // namespace strata
