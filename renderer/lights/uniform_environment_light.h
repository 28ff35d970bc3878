#pragma once
// An environment of the same radiance L from every direction (the uniform sky of notes section
// 5.3). Next-event estimation never samples it: by MIS compensation (environment_map.h) a sky
// with nothing above its mean is left wholly to the BSDF's samples, which under it sample the
// integrand's own shape where the BSDF is Lambertian. A uniform light sample over the sphere
// would spend a shadow ray per bounce (half of them below the surface) and, weighed by MIS
// against the BSDF's samples, only add variance to them.
#include "lights/light.h"

namespace strata {

class UniformEnvironmentLight final : public Light {
public:
    // `sceneRadius`: the scene's bounding sphere, through which the light's power flows.
    UniformEnvironmentLight(const glm::vec3& radiance, float sceneRadius);

    // Nothing: the light is not sampled (above).
    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    // 0 for every direction: no light sample draws one.
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    // L for any ray that left the scene (the only rays that reach a light at infinity).
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    // pi r^2 * 4 pi * L, as pbrt-v4 counts the power an infinite light sends into the scene.
    glm::vec3 power() const override;
    glm::vec3 sampledPower() const override { return glm::vec3(0.0f); }

private:
    glm::vec3 radiance_;
    float sceneRadius_;
};

}  // namespace strata
