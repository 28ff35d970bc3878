#include "sampling/hemisphere.h"

#include <algorithm>
#include <cmath>

#include "util/turns.h"

namespace strata {

glm::vec3 sampleUniformHemisphere(glm::vec2 u) {
    const float z = u.x;
    // (1 - z)(1 + z) rather than 1 - z^2: no cancellation near the pole.
    const float r = std::sqrt(std::max(0.0f, (1.0f - z) * (1.0f + z)));
    const glm::vec2 azimuth = cosSinOfTurns(u.y);
    return {r * azimuth.x, r * azimuth.y, z};
}

glm::vec3 sampleUniformSphere(glm::vec2 u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, (1.0f - z) * (1.0f + z)));
    const glm::vec2 azimuth = cosSinOfTurns(u.y);
    return {r * azimuth.x, r * azimuth.y, z};
}

glm::vec2 sampleConcentricDisk(glm::vec2 u) {
    const float a = 2.0f * u.x - 1.0f;
    const float b = 2.0f * u.y - 1.0f;
    float r = 0.0f;
    float phi = 0.0f;
    if (a != 0.0f || b != 0.0f) {
        if (std::abs(a) > std::abs(b)) {
            r = a;
            phi = (kPi / 4.0f) * (b / a);
        } else {
            r = b;
            phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
        }
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

glm::vec3 sampleCosineHemisphere(glm::vec2 u) {
    const glm::vec2 disk = sampleConcentricDisk(u);
    // z = sqrt(1 - r^2); the clamp absorbs rounding, and z = 0 only on the disk's rim.
    return {disk.x, disk.y, std::sqrt(std::max(0.0f, 1.0f - disk.x * disk.x - disk.y * disk.y))};
}

}  // namespace strata
