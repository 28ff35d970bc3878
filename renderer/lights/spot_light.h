#pragma once
// A spot light (glTF KHR_lights_punctual "spot"): a point light whose intensity I (W/sr) along
// its axis falls off with the angle theta from it, smoothly to zero at the outer cone, as the
// extension's reference implementation ("Inner and Outer Cone Angles") does:
//   I(theta) = I t^2,  t = clamp((cos theta - cos outer) / w, 0, 1),  w = max(cos inner - cos outer, 1e-3).
// A delta light, reached only by next-event estimation, giving I(theta) / r^2 at distance r.
#include "lights/light.h"

namespace strata {

class SpotLight final : public Light {
public:
    // `axis` is the unit direction the light points along; 0 <= inner <= outer <= pi/2 (radians).
    SpotLight(const glm::vec3& position, const glm::vec3& axis, const glm::vec3& intensity, float innerAngle,
              float outerAngle);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3&, const glm::vec3&, const LightHit&) const override { return 0.0f; }
    glm::vec3 emitted(const glm::vec3&, const LightHit&) const override { return glm::vec3(0.0f); }
    // I times the integral of t^2 over the sphere: 2 pi I ((1 - cos outer - w) + w / 3) when the
    // ramp fits below the axis, in closed form either way.
    glm::vec3 power() const override;
    bool isDelta() const override { return true; }

    // The share t^2 of the axis's intensity sent at cos theta from the axis.
    float falloff(float cosTheta) const;

    glm::vec3 position;
    glm::vec3 axis;
    glm::vec3 intensity;

private:
    float cosOuter_;
    float ramp_;  // w above
};

}  // namespace strata
