#include "lights/directional_light.h"

#include <limits>

#include "util/constants.h"

namespace strata {

std::optional<LightSample> DirectionalLight::sample(const glm::vec3& /*point*/, glm::vec2 /*u*/) const {
    return LightSample{-direction, std::numeric_limits<float>::infinity(), irradiance, 0.0f, false};
}

glm::vec3 DirectionalLight::power() const { return kPi * sceneRadius * sceneRadius * irradiance; }

}  // namespace strata
