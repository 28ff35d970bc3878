#pragma once
// Floating-point rounding bounds for points on surfaces, and the ray origins they call for
// (pbrt-v4's Point3fi and OffsetRayOrigin idea): a point computed in float carries a per-axis
// bound on its error, and a ray that leaves it starts just far enough off the surface, along
// the surface normal, that it cannot find that surface again, however far the point is from the
// origin of the coordinates. The bounds also cover Embree's own rounding, which is relative to
// the largest coordinate of the triangle it tests.
#include <glm/vec3.hpp>

#include "util/components.h"

namespace strata {

// Higham's gamma(n) = n u / (1 - n u), u = 2^-24: the relative error bound of n float operations.
constexpr float gammaBound(int n) {
    constexpr float u = 0x1p-24f;
    return (static_cast<float>(n) * u) / (1.0f - static_cast<float>(n) * u);
}

// Embree's rounding of a test against a triangle whose largest coordinate is `largest`: its tests
// work relative to the ray origin (the watertight one in sheared coordinates that mix all three
// axes), so a ray leaving a plane such as x = 0 can find that plane again at t ~ 0 unless the
// origin clears it by a few ulp of the triangle's largest coordinate (translating the vertices by
// the origin and shearing them each round once per axis: about 3 u). gamma(4) covers that, and
// no more: a much larger bound, gamma(16), at 1e6 from the origin pushes new rays about 1 unit off
// the surface, out through the wall of a unit furnace (tests/scene/test_scene_robustness.cpp: no
// re-hit in 320k spawned rays even with gamma(1), 122 in 20k with no such term).
inline glm::vec3 traversalError(float largest) { return glm::vec3(gammaBound(4) * largest); }

// The next float after x toward +infinity (`up`) or -infinity, for finite x.
float nextFloat(float x, bool up);

// A ray origin off the point `point` (per-axis error bound `error`) on a surface of unit normal
// `normal`, on the side `direction` leaves toward.
glm::vec3 offsetRayOrigin(const glm::vec3& point, const glm::vec3& error, const glm::vec3& normal,
                          const glm::vec3& direction);

}  // namespace strata
