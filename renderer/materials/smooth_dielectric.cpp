#include "materials/smooth_dielectric.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include "materials/fresnel.h"

namespace strata {

SmoothDielectric::SmoothDielectric(float eta, const glm::vec3& transmittance)
    : eta_(eta), filter_(glm::sqrt(glm::max(transmittance, glm::vec3(0.0f)))) {}

std::optional<BsdfSample> SmoothDielectric::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                                   TransportMode mode) const {
    if (wo.z == 0.0f) return std::nullopt;
    const float reflectance = dielectricFresnel(wo.z, eta_);
    if (numbers.lobeChoice < reflectance) {
        const glm::vec3 wi = reflectLocal(wo);
        return BsdfSample{wi, glm::vec3(reflectance / std::abs(wi.z)), reflectance, glm::vec3(1.0f),
                          kReflection | kSpecular, 1.0f, -1};
    }
    // Refraction: the index crossed into over the one left, the normal turned to wo's side.
    const bool entering = wo.z > 0.0f;
    const float etaCrossed = entering ? eta_ : 1.0f / eta_;
    const auto wi = refract(wo, glm::vec3(0.0f, 0.0f, entering ? 1.0f : -1.0f), etaCrossed);
    if (!wi) return std::nullopt;  // only where the reflectance is 1, so never chosen
    glm::vec3 weight = filter_;
    if (mode == TransportMode::Radiance) weight /= etaCrossed * etaCrossed;
    const float transmittance = 1.0f - reflectance;
    return BsdfSample{*wi, weight * (transmittance / std::abs(wi->z)), transmittance, weight,
                      kTransmission | kSpecular, etaCrossed, -1};
}

}  // namespace strata
