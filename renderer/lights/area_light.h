#pragma once
// An emitting triangle: radiance Le leaves its front (counter-clockwise) side only, uniformly in
// every direction. Sampled uniformly by area, so a direction's solid-angle density is
// d^2 / (A cos(theta_light)).
#include "lights/light.h"

namespace strata {

class AreaLight final : public Light {
public:
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& radiance);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 power() const override;

    float area() const { return area_; }

private:
    glm::vec3 p0_, edge1_, edge2_;
    glm::vec3 normal_;  // unit, the emitting side's
    glm::vec3 radiance_;
    float area_;
};

}  // namespace strata
