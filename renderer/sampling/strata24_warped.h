#pragma once
// The 24 strata carried onto the cosine-weighted hemisphere, for the flagship `strata24-bsdf`.
//
// Uniform directions have cos(theta) uniform on [0, 1]; cosine-weighted ones have cos^2(theta)
// uniform. The warp W: (x, y, z) -> (x, y, z) sqrt(1 - z) / sqrt(1 - z^2) in the tangent plane and
// sqrt(z) along the normal (the azimuth kept) therefore carries the uniform measure onto the
// cosine measure, and each of the paper's strata T_i (solid angle pi/12, strata24.h) onto a cell
// W(T_i) holding exactly 1/24 of the projected solid angle pi. A point uniform in T_i lands
// in W(T_i) with density 24 cos(theta) / pi, so one direction per warped stratum per pass is the
// paper's stratified estimator with cosine importance: every sample's weight is f pi, as cosine
// sampling's. strata24-cosine's weights 24 PSA_i f instead spread from 1.3 f to 5.2 f across the
// strata (notes section 3): one sample in each of unequal strata is far from proportional
// allocation, and that costs more variance than the stratification removes.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

// The warp W above, for a unit direction with z >= 0.
glm::vec3 warpUniformToCosine(const glm::vec3& uniform);
// Its inverse: the direction of T_i that W carries to `cosine`, so that a direction lies in the
// warped stratum W(T_i) exactly when warpCosineToUniform(direction) lies in T_i.
glm::vec3 warpCosineToUniform(const glm::vec3& cosine);

// A map of [0,1)^2 onto the warped stratum W(T_id) with density 24 cos(theta) / pi: the uniform
// stratum map (sampleStratum) followed by W. Unit length, z >= 0.
glm::vec3 sampleWarpedStratum(int id, glm::vec2 u);

}  // namespace strata
