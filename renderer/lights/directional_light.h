#pragma once
// A directional light: parallel light from infinitely far away (the sun, glTF's "directional"
// light), of irradiance E (W/m^2) on a surface facing it. A delta light, reached only by
// next-event estimation; its shadow rays run to infinity.
#include "lights/light.h"

namespace strata {

class DirectionalLight final : public Light {
public:
    // `direction` (unit): the way the light travels. `sceneRadius`: the radius of a sphere that
    // holds the scene, which its power needs (SceneLights knows it; a loader gives 0).
    DirectionalLight(const glm::vec3& direction, const glm::vec3& irradiance, float sceneRadius = 0.0f)
        : direction(direction), irradiance(irradiance), sceneRadius(sceneRadius) {}

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3&, const glm::vec3&, const LightHit&) const override { return 0.0f; }
    glm::vec3 emitted(const glm::vec3&, const LightHit&) const override { return glm::vec3(0.0f); }
    // The power the scene can receive: E through the scene's cross-section, pi r^2 E (pbrt-v4's
    // DistantLight does the same), so that LightSampler weighs it against the scene's other lights.
    glm::vec3 power() const override;
    bool isDelta() const override { return true; }

    // The light as a scene describes it.
    glm::vec3 direction;
    glm::vec3 irradiance;
    float sceneRadius;
};

}  // namespace strata
