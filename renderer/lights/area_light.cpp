#include "lights/area_light.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "util/constants.h"

namespace strata {

AreaLight::AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                     const glm::vec3& radiance)
    : p0_(p0), edge1_(p1 - p0), edge2_(p2 - p0), radiance_(radiance) {
    const glm::vec3 cross = glm::cross(edge1_, edge2_);
    normal_ = glm::normalize(cross);
    area_ = static_cast<float>(0.5 * glm::length(glm::dvec3(cross)));
}

AreaLight::AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const Material& material,
                     const std::array<glm::vec2, 3>& uvs)
    : AreaLight(p0, p1, p2, material.meanEmission()) {
    textured_ = &material;
    uvs_ = uvs;
}

std::optional<LightSample> AreaLight::sample(const glm::vec3& point, glm::vec2 u) const {
    // Uniform by area: barycentrics (1 - sqrt(u), sqrt(u)(1 - v), sqrt(u) v).
    const float s = std::sqrt(u.x);
    const float b1 = s * (1.0f - u.y);
    const float b2 = s * u.y;
    const glm::vec3 onLight = p0_ + b1 * edge1_ + b2 * edge2_;
    const glm::vec3 toLight = onLight - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 direction = toLight / distance;
    const float cosLight = -glm::dot(normal_, direction);
    if (!(cosLight > 0.0f)) return std::nullopt;  // the point sees its back (one-sided)
    return LightSample{direction, distance, radianceAt(b1, b2), distanceSquared / (area_ * cosLight), true};
}

float AreaLight::pdf(const glm::vec3& /*point*/, const glm::vec3& direction, const LightHit& hit) const {
    const float cosLight = -glm::dot(hit.normal, direction);
    if (!(cosLight > 0.0f)) return 0.0f;
    return hit.distance * hit.distance / (area_ * cosLight);
}

glm::vec3 AreaLight::emitted(const glm::vec3& direction, const LightHit& hit) const {
    return glm::dot(hit.normal, direction) < 0.0f ? radianceAt(hit.barycentrics.x, hit.barycentrics.y)
                                                : glm::vec3(0.0f);
}

// Lambertian emission into one hemisphere: pi Le A (Le's texture mean for a textured emitter).
glm::vec3 AreaLight::power() const { return kPi * area_ * radiance_; }

}  // namespace strata
