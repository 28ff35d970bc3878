#include "lights/uniform_environment_light.h"

#include "sampling/hemisphere.h"

namespace strata {

UniformEnvironmentLight::UniformEnvironmentLight(const glm::vec3& radiance, float sceneRadius)
    : radiance_(radiance), sceneRadius_(sceneRadius) {}

std::optional<LightSample> UniformEnvironmentLight::sample(const glm::vec3&, glm::vec2) const {
    return std::nullopt;
}

float UniformEnvironmentLight::pdf(const glm::vec3&, const glm::vec3&, const LightHit&) const { return 0.0f; }

glm::vec3 UniformEnvironmentLight::emitted(const glm::vec3&, const LightHit&) const { return radiance_; }

glm::vec3 UniformEnvironmentLight::power() const {
    return kPi * sceneRadius_ * sceneRadius_ * kSphereSolidAngle * radiance_;
}

}  // namespace strata
