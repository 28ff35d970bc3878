#pragma once
// Sampling of the unit hemisphere around +z: uniformly, as the paper's xi_N draws directions with
// p(w) = 1 / (2 pi) (section 3), and by cosine, p(w) = cos(theta) / pi, the density of the
// Lambertian integrand f_r cos; and of the whole sphere, uniformly (a uniform environment).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "util/constants.h"

namespace strata {

inline constexpr float kHemisphereSolidAngle = 2.0f * kPi;
inline constexpr float kSphereSolidAngle = 4.0f * kPi;

// Maps [0,1)^2 onto the hemisphere, area-preserving: cos(theta) = u, azimuth = 2 pi v.
glm::vec3 sampleUniformHemisphere(glm::vec2 u);
// Maps [0,1)^2 onto the whole sphere, area-preserving: z = 1 - 2 u, azimuth = 2 pi v.
glm::vec3 sampleUniformSphere(glm::vec2 u);

// Maps [0,1)^2 onto the unit disk, area-preserving: Shirley & Chiu's concentric map, which keeps
// strata of the square compact; (0.5, 0.5) is the centre.
glm::vec2 sampleConcentricDisk(glm::vec2 u);

// Maps [0,1)^2 onto the hemisphere with density cos(theta) / pi: Malley's method, a uniform point
// of the unit disk (sampleConcentricDisk) lifted onto the hemisphere.
glm::vec3 sampleCosineHemisphere(glm::vec2 u);
inline float cosineHemispherePdf(const glm::vec3& w) { return w.z > 0.0f ? w.z / kPi : 0.0f; }

}  // namespace strata
