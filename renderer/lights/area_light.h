#pragma once
// An emitting triangle: radiance Le leaves its front (counter-clockwise) side only, uniformly in
// every direction. Seen from a point where it subtends at least `minSphericalSolidAngle`, it is
// sampled uniformly by solid angle (Arvo's map, sampling/spherical_triangle.h), density
// 1 / Omega; otherwise uniformly by area, density d^2 / (A cos(theta_light)). Which of the two
// depends only on the point and the triangle, so sample() and pdf() always agree.
//
// A textured emitter (a material with an emission texture or a coverage, material.h) takes its
// radiance at each point from the material at that point's UV, both where a light sample lands
// and where a ray hits it, so the estimator stays unbiased; its power, by which lights are
// chosen, uses Ke's mean over the emission texture, positive wherever the radiance can be. A
// blended emitter stops a ray with probability opacity (scene/cutout_filter.h), and a ray that
// hits it sees Le: in expectation opacity x Le, which its light samples carry, the shadow ray
// ending short of the light and so not testing it.
#include <array>
#include <glm/vec2.hpp>

#include "lights/light.h"
#include "materials/material.h"
#include "sampling/spherical_triangle.h"

namespace strata {

class AreaLight final : public Light {
public:
    // The solid angle (sr) from which on the triangle is sampled by solid angle. Measured:
    //  - the relative variance per sample of the irradiance estimate Le cos / pdf, by area and
    //    by solid angle, for a triangle of the Cornell box's 130 x 105 mm light seen by 400
    //    receivers per band (random normals facing it): 0.030 / 0.027 at 1e-3 sr, 0.26 / 0.16
    //    at 0.03-0.1 sr, 0.47 / 0.29 at 0.1-0.2, 1.0 / 0.41 at 0.2-0.4, 9.9 / 0.48 at 0.4-0.7,
    //    62 / 0.80 at 1-2 sr;
    //  - a solid-angle sample and its pdf() cost about 110 ns more than area sampling's, some 40%
    //    of a path vertex in a scene as small as the Cornell box (32 triangles). There (256^2,
    //    depth 9, NEE, strata24, relMSE x CPU seconds against area sampling alone): every light
    //    by solid angle (down to 1e-7 sr) cut the variance per path by 3% and lost 27%; from
    //    0.02 sr on, 3% less variance and 16% lost; from 0.1 sr on, even.
    // From 0.2 sr on the variance per sample falls 2.5x and more, 100x beside the light, well
    // past the cost.
    static constexpr double kMinSphericalSolidAngle = 0.2;

    // `minSphericalSolidAngle`: infinity samples by area only, 0 by solid angle wherever the
    // spherical map is well conditioned.
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& radiance,
              double minSphericalSolidAngle = kMinSphericalSolidAngle);
    // A textured emitter: radiance material.emissionAt(uv), `uvs` its corners' coordinates;
    // `material` outlives the light.
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const Material& material,
              const std::array<glm::vec2, 3>& uvs, double minSphericalSolidAngle = kMinSphericalSolidAngle);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 power() const override;
    std::optional<LightBounds> bounds() const override;

    float area() const { return area_; }
    // The solid angle sample() samples uniformly from `point`, or 0 where it samples by area.
    double sphericalSolidAngle(const glm::vec3& point) const;

private:
    // The triangle as seen from `point` when it is sampled by solid angle from there.
    std::optional<SphericalTriangle> spherical(const glm::vec3& point) const;
    std::optional<LightSample> sampleArea(const glm::vec3& point, glm::vec2 u) const;
    // Le at barycentrics (b1, b2) of vertices 1 and 2, as a ray that hits there sees it, and as a
    // light sample there brings it (times a blended emitter's opacity).
    glm::vec3 radianceAt(float b1, float b2) const {
        if (!textured_) return radiance_;
        return textured_->emissionAt(uvAt(b1, b2));
    }
    glm::vec3 sampledRadianceAt(float b1, float b2) const {
        if (!textured_) return radiance_;
        const glm::vec2 uv = uvAt(b1, b2);
        return textured_->emissionAt(uv) * textured_->opacityAt(uv);
    }
    glm::vec2 uvAt(float b1, float b2) const { return (1.0f - b1 - b2) * uvs_[0] + b1 * uvs_[1] + b2 * uvs_[2]; }
    // A sample of the point `onLight`, at `distance` along `direction`, with its end off the
    // surface where the shortened shadow ray would not clear the point's error (light.h).
    std::optional<LightSample> sampleAt(const glm::vec3& onLight, const glm::vec3& direction, float distance,
                                        const glm::vec3& radiance, float pdf) const;
    // sampledRadianceAt where the ray from `point` along `direction` meets the triangle at
    // `distance`.
    glm::vec3 sampledRadianceAlong(const glm::dvec3& point, const glm::dvec3& direction, double distance) const;

    glm::vec3 p0_, p1_, p2_;
    glm::vec3 normal_;  // unit, the emitting side's
    glm::vec3 radiance_;
    float area_;
    glm::dvec3 centroid_;
    double radius_;  // of the sphere about the centroid through the farthest vertex
    glm::vec3 pointError_;  // a bound on the rounding error of any sampled point (constructor)
    float normalError_;     // twice that bound's extent along the normal
    double minSphericalSolidAngle_;
    const Material* textured_ = nullptr;
    std::array<glm::vec2, 3> uvs_{};
};

}  // namespace strata
