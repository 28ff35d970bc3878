#pragma once
// An emitting triangle: radiance Le leaves its front (counter-clockwise) side only, uniformly in
// every direction. Sampled uniformly by area, so a direction's solid-angle density is
// d^2 / (A cos(theta_light)).
//
// A textured emitter (a material with an emission texture or a cut-out, material.h) takes its
// radiance at each point from the material at that point's UV, both where a light sample lands
// and where a ray hits it, so the estimator stays unbiased; its power, by which lights are
// chosen, uses Ke's mean over the emission texture, positive wherever the radiance can be.
#include <array>
#include <glm/vec2.hpp>

#include "lights/light.h"
#include "materials/material.h"

namespace strata {

class AreaLight final : public Light {
public:
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& radiance);
    // A textured emitter: radiance material.emissionAt(uv), `uvs` its corners' coordinates;
    // `material` outlives the light.
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const Material& material,
              const std::array<glm::vec2, 3>& uvs);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 power() const override;

    float area() const { return area_; }

private:
    // Le at barycentrics (b1, b2) of vertices 1 and 2.
    glm::vec3 radianceAt(float b1, float b2) const {
        if (!textured_) return radiance_;
        return textured_->emissionAt((1.0f - b1 - b2) * uvs_[0] + b1 * uvs_[1] + b2 * uvs_[2]);
    }

    glm::vec3 p0_, edge1_, edge2_;
    glm::vec3 normal_;  // unit, the emitting side's
    glm::vec3 radiance_;
    float area_;
    const Material* textured_ = nullptr;
    std::array<glm::vec2, 3> uvs_{};
};

}  // namespace strata
