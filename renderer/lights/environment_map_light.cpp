#include "lights/environment_map_light.h"

#include <cmath>
#include <limits>

#include "io/image_io.h"
#include "util/constants.h"
#include "util/turns.h"

namespace strata {

EnvironmentMapLight::EnvironmentMapLight(std::shared_ptr<const EnvironmentMap> map, float rotationDegrees,
                                         float sceneRadius)
    : map_(std::move(map)),
      cosRotation_(std::cos(rotationDegrees * (kPi / 180.0f))),
      sinRotation_(std::sin(rotationDegrees * (kPi / 180.0f))),
      power_(glm::vec3(M_PI * static_cast<double>(sceneRadius) * sceneRadius * map_->sphereIntegral())),
      sampledPower_(static_cast<float>(M_PI * static_cast<double>(sceneRadius) * sceneRadius *
                                       map_->sampledIntegral())) {}

glm::vec2 EnvironmentMapLight::imagePoint(const glm::vec3& d) const {
    // Into the map's frame: the inverse rotation about +y.
    const float x = cosRotation_ * d.x - sinRotation_ * d.z;
    const float z = sinRotation_ * d.x + cosRotation_ * d.z;
    // atan2 rather than acos(d.y), which loses theta's digits near the poles.
    const float theta = std::atan2(std::sqrt(x * x + z * z), d.y);
    const float phi = std::atan2(x, -z);
    return {phi / (2.0f * kPi) + 0.5f, theta / kPi};
}

const glm::vec3& EnvironmentMapLight::texel(glm::ivec2 cell) const {
    const Image& image = map_->image();
    return image.pixels[static_cast<size_t>(cell.y) * image.width + cell.x];
}

std::optional<LightSample> EnvironmentMapLight::sample(const glm::vec3& /*point*/, glm::vec2 u) const {
    if (!map_->sampled()) return std::nullopt;
    const PiecewiseConstant2D::Sample s = map_->distribution().sample(u);
    // theta = pi y (half a turn times y) and phi = 2 pi (x - 1/2), whose cosine and sine are
    // those of 2 pi x negated.
    const glm::vec2 polar = cosSinOfTurns(0.5f * s.point.y);
    const float sinTheta = polar.y;
    if (!(sinTheta > 0.0f) || !(s.pdf > 0.0f)) return std::nullopt;
    const glm::vec2 azimuth = cosSinOfTurns(s.point.x);
    // In the map's frame, then turned by the rotation.
    const float x = -sinTheta * azimuth.y;
    const float z = sinTheta * azimuth.x;
    const glm::vec3 direction(cosRotation_ * x + sinRotation_ * z, polar.x,
                              -sinRotation_ * x + cosRotation_ * z);
    return LightSample{direction, std::numeric_limits<float>::infinity(),
                       texel(map_->distribution().cellOf(s.point)),
                       s.pdf / (2.0f * kPi * kPi * sinTheta), false};
}

float EnvironmentMapLight::pdf(const glm::vec3&, const glm::vec3& direction, const LightHit&) const {
    if (!map_->sampled()) return 0.0f;
    const glm::vec2 point = imagePoint(direction);
    const float sinTheta = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (!(sinTheta > 0.0f)) return 0.0f;
    return map_->distribution().pdf(point) / (2.0f * kPi * kPi * sinTheta);
}

glm::vec3 EnvironmentMapLight::emitted(const glm::vec3& direction, const LightHit&) const {
    return texel(map_->distribution().cellOf(imagePoint(direction)));
}

}  // namespace strata
