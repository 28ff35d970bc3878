#pragma once
// An emitting triangle: radiance Le leaves its front (counter-clockwise) side only, uniformly in
// every direction. Seen from a point where it subtends at least `minSphericalSolidAngle`, it is
// sampled uniformly by solid angle (Arvo's map, sampling/spherical_triangle.h), density
// 1 / Omega; otherwise uniformly by area, density d^2 / (A cos(theta_light)). Which of the two
// depends only on the point and the triangle, so sample() and pdf() always agree.
#include "lights/light.h"
#include "sampling/spherical_triangle.h"

namespace strata {

class AreaLight final : public Light {
public:
    // The solid angle (sr) from which on the triangle is sampled by solid angle. Measured on a
    // 130 x 105 mm light seen from 0.01 to 3 sr: see area_light.cpp.
    static constexpr double kMinSphericalSolidAngle = 0.0;

    // `minSphericalSolidAngle`: infinity samples by area only, 0 by solid angle wherever the
    // spherical map is well conditioned.
    AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& radiance,
              double minSphericalSolidAngle = kMinSphericalSolidAngle);

    std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const override;
    float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const override;
    glm::vec3 power() const override;

    float area() const { return area_; }
    // The solid angle sample() samples uniformly from `point`, or 0 where it samples by area.
    double sphericalSolidAngle(const glm::vec3& point) const;

private:
    // The triangle as seen from `point` when it is sampled by solid angle from there.
    std::optional<SphericalTriangle> spherical(const glm::vec3& point) const;
    std::optional<LightSample> sampleArea(const glm::vec3& point, glm::vec2 u) const;

    glm::vec3 p0_, p1_, p2_;
    glm::vec3 normal_;  // unit, the emitting side's
    glm::vec3 radiance_;
    float area_;
    glm::dvec3 centroid_;
    double radius_;  // of the sphere about the centroid through the farthest vertex
    double minSphericalSolidAngle_;
};

}  // namespace strata
