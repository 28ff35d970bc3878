#pragma once
// The Lambertian BRDF f_r = Kd / pi alone: the paper's reflectance model, and the whole material
// of a scene without specular layers. It offers LayeredBsdf's interface (evaluate, sample, pdf),
// so the integrator and the direction samplers are compiled once for each: a purely Lambertian
// scene runs a path with no trace of the microfacet code (issue "skip what a scene doesn't need").
#include <optional>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sampling/hemisphere.h"
#include "materials/material.h"

namespace strata {

class LambertianBsdf {
public:
    explicit LambertianBsdf(const Material& material)
        : albedo_(material.diffuse), reflectance_(material.diffuse / kPi) {}

    bool isBlack() const { return albedo_.x == 0.0f && albedo_.y == 0.0f && albedo_.z == 0.0f; }

    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi) const {
        return wo.z > 0.0f && wi.z > 0.0f ? reflectance_ : glm::vec3(0.0f);
    }
    // Cosine sampling: the weight f cos / pdf is exactly Kd.
    std::optional<BsdfSample> sample(const glm::vec3& wo, glm::vec2 u, float /*lobeChoice*/) const {
        if (!(wo.z > 0.0f)) return std::nullopt;
        const glm::vec3 wi = sampleCosineHemisphere(u);
        return BsdfSample{wi, cosineHemispherePdf(wi), albedo_};
    }
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        return wo.z > 0.0f ? cosineHemispherePdf(wi) : 0.0f;
    }

private:
    glm::vec3 albedo_;       // Kd
    glm::vec3 reflectance_;  // Kd / pi
};

// Whether every material of the scene is Lambertian (no specular layer).
bool allLambertian(const std::vector<Material>& materials);

}  // namespace strata
