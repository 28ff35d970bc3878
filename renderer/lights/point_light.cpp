#include "lights/point_light.h"

#include "util/constants.h"

namespace strata {

std::optional<LightSample> PointLight::sample(const glm::vec3& point, glm::vec2 /*u*/) const {
    return pointSourceSample(position, intensity, point);
}

glm::vec3 PointLight::power() const { return 4.0f * kPi * intensity; }

}  // namespace strata
