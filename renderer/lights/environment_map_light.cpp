#include "lights/environment_map_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "film/accumulation_buffer.h"
#include "io/image_io.h"
#include "util/constants.h"

namespace strata {
namespace {

// Luminance times sin(theta) at each texel's centre: the 2D distribution's weights.
std::vector<float> samplingWeights(const Image& map) {
    std::vector<float> weights(map.pixels.size());
    for (int y = 0; y < map.height; ++y) {
        const double sinTheta = std::sin(M_PI * (y + 0.5) / map.height);
        for (int x = 0; x < map.width; ++x) {
            const size_t i = static_cast<size_t>(y) * map.width + x;
            weights[i] = static_cast<float>(luminance(glm::dvec3(map.pixels[i])) * sinTheta);
        }
    }
    return weights;
}

// pi r^2 times the sum over texels of radiance times the texel's solid angle,
// (2 pi / width) (cos theta_top - cos theta_bottom).
glm::vec3 powerOf(const Image& map, float sceneRadius) {
    glm::dvec3 integral(0.0);
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = 2.0 * M_PI / map.width *
                                  (std::cos(M_PI * y / map.height) - std::cos(M_PI * (y + 1) / map.height));
        for (int x = 0; x < map.width; ++x) {
            integral += solidAngle * glm::dvec3(map.pixels[static_cast<size_t>(y) * map.width + x]);
        }
    }
    const double r = sceneRadius;
    return glm::vec3(M_PI * r * r * integral);
}

}  // namespace

EnvironmentMapLight::EnvironmentMapLight(std::shared_ptr<const Image> map, float rotationDegrees,
                                         float sceneRadius)
    : map_(std::move(map)),
      cosRotation_(std::cos(rotationDegrees * (kPi / 180.0f))),
      sinRotation_(std::sin(rotationDegrees * (kPi / 180.0f))),
      distribution_(samplingWeights(*map_), map_->width, map_->height),
      power_(powerOf(*map_, sceneRadius)) {}

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
    return map_->pixels[static_cast<size_t>(cell.y) * map_->width + cell.x];
}

std::optional<LightSample> EnvironmentMapLight::sample(const glm::vec3& /*point*/, glm::vec2 u) const {
    const PiecewiseConstant2D::Sample s = distribution_.sample(u);
    const float theta = kPi * s.point.y;
    const float sinTheta = std::sin(theta);
    if (!(sinTheta > 0.0f) || !(s.pdf > 0.0f)) return std::nullopt;
    const float phi = 2.0f * kPi * (s.point.x - 0.5f);
    // In the map's frame, then turned by the rotation.
    const float x = sinTheta * std::sin(phi);
    const float z = -sinTheta * std::cos(phi);
    const glm::vec3 direction(cosRotation_ * x + sinRotation_ * z, std::cos(theta),
                              -sinRotation_ * x + cosRotation_ * z);
    return LightSample{direction, std::numeric_limits<float>::infinity(),
                       texel(distribution_.cellOf(s.point)),
                       s.pdf / (2.0f * kPi * kPi * sinTheta), false};
}

float EnvironmentMapLight::pdf(const glm::vec3&, const glm::vec3& direction, const LightHit&) const {
    const glm::vec2 point = imagePoint(direction);
    const float sinTheta = std::sqrt(direction.x * direction.x + direction.z * direction.z);
    if (!(sinTheta > 0.0f)) return 0.0f;
    return distribution_.pdf(point) / (2.0f * kPi * kPi * sinTheta);
}

glm::vec3 EnvironmentMapLight::emitted(const glm::vec3& direction, const LightHit&) const {
    return texel(distribution_.cellOf(imagePoint(direction)));
}

}  // namespace strata
