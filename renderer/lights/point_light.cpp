#include "lights/point_light.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "util/constants.h"

namespace strata {

std::optional<LightSample> PointLight::sample(const glm::vec3& point, glm::vec2 /*u*/) const {
    const glm::vec3 toLight = position - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const float distance = std::sqrt(distanceSquared);
    return LightSample{toLight / distance, distance, intensity / distanceSquared, 0.0f, false};
}

glm::vec3 PointLight::power() const { return 4.0f * kPi * intensity; }

}  // namespace strata
