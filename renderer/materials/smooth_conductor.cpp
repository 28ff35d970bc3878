#include "materials/smooth_conductor.h"

#include "materials/fresnel.h"

namespace strata {

std::optional<BsdfSample> SmoothConductor::sample(const glm::vec3& wo, const BsdfNumbers&, TransportMode) const {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const glm::vec3 reflectance = albedo(wo);
    return BsdfSample{reflectLocal(wo), reflectance / wo.z, 1.0f, reflectance, kReflection | kSpecular, 1.0f, -1};
}

glm::vec3 SmoothConductor::albedo(const glm::vec3& wo) const { return schlickFresnel(f0_, wo.z); }

}  // namespace strata
