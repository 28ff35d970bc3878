#pragma once
// Cosine-weighted sampling inside each of the 24 strata (strata24.h), for the `strata24-cosine`
// estimator: in stratum i the density is cos(theta) / PSA_i, where PSA_i = integral over the
// stratum of cos(theta) d(omega) is its projected solid angle. The strata are not equal in
// projected solid angle: they fall into three classes of 8 (notes section 3),
//   pole    (orders 0, 1, touch the normal):  PSA = asin(1/sqrt 3) / (2 sqrt 2) = 0.2176049378
//   middle  (orders 2, 3):                    PSA = asin(1/3) / (2 sqrt 2)      = 0.1201504916
//   equator (orders 4, 5, touch the horizon): PSA = pi/8 - acos(1/sqrt 3)/(2 sqrt 2) = 0.0549436523
// and 8 (sum of the three) = pi.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

// PSA of stratum `id` (exact closed forms above, in double precision).
double stratumProjectedSolidAngle(int id);

// A map of [0,1)^2 onto stratum `id` with density cos(theta) / PSA_id (Malley's method: the
// stratum projects onto a region of the unit disk, sampled uniformly; notes section 3). The
// azimuth is inverted in closed form for the pole and middle classes; the equator class's CDF is
// transcendental, and its inverse is interpolated from a table of the exact one (safeguarded
// Newton), within 1e-8 in tan(phi): exact to float precision. Output: unit length, z >= 0, inside
// the stratum.
glm::vec3 sampleStratumCosine(int id, glm::vec2 u);

// The equator class's azimuth inverse for u in [0, 1]: tan(phi) with F(phi) = u PSA, as sampled
// (interpolated) and exact (Newton).
double equatorTanPhi(double u);
double equatorTanPhiExact(double u);

}  // namespace strata
