#pragma once
// An isotropic point light of intensity I (W/sr): a delta light, reached only by next-event
// estimation, giving I / r^2 at distance r.
#include <cmath>
#include <glm/geometric.hpp>

#include "lights/light.h"

namespace strata {

// The light that a point source of `intensity` at `position` gives `point`: I / r^2 along the
// unit direction to it; none where the two coincide. Point and spot lights share it.
inline std::optional<LightSample> pointSourceSample(const glm::vec3& position, const glm::vec3& intensity,
                                                    const glm::vec3& point) {
    const glm::vec3 toLight = position - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const float distance = std::sqrt(distanceSquared);
    return LightSample{toLight / distance, distance, intensity / distanceSquared, 0.0f, false};
}

class PointLight final : public Light {
public:
    PointLight(const glm::vec3& position, const glm::vec3& intensity)
        : position(position), intensity(intensity) {}

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3&, const glm::vec3&, const LightHit&) const override { return 0.0f; }
    glm::vec3 emitted(const glm::vec3&, const LightHit&) const override { return glm::vec3(0.0f); }
    glm::vec3 power() const override;
    bool isDelta() const override { return true; }

    // The light as a scene describes it.
    glm::vec3 position;
    glm::vec3 intensity;
};

}  // namespace strata
