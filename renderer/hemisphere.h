#pragma once
// Uniform sampling of the unit hemisphere around +z: the paper's xi_N draws directions with
// p(w) = 1 / (2 pi) (section 3).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "constants.h"

namespace strata {

inline constexpr float kHemisphereSolidAngle = 2.0f * kPi;

// Maps [0,1)^2 onto the hemisphere, area-preserving: cos(theta) = u, azimuth = 2 pi v.
glm::vec3 sampleUniformHemisphere(glm::vec2 u);

}  // namespace strata
