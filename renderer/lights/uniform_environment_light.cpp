#include "lights/uniform_environment_light.h"

#include <limits>

#include "sampling/hemisphere.h"

namespace strata {

UniformEnvironmentLight::UniformEnvironmentLight(const glm::vec3& radiance, float sceneRadius)
    : radiance_(radiance), sceneRadius_(sceneRadius) {}

std::optional<LightSample> UniformEnvironmentLight::sample(const glm::vec3& /*point*/, glm::vec2 u) const {
    return LightSample{sampleUniformSphere(u), std::numeric_limits<float>::infinity(), radiance_,
                       1.0f / kSphereSolidAngle, false};
}

float UniformEnvironmentLight::pdf(const glm::vec3&, const glm::vec3&, const LightHit&) const {
    return 1.0f / kSphereSolidAngle;
}

glm::vec3 UniformEnvironmentLight::emitted(const glm::vec3&, const LightHit&) const { return radiance_; }

glm::vec3 UniformEnvironmentLight::power() const {
    return kPi * sceneRadius_ * sceneRadius_ * kSphereSolidAngle * radiance_;
}

}  // namespace strata
