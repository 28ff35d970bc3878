#include "lights/environment_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "film/accumulation_buffer.h"

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

// The sum over texels of radiance times the texel's solid angle,
// (2 pi / width) (cos theta_top - cos theta_bottom).
glm::dvec3 integralOverSphere(const Image& map) {
    glm::dvec3 integral(0.0);
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = 2.0 * M_PI / map.width *
                                  (std::cos(M_PI * y / map.height) - std::cos(M_PI * (y + 1) / map.height));
        for (int x = 0; x < map.width; ++x) {
            integral += solidAngle * glm::dvec3(map.pixels[static_cast<size_t>(y) * map.width + x]);
        }
    }
    return integral;
}

float largestComponent(const Image& map) {
    float largest = 0.0f;
    for (const glm::vec3& texel : map.pixels) largest = std::max({largest, texel.x, texel.y, texel.z});
    return largest;
}

}  // namespace

EnvironmentMap::EnvironmentMap(Image image, std::string name)
    : image_(std::move(image)),
      name_(std::move(name)),
      distribution_(samplingWeights(image_), image_.width, image_.height),
      sphereIntegral_(integralOverSphere(image_)),
      maxRadiance_(largestComponent(image_)) {}

}  // namespace strata
