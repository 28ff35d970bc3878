#include "geometry/rounding.h"

#include <bit>
#include <cstdint>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace strata {

// std::nextafter(x, +-infinity) for finite x, inlined: the libm call was a measurable share of a
// bounce (three per ray origin). Stepping the bit pattern moves one ulp away from zero for
// positive x when `up` (toward zero when not), as nextafter does; zero steps to +-denorm_min.
float nextFloat(float x, bool up) {
    const uint32_t bits = std::bit_cast<uint32_t>(x);
    if ((bits & 0x7fffffffu) == 0) {
        const float tiny = std::numeric_limits<float>::denorm_min();
        return up ? tiny : -tiny;
    }
    const bool awayFromZero = (bits >> 31 == 0) == up;
    return std::bit_cast<float>(awayFromZero ? bits + 1 : bits - 1);
}

glm::vec3 offsetRayOrigin(const glm::vec3& point, const glm::vec3& error, const glm::vec3& normal,
                          const glm::vec3& direction) {
    const float distance = glm::dot(magnitudes(normal), error);
    glm::vec3 offset = distance * normal;
    if (glm::dot(direction, normal) < 0.0f) offset = -offset;
    glm::vec3 origin = point + offset;
    // Round away from the surface, so the addition itself cannot land back on it.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0.0f) {
            origin[i] = nextFloat(origin[i], true);
        } else if (offset[i] < 0.0f) {
            origin[i] = nextFloat(origin[i], false);
        }
    }
    return origin;
}

}  // namespace strata
