#include "geometry/smooth_surface.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace strata {

glm::vec3 smoothSurfaceLift(const std::array<glm::vec3, 3>& corners, const std::array<glm::vec3, 3>& normals,
                            const glm::vec3& barycentrics) {
    const glm::vec3 point = barycentrics.x * corners[0] + barycentrics.y * corners[1] + barycentrics.z * corners[2];
    glm::vec3 lift(0.0f);
    for (int i = 0; i < 3; ++i) {
        const float length = glm::length(normals[i]);
        if (!(length > 0.0f)) continue;
        const glm::vec3 normal = normals[i] / length;
        // The point's height over the vertex's tangent plane; below it, the point is raised onto it.
        const float height = glm::dot(point - corners[i], normal);
        if (height < 0.0f) lift -= barycentrics[i] * height * normal;
    }
    return lift;
}

float terminatorLiftShare(float geometricCosine, float cutoff) {
    if (!(cutoff > 0.0f)) return 0.0f;
    return std::clamp(1.0f - geometricCosine / cutoff, 0.0f, 1.0f);
}

}  // namespace strata
