#pragma once
// An environment of the same radiance L from every direction (the uniform sky of notes section
// 5.3). Sampled uniformly over the sphere, pdf 1 / (4 pi): the interface gives the light no
// surface normal to aim a cosine-weighted sample by, and MIS with the direction sampler covers
// the half of the sphere a sample below the surface wastes.
#include "lights/light.h"

namespace strata {

class UniformEnvironmentLight final : public Light {
public:
    // `sceneRadius`: the scene's bounding sphere, through which the light's power flows.
    UniformEnvironmentLight(const glm::vec3& radiance, float sceneRadius);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    // L for any ray that left the scene (the only rays that reach a light at infinity).
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    // pi r^2 * 4 pi * L, as pbrt-v4 counts the power an infinite light sends into the scene.
    glm::vec3 power() const override;

private:
    glm::vec3 radiance_;
    float sceneRadius_;
};

}  // namespace strata
