#include "lights/spot_light.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "lights/point_light.h"
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
    std::optional<LightSample> sample = pointSourceSample(position, intensity, point);
    if (!sample) return std::nullopt;
    const float share = falloff(-glm::dot(sample->direction, axis));
    if (!(share > 0.0f)) return std::nullopt;
    sample->radiance *= share;
    return sample;
}

glm::vec3 SpotLight::power() const {
    // Over cos theta in [cos outer, 1]: the ramp's t^2 up to min(1, cos outer + w), 1 above it.
    const double top = std::min(1.0, static_cast<double>(cosOuter_) + ramp_);
    const double rise = top - cosOuter_;
    const double integral = (1.0 - top) + rise * rise * rise / (3.0 * static_cast<double>(ramp_) * ramp_);
    return intensity * static_cast<float>(2.0 * kPi * integral);
}

}  // namespace strata
