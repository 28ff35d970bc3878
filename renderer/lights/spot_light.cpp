#include "lights/spot_light.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "util/constants.h"

namespace strata {

SpotLight::SpotLight(const glm::vec3& position, const glm::vec3& axis, const glm::vec3& intensity, float innerAngle,
                     float outerAngle)
    : position(position),
      axis(axis),
      intensity(intensity),
      cosOuter_(std::cos(outerAngle)),
      ramp_(std::max(std::cos(innerAngle) - std::cos(outerAngle), 1e-3f)) {}

float SpotLight::falloff(float cosTheta) const {
    const float t = std::clamp((cosTheta - cosOuter_) / ramp_, 0.0f, 1.0f);
    return t * t;
}

std::optional<LightSample> SpotLight::sample(const glm::vec3& point, glm::vec2 /*u*/) const {
    const glm::vec3 toLight = position - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 direction = toLight / distance;
    const float share = falloff(-glm::dot(direction, axis));
    if (!(share > 0.0f)) return std::nullopt;
    return LightSample{direction, distance, intensity * (share / distanceSquared), 0.0f, false};
}

glm::vec3 SpotLight::power() const {
    // Over cos theta in [cos outer, 1]: the ramp's t^2 up to min(1, cos outer + w), 1 above it.
    const double top = std::min(1.0, static_cast<double>(cosOuter_) + ramp_);
    const double rise = top - cosOuter_;
    const double integral = (1.0 - top) + rise * rise * rise / (3.0 * static_cast<double>(ramp_) * ramp_);
    return intensity * static_cast<float>(2.0 * kPi * integral);
}

}  // namespace strata
