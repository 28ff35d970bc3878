#include "lights/environment_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/luminance.h"

namespace strata {
namespace {

// The solid angle of a texel of row y, (2 pi / width) (cos theta_top - cos theta_bottom).
double texelSolidAngle(const Image& map, int y) {
    return 2.0 * M_PI / map.width * (std::cos(M_PI * y / map.height) - std::cos(M_PI * (y + 1) / map.height));
}

// The sum over texels of radiance times the texel's solid angle.
glm::dvec3 integralOverSphere(const Image& map) {
    glm::dvec3 integral(0.0);
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = texelSolidAngle(map, y);
        for (int x = 0; x < map.width; ++x) {
            integral += solidAngle * glm::dvec3(map.pixels[static_cast<size_t>(y) * map.width + x]);
        }
    }
    return integral;
}

// The compensated weights of environment_map.h: max(0, luminance - `mean`) times sin(theta) at
// each texel's centre.
std::vector<float> samplingWeights(const Image& map, double mean) {
    std::vector<float> weights(map.pixels.size());
    for (int y = 0; y < map.height; ++y) {
        const double sinTheta = std::sin(M_PI * (y + 0.5) / map.height);
        for (int x = 0; x < map.width; ++x) {
            const size_t i = static_cast<size_t>(y) * map.width + x;
            weights[i] = static_cast<float>(std::max(0.0, luminance(glm::dvec3(map.pixels[i])) - mean) * sinTheta);
        }
    }
    return weights;
}

// The integral over the sphere of max(0, luminance - `mean`).
double integralAboveMean(const Image& map, double mean) {
    double integral = 0.0;
    for (int y = 0; y < map.height; ++y) {
        const double solidAngle = texelSolidAngle(map, y);
        for (int x = 0; x < map.width; ++x) {
            const glm::dvec3 texel(map.pixels[static_cast<size_t>(y) * map.width + x]);
            integral += solidAngle * std::max(0.0, luminance(texel) - mean);
        }
    }
    return integral;
}

// The luminance a texel must exceed to be sampled: the map's mean over the sphere, raised by a
// rounding margin so that a texel equal to the mean is not above it.
double samplingThreshold(const glm::dvec3& sphereIntegral) {
    return luminance(sphereIntegral) / (4.0 * M_PI) * (1.0 + 1e-6);
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
      sphereIntegral_(integralOverSphere(image_)),
      distribution_(samplingWeights(image_, samplingThreshold(sphereIntegral_)), image_.width, image_.height),
      sampledIntegral_(integralAboveMean(image_, samplingThreshold(sphereIntegral_))),
      maxRadiance_(largestComponent(image_)) {}

}  // namespace strata
