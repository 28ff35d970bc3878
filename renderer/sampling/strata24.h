#pragma once
// The 24-stratum partition of the hemisphere (Dimov, Penzov & Stoilova, section 3, Fig. 2).
//
// In the local frame (normal = +z) the planes x = 0 and y = 0 cut the hemisphere into 4 quadrants
// and the bisector planes |x| = |y|, |y| = z, |x| = z cut each quadrant into 6 equal orthogonal
// spherical triangles of solid angle pi/12 (angles pi/4, pi/2, pi/3).
//
// Stratum id convention (../shared/notes/strata-math.md section 2.2), id = 6 * quadrant + order:
//   quadrant = id / 6 gives the signs of (x, y): 0:(+,+) 1:(-,+) 2:(-,-) 3:(+,-), counter-clockwise;
//   order    = id % 6 gives the ordering of (|x|, |y|, z):
//     0: z >= |x| >= |y|    1: z >= |y| >= |x|      (pole class: touches the normal)
//     2: |x| >= z >= |y|    3: |y| >= z >= |x|      (middle class)
//     4: |x| >= |y| >= z    5: |y| >= |x| >= z      (equator class: touches the horizon)
// The paper's Fig. 2 triangle is stratum 0; the triangle {x >= y >= z >= 0} is stratum 4.
#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "util/constants.h"

namespace strata {

inline constexpr int kStrataCount = 24;
inline constexpr float kStratumSolidAngle = kPi / 12.0f;

// An exact area-preserving map of [0,1)^2 onto stratum `id` (pdf 12/pi on it): the closed-form
// polar map about the triangle's pi/4 vertex (notes section 2.3, "S1"), with the azimuth inverted
// in closed form, so there is no iteration and no rejection. The output is unit length, has
// z >= 0 and lies in its stratum (ties on the boundary planes resolved in its favour).
glm::vec3 sampleStratum(int id, glm::vec2 u);

// Places sorted coordinates a >= b >= c >= 0 of the canonical triangle onto the axes of stratum
// `id` (its ordering, then the quadrant's signs): the symmetry that maps the canonical triangle
// onto every stratum, shared by the uniform and the cosine-weighted stratum samplers.
glm::vec3 placeInStratum(int id, float a, float b, float c);

// The stratum that contains a local direction with z >= 0 (boundary ties broken as documented in
// the notes, section 2.2). classifyStratum(sampleStratum(id, u)) == id for every u.
int classifyStratum(const glm::vec3& direction);

// Whether stratum `id` (a closed set) contains the local direction: its signs match the quadrant
// and its coordinates are ordered as `order` says. Points on a boundary plane belong to both
// neighbours, which is why tests of the sampler use this rather than classifyStratum's tie-break.
bool stratumContains(int id, const glm::vec3& direction);

// The triangle's vertices as unit vectors: the pi/4 vertex, the right-angle vertex, the octant
// centre (1,1,1)/sqrt(3) with the quadrant's signs.
std::array<glm::vec3, 3> stratumVertices(int id);

}  // namespace strata
