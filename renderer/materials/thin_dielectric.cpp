#include "materials/thin_dielectric.h"

#include <cmath>

#include "materials/fresnel.h"

namespace strata {

float ThinDielectric::reflectance(float cosThetaO) const {
    const float r = dielectricFresnel(std::abs(cosThetaO), eta_);
    const float t = 1.0f - r;
    return r < 1.0f ? r + t * t * r / (1.0f - r * r) : 1.0f;
}

std::optional<BsdfSample> ThinDielectric::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                                 TransportMode) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float r = reflectance(wo.z);
    const float cosine = std::abs(wo.z);
    if (numbers.lobeChoice < r) {
        return BsdfSample{reflectLocal(wo), glm::vec3(r / cosine), r, glm::vec3(1.0f),
                          kReflection | kSpecular, 1.0f, -1};
    }
    const float t = 1.0f - r;
    return BsdfSample{-wo, transmittance_ * (t / cosine), t, transmittance_, kTransmission | kSpecular, 1.0f, -1};
}

}  // namespace strata
