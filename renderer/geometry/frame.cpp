#include "geometry/frame.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

Frame Frame::fromNormal(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return Frame{glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
                 glm::vec3(b, sign + n.y * n.y * a, -n.y), n};
}

glm::vec3 Frame::toLocal(const glm::vec3& world) const {
    return {glm::dot(world, tangent), glm::dot(world, bitangent), glm::dot(world, normal)};
}

}  // namespace strata
