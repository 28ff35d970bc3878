#include "hemisphere.h"

#include <algorithm>
#include <cmath>

namespace strata {

glm::vec3 sampleUniformHemisphere(glm::vec2 u) {
    const float z = u.x;
    // (1 - z)(1 + z) rather than 1 - z^2: no cancellation near the pole.
    const float r = std::sqrt(std::max(0.0f, (1.0f - z) * (1.0f + z)));
    const float phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace strata
