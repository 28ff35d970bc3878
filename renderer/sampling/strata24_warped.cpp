#include "sampling/strata24_warped.h"

#include <algorithm>
#include <cmath>

#include "sampling/strata24.h"

namespace strata {

glm::vec3 warpUniformToCosine(const glm::vec3& uniform) {
    // sqrt(1 - z) / sqrt(1 - z^2) = 1 / sqrt(1 + z): no cancellation at the pole or the horizon.
    const float z = std::max(uniform.z, 0.0f);
    const float tangentScale = 1.0f / std::sqrt(1.0f + z);
    return {uniform.x * tangentScale, uniform.y * tangentScale, std::sqrt(z)};
}

glm::vec3 warpCosineToUniform(const glm::vec3& cosine) {
    // z -> z^2 along the normal, the tangent part scaled by sqrt(1 + z^2).
    const float z = std::max(cosine.z, 0.0f);
    const float tangentScale = std::sqrt(1.0f + z * z);
    return {cosine.x * tangentScale, cosine.y * tangentScale, z * z};
}

glm::vec3 sampleWarpedStratum(int id, glm::vec2 u) { return warpUniformToCosine(sampleStratum(id, u)); }

}  // namespace strata
