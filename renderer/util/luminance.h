#pragma once
// Rec. 709 luminance, which the film's statistics and io's exposure metering both weigh colour by.
#include <glm/vec3.hpp>

namespace strata {

// Rec. 709 luminance of linear RGB.
inline double luminance(const glm::dvec3& rgb) {
    return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
}

}  // namespace strata
