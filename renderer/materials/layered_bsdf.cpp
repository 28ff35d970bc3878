#include "materials/layered_bsdf.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "util/constants.h"
#include "sampling/hemisphere.h"

namespace strata {
namespace {

bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }
float average(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }

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

glm::vec3 LayeredBsdf::tabulatedAlbedo(const glm::vec3& wo) const {
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
    const float specular = average(e);
    const float diffuse = average(diffuse_ * (glm::vec3(1.0f) - e));
    // Both lobes keep some probability so that the mixture's density covers each lobe.
    return std::clamp(specular / std::max(specular + diffuse, 1e-6f), 0.05f, 0.95f);
}

std::optional<BsdfSample> LayeredBsdf::sample(const glm::vec3& wo, glm::vec2 u,
                                              float lobeChoice) const {
    const float pSpecular = specularProbability(wo);
    if (pSpecular == 0.0f) {
        // Pure Lambertian: f cos / pdf = (Kd / pi) cos / (cos / pi) is Kd exactly, with no
        // rounding (the cosine-sampled furnace then has zero variance, notes section 5.1).
        const glm::vec3 wi = sampleCosineHemisphere(u);
        return BsdfSample{wi, cosineHemispherePdf(wi), diffuse_};
    }
    glm::vec3 wi;
    if (lobeChoice < pSpecular) {
        const auto specular = sampleSpecular(wo, u);
        if (!specular) return std::nullopt;
        wi = *specular;
    } else {
        wi = sampleCosineHemisphere(u);
    }
    const float density = pdf(wo, wi);
    if (!(density > 0.0f) || wi.z <= 0.0f) return std::nullopt;
    return BsdfSample{wi, density, evaluate(wo, wi) * (wi.z / density)};
}

float LayeredBsdf::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float pSpecular = specularProbability(wo);
    float density = (1.0f - pSpecular) * cosineHemispherePdf(wi);
    if (pSpecular > 0.0f) density += pSpecular * specularPdf(wo, wi);
    return density;
}

std::optional<glm::vec3> LayeredBsdf::sampleSpecular(const glm::vec3& wo, glm::vec2 u) const {
    const glm::vec3 h = lobe_->distribution.sampleVisibleNormal(wo, u);
    const glm::vec3 wi = 2.0f * glm::dot(wo, h) * h - wo;
    if (wi.z <= 0.0f) return std::nullopt;
    return glm::normalize(wi);
}

float LayeredBsdf::specularPdf(const glm::vec3& wo, const glm::vec3& wi) const {
    return lobe_->distribution.reflectionPdf(wo, wi);
}

}  // namespace strata
